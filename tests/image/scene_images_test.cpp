// Image tests: every bundled scene rendered small and compared with its stored reference.
//
// References are linear HDR EXR files in tests/reference/. After an intended change to the
// look of a scene, regenerate them with RAYSTUDIO_UPDATE_REFERENCES=1 and look at the diff.
#include "image/image_io.h"
#include "integrator/renderer.h"
#include "io/scene_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace rs {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 160;
constexpr int kHeight = 90;
// Tolerance: renders are deterministic, but compilers may round differently at silhouettes
// and shadow edges. Mean error must stay tiny and only a few pixels may flip.
constexpr double kMaxMeanAbsDiff = 2e-4;
constexpr double kPixelFlipThreshold = 1e-2;
constexpr double kMaxFlippedFraction = 0.005;

std::vector<fs::path> bundledScenes() {
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::directory_iterator(RAYSTUDIO_SCENES_DIR))
        if (entry.path().string().ends_with(".scene.json")) scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

class SceneImage : public ::testing::TestWithParam<fs::path> {};

TEST_P(SceneImage, MatchesReference) {
    const fs::path scenePath = GetParam();
    SceneLoadResult loaded = loadScene(scenePath.string());
    ASSERT_TRUE(loaded.ok()) << loaded.errorText();
    loaded.document.render.width = kWidth;
    loaded.document.render.height = kHeight;
    const RenderResult render = renderImage(CompiledScene(loaded.document));

    const std::string stem = scenePath.filename().string().substr(
        0, scenePath.filename().string().size() - std::string(".scene.json").size());
    const fs::path reference = fs::path(RAYSTUDIO_REFERENCE_DIR) / (stem + ".exr");
    std::string error;
    if (std::getenv("RAYSTUDIO_UPDATE_REFERENCES")) {
        ASSERT_TRUE(writeImage(reference.string(), render.image, ToneMap::Clamp, 0.0f, error))
            << error;
        GTEST_SKIP() << "reference written: " << reference;
    }
    ImageRgb expected;
    ASSERT_TRUE(readImage(reference.string(), expected, error))
        << error << " (set RAYSTUDIO_UPDATE_REFERENCES=1 to create it)";
    ASSERT_EQ(expected.width, kWidth);
    ASSERT_EQ(expected.height, kHeight);

    double sum = 0.0;
    int flipped = 0;
    for (std::size_t i = 0; i < expected.pixels.size(); ++i) {
        const Color d = glm::abs(expected.pixels[i] - render.image.pixels[i]);
        const double m = std::max({d.x, d.y, d.z});
        sum += (d.x + d.y + d.z) / 3.0;
        if (m > kPixelFlipThreshold) ++flipped;
    }
    const double mean = sum / double(expected.pixels.size());
    EXPECT_LE(mean, kMaxMeanAbsDiff) << stem;
    EXPECT_LE(double(flipped) / double(expected.pixels.size()), kMaxFlippedFraction)
        << stem << ": " << flipped << " pixels differ by more than " << kPixelFlipThreshold;
    // A blank render would be a broken scene, whatever the reference says.
    double energy = 0.0;
    for (const Color& c : render.image.pixels) energy += c.x + c.y + c.z;
    EXPECT_GT(energy / double(render.image.pixels.size()), 0.01) << stem << " renders black";
}

INSTANTIATE_TEST_SUITE_P(Bundled, SceneImage, ::testing::ValuesIn(bundledScenes()),
                         [](const auto& info) {
                             std::string name = info.param.filename().string();
                             name = name.substr(0, name.find('.'));
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

}  // namespace
}  // namespace rs
