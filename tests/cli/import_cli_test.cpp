// raystudio-cli import: an asset becomes a scene with its parts' materials, its lights or a
// key light and a framing camera, which validates and renders; bad input is an error naming it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.h"
#include "image/image_io.h"

namespace {
namespace fs = std::filesystem;

class ImportCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("raystudio-import-cli-" + std::to_string(getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

const std::string kBox = std::string(RAYSTUDIO_SCENES_DIR) + "/meshes/two-tone-box.obj";

TEST_F(ImportCli, TwoPartObj_BecomesASceneWithItsMaterials_ThatRenders) {
    const std::string scene = (dir_ / "box.scene.json").string();
    const CliRun run = cli("import '" + kBox + "' -o '" + scene + "' --width 64 --height 48");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("12 triangles, 2 materials"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("a key light (the asset has none)"), std::string::npos) << run.out;
    std::ifstream in(scene);
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_EQ(j["materials"].size(), 2u);
    EXPECT_EQ(j["materials"][0]["name"], "body");
    EXPECT_EQ(j["materials"][1]["name"], "lid");
    // The MTL's Kd; assimp numbers its own default material 0, then body 1 and lid 2.
    EXPECT_EQ(j["materials"][1]["color"], nlohmann::json({0.2, 0.45, 0.7}));
    EXPECT_EQ(j["objects"][0]["part_materials"], nlohmann::json({nullptr, "body", "lid"}));
    EXPECT_EQ(j["lights"].size(), 1u);
    // Resting on y = 0: the unit box is raised by half its height.
    EXPECT_EQ(j["objects"][0]["translate"], nlohmann::json({0.0, 0.5, 0.0}));

    EXPECT_EQ(cli("validate '" + scene + "'").out, "ok\n");
    const std::string image = (dir_ / "box.png").string();
    const CliRun render = cli("render '" + scene + "' -o '" + image + "'");
    EXPECT_EQ(render.exitCode, 0) << render.err;
    EXPECT_TRUE(fs::exists(image));
}

// The camera fits the asset's box, not the sphere around it: a long flat slab fills most of
// the picture's width (the sphere around it would leave it under half), and no part of it is
// cut off at the edges.
TEST_F(ImportCli, Framing_FitsAFlatAssetsBoxInsideThePicture) {
    const fs::path slab = dir_ / "slab.obj";
    {
        std::ofstream out(slab);
        // 20 x 0.5 x 4, one box of 12 triangles.
        for (int k = 0; k < 8; ++k)
            out << "v " << ((k & 1) ? 10 : -10) << ' ' << ((k & 2) ? 0.5 : 0) << ' '
                << ((k & 4) ? 2 : -2) << '\n';
        out << "f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n";
    }
    const std::string scene = (dir_ / "slab.scene.json").string();
    const CliRun run =
        cli("import '" + slab.string() + "' -o '" + scene + "' --width 160 --height 90");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string image = (dir_ / "slab.exr").string();
    ASSERT_EQ(cli("render '" + scene + "' -o '" + image + "'").exitCode, 0);
    rs::ImageRgb shown;
    std::string error;
    ASSERT_TRUE(rs::readImage(image, shown, error)) << error;
    ASSERT_EQ(shown.width, 160);
    // The columns and rows the slab covers (the background is black).
    int left = shown.width, right = -1, top = shown.height, bottom = -1;
    for (int y = 0; y < shown.height; ++y)
        for (int x = 0; x < shown.width; ++x) {
            const rs::Color& c = shown.at(x, y);
            if (c.x + c.y + c.z <= 0.0f) continue;
            left = std::min(left, x), right = std::max(right, x);
            top = std::min(top, y), bottom = std::max(bottom, y);
        }
    ASSERT_GE(right, 0) << "the slab is not in the picture";
    EXPECT_GT(left, 0);
    EXPECT_LT(right, shown.width - 1);
    EXPECT_GT(top, 0);
    EXPECT_LT(bottom, shown.height - 1);
    EXPECT_GE(right - left + 1, shown.width * 7 / 10) << left << ".." << right;
}

TEST_F(ImportCli, BadInput_IsAnErrorNamingIt) {
    const std::string scene = (dir_ / "x.scene.json").string();
    const std::string missing = (dir_ / "nothing.glb").string();
    CliRun run = cli("import '" + missing + "' -o '" + scene + "'");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("mesh \"" + missing + "\": file not found"), std::string::npos)
        << run.err;
    run = cli("import '" + kBox + "' -o '" + scene + "' --camera asset");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("has no camera (--camera asset)"), std::string::npos) << run.err;
    run = cli("import '" + kBox + "' -o '" + scene + "' --camera side");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--camera must be frame or asset"), std::string::npos) << run.err;
    run = cli("import '" + kBox + "' -o '" + (dir_ / "no" / "x.scene.json").string() + "'");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("the folder does not exist"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(scene));
}

// The asset's cameras are kept as views; render --view looks through one.
TEST_F(ImportCli, AssetCameras_BecomeViews_ThatRenderLooksThrough) {
    const std::string asset = std::string(RAYSTUDIO_TEST_DATA) + "/meshes/two_cameras.gltf";
    const std::string scene = (dir_ / "tri.scene.json").string();
    const CliRun run = cli("import '" + asset + "' -o '" + scene + "' --width 48 --height 32");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("its cameras are views \"Eye\", \"Side\" (render --view NAME)"),
              std::string::npos)
        << run.out;
    std::ifstream in(scene);
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_EQ(j["views"].size(), 2u);
    EXPECT_EQ(j["views"][0]["name"], "Eye");
    EXPECT_EQ(j["views"][1]["name"], "Side");
    EXPECT_EQ(j["version"], 2);

    const std::string framing = (dir_ / "framing.png").string();
    const std::string side = (dir_ / "side.png").string();
    ASSERT_EQ(cli("render '" + scene + "' -o '" + framing + "'").exitCode, 0);
    const CliRun through = cli("render '" + scene + "' -o '" + side + "' --view Side");
    ASSERT_EQ(through.exitCode, 0) << through.err;
    EXPECT_NE(readAll(framing), readAll(side));

    const CliRun unknown = cli("render '" + scene + "' -o '" + side + "' --view Top");
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.err.find("--view Top: " + scene +
                               " has no view named that (its views: \"Eye\", \"Side\")"),
              std::string::npos)
        << unknown.err;
    const CliRun none = cli("render '" + kBox.substr(0, kBox.rfind('/')) +
                            "/../classic.scene.json' -o '" + side + "' --view Eye");
    EXPECT_EQ(none.exitCode, 2);
    EXPECT_NE(none.err.find("has no view named that (it has no views)"), std::string::npos)
        << none.err;
}

}  // namespace
