// raystudio-cli as a user runs it: exit codes 0/1/2, messages that name the problem, outputs.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "cli_run.h"
#include "image/image_io.h"

namespace {

namespace fs = std::filesystem;

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("raystudio-cli-test-" +
                std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
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

TEST_F(CliTest, CommandHelp_PrintsThatCommandsUsageToStdoutAndExits0) {
    for (const char* command : {"render", "validate", "bench", "drag", "merge", "farm"}) {
        for (const char* flag : {"--help", "-h"}) {
            CliRun r = cli(std::string(command) + " " + flag);
            EXPECT_EQ(r.exitCode, 0) << command << " " << flag << ": " << r.err;
            EXPECT_EQ(r.err, "") << command;
            EXPECT_EQ(r.out.find("usage: raystudio-cli"), 0u) << r.out;
            EXPECT_NE(r.out.find(std::string("  ") + command + " "), std::string::npos) << r.out;
        }
    }
    // Only that command's entries: render's two, and neither drag nor merge.
    const CliRun render = cli("render " + kRoom + " --help");
    EXPECT_NE(render.out.find("--tile I/N"), std::string::npos) << render.out;
    EXPECT_NE(render.out.find("--force"), std::string::npos) << render.out;
    EXPECT_EQ(render.out.find("drag SCENE"), std::string::npos) << render.out;
    EXPECT_EQ(render.out.find("merge PART"), std::string::npos) << render.out;
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
    // Each extension gives its format (the file's magic bytes), and every file holds the same
    // picture: read back, the 8-bit ones agree with each other, the float ones with each other.
    const std::vector<std::pair<std::string, std::string>> formats = {{"png", "\x89PNG"},
                                                                      {"jpg", "\xff\xd8\xff"},
                                                                      {"tif", "II*"},
                                                                      {"exr", "v/1\x01"},
                                                                      {"hdr", "#?RADIANCE"}};
    std::map<std::string, rs::ImageRgb> images;
    for (const auto& [ext, magic] : formats) {
        const std::string out = path("room." + ext);
        CliRun r = cli("render " + kRoom + " -o " + out + " --width 16 --height 9");
        ASSERT_EQ(r.exitCode, 0) << ext << ": " << r.err;
        EXPECT_EQ(r.out, "") << ext;
        EXPECT_EQ(readAll(out).substr(0, magic.size()), magic) << ext << " is not that format";
        std::string error;
        ASSERT_TRUE(rs::readImage(out, images[ext], error)) << ext << ": " << error;
        ASSERT_EQ(images[ext].width, 16) << ext;
        ASSERT_EQ(images[ext].height, 9) << ext;
    }
    // Largest difference, relative to the pixel's largest channel when `relative`, and mean.
    auto worst = [&](const std::string& a, const std::string& b, bool relative) {
        float w = 0.0f;
        for (std::size_t i = 0; i < images[a].pixels.size(); ++i) {
            const rs::Color x = images[a].pixels[i], y = images[b].pixels[i];
            const float scale = relative ? std::max({1e-3f, x.x, x.y, x.z}) : 1.0f;
            for (int c = 0; c < 3; ++c) w = std::max(w, std::abs(x[c] - y[c]) / scale);
        }
        return w;
    };
    auto mean = [&](const std::string& a, const std::string& b) {
        double sum = 0.0;
        for (std::size_t i = 0; i < images[a].pixels.size(); ++i) {
            const rs::Color d = glm::abs(images[a].pixels[i] - images[b].pixels[i]);
            sum += double(d.x + d.y + d.z) / 3.0;
        }
        return sum / double(images[a].pixels.size());
    };
    EXPECT_EQ(worst("png", "tif", false), 0.0f);  // both lossless 8-bit
    EXPECT_LE(mean("png", "jpg"), 0.05);          // JPEG loss at 16x9 (chroma subsampled), linear
    EXPECT_LE(worst("exr", "hdr", true), 0.01f);  // RGBE: 8 bits of mantissa, a shared exponent
    // Not a blank picture: the red left wall and the dark floor differ.
    float lo = 1e9f, hi = 0.0f;
    for (const rs::Color& c : images["exr"].pixels) lo = std::min(lo, c.x), hi = std::max(hi, c.x);
    EXPECT_GT(hi - lo, 0.2f);
}

TEST_F(CliTest, Render_BadNumbers_Exit2NamingTheOption) {
    for (const char* bad : {"--width 0", "--width abc", "--height -5", "--threads 0",
                            "--supersampling 0", "--max-depth -1", "--width 99999"}) {
        CliRun r = cli("render " + kRoom + " -o " + path("x.png") + " " + bad);
        EXPECT_EQ(r.exitCode, 2) << bad;
        EXPECT_NE(r.err.find(std::string(bad).substr(0, std::string(bad).find(' '))),
                  std::string::npos)
            << bad << ": " << r.err;
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

TEST_F(CliTest, DragJson_ReportsTheSessionFrameAndRenderImageInWallAndCpuTime) {
    const CliRun r = cli("drag " + kRoom + " --object 'blue ball' --to 0,1,-5 --steps 2" +
                         " --threads 2 --width 16 --height 9 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto stats = nlohmann::json::parse(r.out);
    for (const char* key :
         {"session_frame_ms", "render_image_ms", "session_frame_cpu_ms", "render_image_cpu_ms"}) {
        ASSERT_TRUE(stats.contains(key)) << key << " missing in " << r.out;
        EXPECT_GE(stats[key].get<double>(), 0.0) << key;
    }
}

TEST_F(CliTest, DragFrames_SetsHowManySessionFramesAreTimedAndRejectsBadCounts) {
    CliRun r = cli("drag " + kRoom + " --object 'blue ball' --to 0,1,-5 --steps 1" +
                   " --threads 2 --width 16 --height 9 --frames 3 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["session_frames"].get<int>(), 3) << r.out;
    r = cli("drag " + kRoom + " --object 'blue ball' --to 0,1,-5 --steps 1 --width 16 --height 9");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("medians of 5"), std::string::npos) << r.out;  // the default
    for (const char* bad : {"0", "-1", "1001", "x", ""}) {
        r = cli("drag " + kRoom + " --object 'blue ball' --to 0,1,-5 --width 8 --height 8" +
                " --frames '" + bad + "'");
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.err;
        EXPECT_NE(r.err.find("--frames"), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "") << bad;
    }
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
    // "At once": the refusal names the check made before anything is read ("not a regular
    // file"), which a run that read /dev/zero or waited on the FIFO could not print; the
    // run's 10 s limit only stops a hang (no bound in seconds: that raced a loaded machine).
    for (const std::string& bad : {std::string("/dev/zero"), fifo, dir_.string()}) {
        CliRun r = cli("validate '" + bad + "'", 10);
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.err;
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
    for (const std::string& command : {"validate " + bad, "render " + bad + " -o " + path("x.png"),
                                       "bench " + bad, "drag " + bad + " --object a --to 0,0,0"}) {
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
    ASSERT_EQ(entries.size(), 13u);  // Baseline + 3 experiments of 4 values.
    std::map<std::string, std::vector<std::pair<int, long>>> runs;  // experiment -> (value, rays)
    for (const auto& e : entries) {
        ASSERT_TRUE(e.contains("experiment") && e.contains("value") && e.contains("median_ms") &&
                    e.contains("rays"))
            << e.dump();
        EXPECT_GE(e["median_ms"].get<double>(), 0.0);
        runs[e["experiment"]].emplace_back(e["value"].get<int>(), e["rays"].get<long>());
    }
    ASSERT_EQ(runs["baseline"].size(), 1u);
    const long baseline = runs["baseline"][0].second;
    auto values = [&](const std::string& name) {
        std::vector<int> v;
        for (const auto& [value, rays] : runs[name]) v.push_back(value);
        return v;
    };
    EXPECT_EQ(values("shadow_samples"), (std::vector<int>{0, 1, 27, 64}));
    EXPECT_EQ(values("max_depth"), (std::vector<int>{0, 1, 2, 44}));
    EXPECT_EQ(values("supersampling"), (std::vector<int>{1, 2, 4, 8}));
    // What each experiment does to the work, at 16 x 9 = 144 pixels of the room:
    // no shadow rays without shadows; the room's one point light takes one shadow ray per
    // shading point whatever the sample count (its samples coincide); the baseline is the
    // scene's own settings (1 sample, depth 3, no supersampling).
    const auto& shadows = runs["shadow_samples"];
    EXPECT_GE(shadows[0].second, 144);
    EXPECT_LT(shadows[0].second, shadows[1].second);
    EXPECT_EQ(shadows[1].second, baseline);
    EXPECT_EQ(shadows[2].second, shadows[1].second);
    EXPECT_EQ(shadows[3].second, shadows[1].second);
    // Deeper trees trace more rays.
    const auto& depth = runs["max_depth"];
    for (std::size_t i = 1; i < depth.size(); ++i) EXPECT_GT(depth[i].second, depth[i - 1].second);
    // k samples per pixel: about k times the rays of one, plus, with several samples, the id
    // pass's one camera ray a pixel (144).
    const auto& ss = runs["supersampling"];
    EXPECT_EQ(ss[0].second, baseline);
    for (const auto& [k, rays] : ss) {
        const double idPass = k > 1 ? 144.0 : 0.0;
        EXPECT_GE(double(rays), 0.9 * k * double(baseline) + idPass) << k << " samples";
        EXPECT_LE(double(rays), 1.2 * k * double(baseline) + idPass) << k << " samples";
    }
}

TEST_F(CliTest, GarbageSceneFiles_NeverCrash) {
    // Every mutation ends in exit 0 with an image or exit 2 with a message naming the file and
    // the place; what render accepts, validate accepts; text that is not JSON at all (as
    // nlohmann::json, an independent parser, judges) is always an error at a line and column.
    // (Whether the rest are valid is validate's business: scene_errors_test.cpp.)
    std::mt19937 rng(1234);
    const std::string good = R"({"format": "raystudio-scene", "version": 1, "render": {"width": 8,
 "height": 8}, "objects": [{"name": "s", "type": "sphere", "center": [0,0,-3], "radius": 1}]})";
    int rejected = 0, notJson = 0;
    for (int i = 0; i < 40; ++i) {
        std::string text = good;
        // Mutate a few characters: truncations, swaps, junk bytes.
        for (int m = 0; m < 3; ++m) {
            std::size_t at = rng() % text.size();
            switch (rng() % 3) {
                case 0:
                    text.erase(at, 1 + rng() % 5);
                    break;
                case 1:
                    text[at] = char(rng() % 256);
                    break;
                default:
                    text.insert(text.begin() + long(at), "{}[],:\"0-e."[rng() % 11]);
                    break;
            }
        }
        const std::string scene = write("fuzz.scene.json", text);
        fs::remove(path("fuzz.png"));
        CliRun r = cli("render " + scene + " -o " + path("fuzz.png"));
        const std::string what = "mutation " + std::to_string(i) + ":\n" + text + "\n" + r.err;
        ASSERT_TRUE(r.exitCode == 0 || r.exitCode == 2) << "exit " << r.exitCode << " for " << what;
        if (r.exitCode == 0) {  // a scene render accepts, validate accepts too
            EXPECT_TRUE(fs::exists(path("fuzz.png"))) << what;
            EXPECT_EQ(cli("validate " + scene).out, "ok\n") << what;
            continue;
        }
        ++rejected;
        EXPECT_FALSE(fs::exists(path("fuzz.png"))) << "an image written for " << what;
        EXPECT_EQ(r.out, "") << what;
        EXPECT_EQ(r.err.rfind(scene + ":", 0), 0u)
            << "the message does not start with the file: " << what;
        if (!nlohmann::json::accept(text)) {
            ++notJson;
            // file:line:column: ...
            const std::string rest = r.err.substr(scene.size() + 1);
            EXPECT_TRUE(!rest.empty() && std::isdigit(static_cast<unsigned char>(rest[0])) &&
                        rest.find(':') != std::string::npos)
                << "no line and column for " << what;
        }
    }
    // Three random edits of a 150-byte file break it most of the time; a test where every
    // mutation passed would test nothing.
    EXPECT_GE(rejected, 25);
    EXPECT_GE(notJson, 15);
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
    CliRun r =
        cli("render " + kRoom + " -o " + path("deep.png") + " --max-depth 1000 --min-weight 0");
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
    CliRun r = cli("render " + kRoom + " -o " + path("huge.png") +
                   " --width 16384 --height 16384 --force");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("at most 64 Mpixels"), std::string::npos) << r.err;
}

}  // namespace
