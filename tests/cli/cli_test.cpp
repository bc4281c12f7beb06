// raystudio-cli as a user runs it: exit codes 0/1/2, messages that name the problem, outputs.
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace {

namespace fs = std::filesystem;

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("raystudio-cli-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) {
        const fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p.string();
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

const std::string kRoom = std::string(RAYSTUDIO_SCENES_DIR) + "/reference-room.scene.json";

TEST_F(CliTest, NoArguments_PrintsUsageToStderrAndExits2) {
    CliRun r = cli("");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("usage"), std::string::npos);
    EXPECT_EQ(r.out, "");
}

TEST_F(CliTest, Help_PrintsUsageToStdoutAndExits0) {
    CliRun r = cli("--help");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("usage"), std::string::npos);
    EXPECT_NE(r.out.find("--min-weight W"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "");
}

TEST_F(CliTest, UnknownCommandOrOption_Exits2NamingItOnStderr) {
    CliRun r = cli("paint " + kRoom);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("paint"), std::string::npos);
    EXPECT_EQ(r.out, "");
    r = cli("render " + kRoom + " -o " + path("x.png") + " --fast");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--fast"), std::string::npos);
    EXPECT_EQ(r.out, "");
}

TEST_F(CliTest, Render_WritesTheImageAndStatsLine) {
    CliRun r = cli("render " + kRoom + " -o " + path("room.png") +
                   " --width 64 --height 36 --threads 2 --stats");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");  // not a terminal: no progress bar
    EXPECT_TRUE(fs::exists(path("room.png")));
    auto stats = nlohmann::json::parse(r.out);
    EXPECT_EQ(stats["width"], 64);
    EXPECT_EQ(stats["height"], 36);
    EXPECT_GT(stats["rays"].get<long>(), 64 * 36 - 1);
    EXPECT_GE(stats["ms"].get<double>(), 0.0);
    EXPECT_TRUE(stats.contains("mrays_per_s"));
}

TEST_F(CliTest, Render_EveryOutputFormat) {
    for (const char* ext : {"png", "jpg", "tif", "exr", "hdr"}) {
        const std::string out = path(std::string("room.") + ext);
        CliRun r = cli("render " + kRoom + " -o " + out + " --width 16 --height 9");
        EXPECT_EQ(r.exitCode, 0) << ext << ": " << r.err;
        EXPECT_GT(fs::file_size(out), 0u) << ext;
    }
}

TEST_F(CliTest, Render_BadNumbers_Exit2NamingTheOption) {
    for (const char* bad : {"--width 0", "--width abc", "--height -5", "--threads 0",
                            "--supersampling 0", "--max-depth -1", "--width 99999"}) {
        CliRun r = cli("render " + kRoom + " -o " + path("x.png") + " " + bad);
        EXPECT_EQ(r.exitCode, 2) << bad;
        EXPECT_NE(r.err.find(std::string(bad).substr(0, std::string(bad).find(' '))),
                  std::string::npos) << bad << ": " << r.err;
        EXPECT_EQ(r.out, "") << bad;
    }
}

TEST_F(CliTest, MinWeight_IsAcceptedByRenderBenchAndDrag) {
    CliRun r = cli("render " + kRoom + " -o " + path("x.png") + " --width 8 --height 8" +
                   " --min-weight 0.5");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    r = cli("render " + kRoom + " -o " + path("x.png") + " --width 8 --height 8 --min-weight=0");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    r = cli("bench " + kRoom + " --repeat 1 --json --width 8 --height 8 --min-weight 0.01");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    r = cli("drag " + kRoom + " --object 'blue ball' --to 0,1,-5 --steps 2 --threads 2" +
            " --width 16 --height 9 --min-weight 0.001");
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST_F(CliTest, MinWeight_OutsideZeroToOne_Exits2NamingTheOption) {
    for (const char* bad : {"1", "1.5", "-0.1", "abc", "nan", "inf", "0.5x", ""}) {
        for (const char* command : {"render", "bench", "drag"}) {
            const std::string rest = std::string(command) == "render" ? " -o " + path("x.png")
                                     : std::string(command) == "drag"
                                         ? " --object 'blue ball' --to 0,1,-5"
                                         : "";
            CliRun r = cli(std::string(command) + " " + kRoom + rest +
                           " --width 8 --height 8 --min-weight '" + bad + "'");
            EXPECT_EQ(r.exitCode, 2) << command << " " << bad << ": " << r.err;
            EXPECT_NE(r.err.find("--min-weight"), std::string::npos) << command << " " << r.err;
            EXPECT_EQ(r.out, "") << command << " " << bad;
        }
    }
}

TEST_F(CliTest, Render_MissingSceneOrOutput_Exit2) {
    CliRun r = cli("render " + path("nope.scene.json") + " -o " + path("x.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("nope.scene.json"), std::string::npos) << r.err;
    r = cli("render " + kRoom);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("-o OUT"), std::string::npos) << r.err;
    r = cli("render " + kRoom + " -o " + path("x.bmpx") + " --width 8 --height 8");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("x.bmpx"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
}

TEST_F(CliTest, Validate_GoodScenePrintsOk) {
    CliRun r = cli("validate " + kRoom);
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, "ok\n");
    EXPECT_EQ(r.err, "");
}

TEST_F(CliTest, Validate_DeviceDirectoryAndFifo_FailAtOnceNamingThePath) {
    const std::string fifo = path("pipe.scene.json");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
    for (const std::string& bad : {std::string("/dev/zero"), fifo, dir_.string()}) {
        const auto start = std::chrono::steady_clock::now();
        CliRun r = cli("validate '" + bad + "'", 10);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.err;
        EXPECT_LT(s, 5.0) << bad;
        EXPECT_EQ(r.err.rfind(bad + ": cannot read scene file: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
    }
}

TEST_F(CliTest, Validate_NulByteAfterTheScene_IsAnErrorAtItsLineAndColumn) {
    const std::string good = "{\"format\": \"raystudio-scene\", \"version\": 1}\n";
    const std::string scene = write("nul.scene.json", good + std::string(1, '\0') + "garbage");
    CliRun r = cli("validate " + scene);
    EXPECT_EQ(r.exitCode, 2) << r.out;
    EXPECT_NE(r.err.find(scene + ":2:1: syntax error: NUL byte"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
}

TEST_F(CliTest, Validate_BadScenePrintsEveryErrorWithItsPointer) {
    const std::string scene = write("bad.scene.json", R"({
  "format": "raystudio-scene", "version": 1,
  "objects": [
    { "name": "a", "type": "sphere", "center": [0, 0, 0], "radius": 0 },
    { "name": "b", "type": "sphere", "center": [0, 0, 0], "radius": 1, "colour": [1, 0, 0] }
  ]
})");
    CliRun r = cli("validate " + scene);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("/objects/0/radius"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("/objects/1/colour"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(":4:"), std::string::npos) << "line of the first error: " << r.err;
    EXPECT_EQ(r.out, "") << "errors belong on stderr";
}

TEST_F(CliTest, EveryCommand_BadSceneGoesToStderrWithExit2) {
    const std::string bad = write("bad.scene.json", R"({"format": "raystudio-scene", "version": 1,
 "render": {"width": 0}})");
    for (const std::string& command :
         {"validate " + bad, "render " + bad + " -o " + path("x.png"), "bench " + bad,
          "drag " + bad + " --object a --to 0,0,0"}) {
        CliRun r = cli(command);
        EXPECT_EQ(r.exitCode, 2) << command;
        EXPECT_NE(r.err.find("/render/width"), std::string::npos) << command << ": " << r.err;
        EXPECT_EQ(r.out, "") << command;
    }
}

TEST_F(CliTest, Drag_PolicyFileThatIsAFifo_IsRefusedWithoutBlocking) {
    const std::string fifo = path("policy.json");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
    CliRun r = cli("drag " + kRoom + " --object 'blue ball' --to 0,1,-5 --policy " + fifo, 10);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("FIFO"), std::string::npos) << r.err;
}

TEST_F(CliTest, Bench_JsonHasOneEntryPerExperiment) {
    CliRun r = cli("bench " + kRoom + " --repeat 1 --json --width 16 --height 9");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto entries = nlohmann::json::parse(r.out);
    ASSERT_TRUE(entries.is_array());
    EXPECT_EQ(entries.size(), 13u);  // Baseline + 3 experiments of 4 values.
    for (const auto& e : entries) {
        EXPECT_TRUE(e.contains("experiment") && e.contains("value") && e.contains("median_ms") &&
                    e.contains("rays"));
    }
    EXPECT_EQ(entries[1]["experiment"], "shadow_samples");
    EXPECT_EQ(entries[12]["value"], 8);
}

TEST_F(CliTest, GarbageSceneFiles_NeverCrash) {
    std::mt19937 rng(1234);
    const std::string good = R"({"format": "raystudio-scene", "version": 1, "render": {"width": 8,
 "height": 8}, "objects": [{"name": "s", "type": "sphere", "center": [0,0,-3], "radius": 1}]})";
    for (int i = 0; i < 40; ++i) {
        std::string text = good;
        // Mutate a few characters: truncations, swaps, junk bytes.
        for (int m = 0; m < 3; ++m) {
            std::size_t at = rng() % text.size();
            switch (rng() % 3) {
                case 0: text.erase(at, 1 + rng() % 5); break;
                case 1: text[at] = char(rng() % 256); break;
                default: text.insert(text.begin() + long(at), "{}[],:\"0-e."[rng() % 11]); break;
            }
        }
        const std::string scene = write("fuzz.scene.json", text);
        CliRun r = cli("render " + scene + " -o " + path("fuzz.png"));
        EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 2) << "exit " << r.exitCode << " for:\n"
                                                        << text << "\n" << r.err;
    }
}

}  // namespace

namespace {

TEST_F(CliTest, DeepRecursionBetweenMirrors_IsRefusedNotACrash) {
    const std::string scene = write("mirrors.scene.json", R"({
  "format": "raystudio-scene", "version": 1,
  "camera": { "position": [0, 0, 0], "target": [0.3, 0, -1] },
  "render": { "width": 8, "height": 8, "max_depth": 200000 },
  "materials": [ { "name": "m", "diffuse": 0.0, "reflectivity": 1.0 } ],
  "objects": [
    { "name": "a", "type": "plane", "point": [0, 0, -2], "normal": [0, 0, 1], "material": "m" },
    { "name": "b", "type": "plane", "point": [0, 0, 2], "normal": [0, 0, -1], "material": "m" } ]
})");
    CliRun r = cli("render " + scene + " -o " + path("x.png"));
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("/render/max_depth"), std::string::npos) << r.err;
    // The deepest accepted recursion renders (a mirror corridor bounces every ray 1000 times).
    std::ifstream in(scene);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("200000"), 6, "1000");
    const std::string deepest = write("deepest.scene.json", text);
    r = cli("render " + deepest + " -o " + path("x.png"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

}  // namespace

namespace {

// The cost budget: a render estimated over it is refused before anything is compiled, with
// a message naming the budget, unless --force.
TEST_F(CliTest, Render_OverTheCostBudget_Exit2NamingTheBudget) {
    CliRun r = cli("render " + kRoom + " -o " + path("deep.png") + " --max-depth 1000 --min-weight 0");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("ray budget of 1e+11 rays"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(path("deep.png")));
}

TEST_F(CliTest, Render_OverTheCostBudgetWithForce_Renders) {
    // Glass the camera never sees: the estimate (a depth-1000 glass tree) is far over the
    // budget, the render itself one ray a pixel.
    const std::string scene = path("behind.scene.json");
    std::ofstream(scene) << R"({
  "format": "raystudio-scene", "version": 1,
  "camera": { "position": [0, 0, 0], "target": [0, 0, -1] },
  "render": { "width": 4, "height": 4, "max_depth": 1000, "min_weight": 0 },
  "materials": [ { "name": "glass", "transparency": 0.9 } ],
  "objects": [ { "name": "ball", "type": "sphere", "center": [0, 0, 10], "radius": 1, "material": "glass" } ]
})";
    CliRun r = cli("render " + scene + " -o " + path("behind.png"));
    EXPECT_EQ(r.exitCode, 2) << r.err;
    r = cli("render " + scene + " -o " + path("behind.png") + " --force");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(path("behind.png")));
}

TEST_F(CliTest, Render_OverTheAreaLimit_Exit2NamingTheLimit) {
    CliRun r = cli("render " + kRoom + " -o " + path("huge.png") + " --width 16384 --height 16384 --force");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("at most 64 Mpixels"), std::string::npos) << r.err;
}

}  // namespace
