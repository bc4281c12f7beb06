// raystudio-cli render --tile, merge and farm: parts merge into the very file a one-machine
// render writes; bad parts, bad tiles and bad job options are refused with exit 2.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "cli_run.h"
#include "image/image_io.h"

namespace {

namespace fs = std::filesystem;

const std::string kScenes = RAYSTUDIO_SCENES_DIR;
/// The soft-shadows scene has a sphere light; small, supersampled (adaptively: decisions at
/// part borders read neighbours in other parts).
const std::string kSoft =
    "'" + kScenes + "/soft-shadows.scene.json' --width 64 --height 37 --supersampling 3";

/// The pixels of an image file, as the project reads them (linear float, bit for bit).
std::string pixelBytes(const std::string& path) {
    rs::ImageRgb image;
    std::string error;
    EXPECT_TRUE(rs::readImage(path, image, error)) << error;
    std::string bytes(image.pixels.size() * sizeof(rs::Color), '\0');
    std::memcpy(bytes.data(), image.pixels.data(), bytes.size());
    return std::to_string(image.width) + "x" + std::to_string(image.height) + ":" + bytes;
}

class FarmCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("raystudio-farm-cli-" + std::to_string(getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    /// Renders parts 0..count-1 of `scene` (shell words) with `extra` options; their paths.
    std::string renderParts(const std::string& scene, int count, const std::string& tag = "p",
                            const std::string& extra = "") {
        std::string paths;
        for (int i = 0; i < count; ++i) {
            const std::string part = path(tag + std::to_string(i) + ".exr");
            const CliRun r = cli("render " + scene + " --tile " + std::to_string(i) + "/" +
                                 std::to_string(count) + " -o '" + part + "' " + extra);
            EXPECT_EQ(r.exitCode, 0) << r.err;
            paths += " '" + part + "'";
        }
        return paths;
    }
    fs::path dir_;
};

TEST_F(FarmCli, MergedParts_AreTheFileAOneMachineRenderWrites) {
    const std::string wholeExr = path("whole.exr"), wholePng = path("whole.png");
    ASSERT_EQ(cli("render " + kSoft + " -o '" + wholeExr + "'").exitCode, 0);
    ASSERT_EQ(cli("render " + kSoft + " -o '" + wholePng + "'").exitCode, 0);
    for (int count : {1, 2, 3, 7}) {
        std::string tag("n");  // appended, not "n" + ...: GCC 12 warns (-Wrestrict) on that
        tag.append(std::to_string(count)).append("-");
        const std::string parts = renderParts(kSoft, count, tag);
        for (const std::string& ext : {std::string(".exr"), std::string(".png")}) {
            const std::string merged = path(tag + "merged" + ext);
            const CliRun m = cli("merge" + parts + " -o '" + merged + "'");
            ASSERT_EQ(m.exitCode, 0) << m.err;
            EXPECT_NE(m.out.find("merged " + std::to_string(count) + " parts (64x37)"),
                      std::string::npos);
            // Every pixel's bits; PNG files are compared whole (an EXR header holds its date).
            const std::string& whole = ext == ".exr" ? wholeExr : wholePng;
            EXPECT_TRUE(pixelBytes(merged) == pixelBytes(whole)) << count << " parts, " << ext;
            if (ext == ".png") {
                EXPECT_TRUE(readAll(merged) == readAll(whole)) << count << " parts, " << ext;
            }
        }
    }
}

TEST_F(FarmCli, Merge_RefusesMissingDoubledAndForeignPartsWithExit2) {
    renderParts(kSoft, 3);
    const std::string p0 = "'" + path("p0.exr") + "'", p1 = "'" + path("p1.exr") + "'",
                      p2 = "'" + path("p2.exr") + "'", out = " -o '" + path("out.exr") + "'";
    CliRun r = cli("merge " + p0 + " " + p2 + out);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("1 of 3 parts missing: 1"), std::string::npos) << r.err;
    r = cli("merge " + p0 + " " + p1 + " " + p1 + " " + p2 + out);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("part 1/3 is given twice"), std::string::npos) << r.err;
    renderParts(kSoft, 3, "deeper", "--max-depth 5");
    r = cli("merge " + p0 + " '" + path("deeper1.exr") + "' " + p2 + out);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("deeper1.exr' belongs to another scene or other settings"),
              std::string::npos)
        << r.err;
    renderParts("'" + kScenes + "/reference-room.scene.json' --width 64 --height 37", 3, "room");
    r = cli("merge " + p0 + " '" + path("room1.exr") + "' " + p2 + out);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("belongs to another scene"), std::string::npos) << r.err;
    ASSERT_EQ(cli("render " + kSoft + " -o '" + path("plain.exr") + "'").exitCode, 0);
    r = cli("merge '" + path("plain.exr") + "'" + out);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("is not a RayStudio part"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("out.exr")));
    r = cli("merge " + p0 + " " + p1 + " " + p2 + " -o '" + path("out.bmp") + "'");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("unsupported extension '.bmp'"), std::string::npos) << r.err;
}

TEST_F(FarmCli, RenderTile_RefusesBadPartsAndNonExrOutput) {
    const std::string out = " -o '" + path("t.exr") + "'";
    struct Case {
        std::string args, message;
    } cases[] = {
        {"--tile 3" + out, "--tile expects I/N"},
        {"--tile 7/7" + out, "between 0 and 6, got 7"},
        {"--tile 0/38" + out, "37 rows tall has at most 37 parts"},
        {"--tile 0/2 -o '" + path("t.png") + "'", "-o must name a .exr file"},
        {"--ids" + out, "--ids is for parts"},
    };
    for (const Case& c : cases) {
        const CliRun r = cli("render " + kSoft + " " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    }
    EXPECT_FALSE(fs::exists(path("t.exr")));
}

TEST_F(FarmCli, FarmSubmitDryRun_PrintsTheArrayAndTheMergeScript) {
    const std::string out = path("poster.exr");
    const CliRun r = cli("farm submit " + kSoft + " -o '" + out +
                         "' --parts 4 --partition gpu-long --time 1-02:00:00 --dry-run");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const std::string& line :
         {std::string("#SBATCH --array=0-3"), std::string("#SBATCH --partition=gpu-long"),
          std::string("#SBATCH --time=1-02:00:00"),
          std::string("--tile \"$SLURM_ARRAY_TASK_ID/4\""),
          "#SBATCH --output=" + out + ".parts/logs/render-%A_%a.log",
          std::string("'--supersampling' '3'"),
          std::string(" merge \"${parts[@]}\" -o '" + out + "'"),
          std::string("--dependency=afterok:RENDER_JOB")})
        EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
    EXPECT_FALSE(fs::exists(out + ".parts")) << "a dry run writes nothing";
}

TEST_F(FarmCli, FarmSubmit_RefusesBadOptionsBeforeAnythingIsQueued) {
    const std::string base = "farm submit " + kSoft + " -o '" + path("o.exr") + "' --dry-run ";
    struct Case {
        std::string args, message;
    } cases[] = {
        {"", "missing --parts N"},
        {"--parts 38", "--parts: an image 37 rows tall has at most 37 parts"},
        {"--parts 2 --time 'tomorrow'", "--time expects a Slurm time limit"},
        {"--parts 2 --time '1:00;rm'", "--time expects a Slurm time limit"},
        {"--parts 2 --partition 'a b'", "--partition expects a partition name"},
        {"--parts 2 --supersampling 0", "--supersampling must be between"},
    };
    for (const Case& c : cases) {
        const CliRun r = cli(base + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    }
    CliRun r =
        cli("farm submit '" + kScenes + "/none.scene.json' -o '" + path("o.exr") + "' --parts 2");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    r = cli("farm submit " + kSoft + " -o '" + path("o.exr") + "' --parts 2", 60,
            "env PATH=/nonexistent");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("sbatch is not on PATH"), std::string::npos) << r.err;
    r = cli("farm status 12x");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("JOB must be a job id"), std::string::npos) << r.err;
    r = cli("farm");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("expects a sub-command"), std::string::npos) << r.err;
}

}  // namespace
