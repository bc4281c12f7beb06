// raystudio-cli on a scene whose mesh makes assimp abort: the import child turns it into an
// error on stderr naming the mesh, and the command exits 2 instead of dying with the importer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_run.h"

namespace {
namespace fs = std::filesystem;

class MeshImportCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ =
            fs::temp_directory_path() / ("raystudio-mesh-import-cli-" + std::to_string(getpid()));
        fs::create_directories(dir_);
        // The fuzz input that aborts Debian's assimp 5.2, without its first (format) byte.
        const std::string input = readAll(std::string(RAYSTUDIO_SCENES_DIR) +
                                          "/../tests/fuzz/corpus/mesh_loader/"
                                          "assimp-triangulate-assert.ply");
        ASSERT_GT(input.size(), 1u);
        mesh_ = (dir_ / "broken.ply").string();
        std::ofstream(mesh_, std::ios::binary) << input.substr(1);
        std::string scene = readAll(std::string(RAYSTUDIO_SCENES_DIR) + "/mesh.scene.json");
        const std::string torus = "meshes/torus.obj";
        ASSERT_NE(scene.find(torus), std::string::npos);
        scene.replace(scene.find(torus), torus.size(), "broken.ply");
        scene_ = (dir_ / "broken.scene.json").string();
        std::ofstream(scene_) << scene;
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
    std::string mesh_, scene_;
};

TEST_F(MeshImportCli, MeshThatAbortsAssimp_IsAnErrorOnStderrAndExit2) {
    const std::string image = (dir_ / "out.png").string();
    for (const std::string& args :
         {"validate '" + scene_ + "'", "render '" + scene_ + "' -o '" + image + "'"}) {
        SCOPED_TRACE(args);
        const CliRun run = cli(args);
        EXPECT_EQ(run.exitCode, 2) << run.err;
        EXPECT_EQ(run.out, "");
        EXPECT_NE(run.err.find("mesh \"" + mesh_ + "\": assimp crashed while reading it"),
                  std::string::npos)
            << run.err;
        EXPECT_NE(run.err.find("signal 6"), std::string::npos) << run.err;
    }
    EXPECT_FALSE(fs::exists(image));
}

}  // namespace
