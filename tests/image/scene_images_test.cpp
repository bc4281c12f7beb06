// Image tests: every bundled scene rendered small and compared with its stored reference.
//
// References are linear HDR EXR files in tests/reference/. After an intended change to the
// look of a scene, regenerate them with RAYSTUDIO_UPDATE_REFERENCES=1 and look at the diff.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "image/image_io.h"
#include "integrator/renderer.h"
#include "io/scene_io.h"

namespace rs {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 160;
constexpr int kHeight = 90;
// Tolerance: renders are deterministic, but compilers may round differently at silhouettes
// and shadow edges. Mean error must stay tiny and at most two pixels (of 14,400) may flip, so
// a lost shadow edge or a missing small reflection fails (MissingReflection_Fails below).
// References regenerated for the one trace path (issue 9): min_weight's default 1/255 drops
// rays too weak to matter (largest change 0.0028, mean <= 3.7e-5), forward accumulation of
// ray-tree weights rounds differently; nothing else changed in the pictures. The reference
// room and glass-and-mirrors were regenerated again when glass began to filter shadows
// instead of blocking them (POV-Ray's oracle agrees with the new pictures).
constexpr double kMaxMeanAbsDiff = 2e-5;
constexpr double kPixelFlipThreshold = 1e-2;
constexpr int kMaxFlippedPixels = 2;

struct Difference {
    double mean = 0.0;
    int flipped = 0;
};

Difference difference(const ImageRgb& expected, const ImageRgb& actual) {
    Difference d;
    double sum = 0.0;
    for (std::size_t i = 0; i < expected.pixels.size(); ++i) {
        const Color e = glm::abs(expected.pixels[i] - actual.pixels[i]);
        sum += (e.x + e.y + e.z) / 3.0;
        if (std::max({e.x, e.y, e.z}) > kPixelFlipThreshold) ++d.flipped;
    }
    d.mean = sum / double(expected.pixels.size());
    return d;
}

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

    const Difference d = difference(expected, render.image);
    EXPECT_LE(d.mean, kMaxMeanAbsDiff) << stem;
    EXPECT_LE(d.flipped, kMaxFlippedPixels)
        << stem << ": " << d.flipped << " pixels differ by more than " << kPixelFlipThreshold;
    // A blank render would be a broken scene, whatever the reference says.
    double energy = 0.0;
    for (const Color& c : render.image.pixels) energy += c.x + c.y + c.z;
    EXPECT_GT(energy / double(render.image.pixels.size()), 0.01) << stem << " renders black";
}

// The tolerance means something: the reference room with its small chrome ball made matte
// (one missing reflection) or its light's shadow rays off must fail the same comparison.
TEST(SceneImageTolerance, MissingReflectionOrShadow_Fails) {
    SceneLoadResult loaded = loadScene(RAYSTUDIO_SCENES_DIR "/reference-room.scene.json");
    ASSERT_TRUE(loaded.ok()) << loaded.errorText();
    SceneDocument doc = loaded.document;
    doc.render.width = kWidth;
    doc.render.height = kHeight;
    ImageRgb expected;
    std::string error;
    ASSERT_TRUE(readImage(RAYSTUDIO_REFERENCE_DIR "/reference-room.exr", expected, error)) << error;
    const Difference same = difference(expected, renderImage(CompiledScene(doc)).image);
    EXPECT_LE(same.flipped, kMaxFlippedPixels);
    SceneDocument matte = doc;
    for (Object& o : matte.objects.editable())
        if (o.name == "chrome ball") o.material = "chalk";
    const Difference noReflection = difference(expected, renderImage(CompiledScene(matte)).image);
    EXPECT_GT(noReflection.flipped, kMaxFlippedPixels);
    SceneDocument unshadowed = doc;
    unshadowed.render.shadowSamples = 0;
    const Difference noShadow = difference(expected, renderImage(CompiledScene(unshadowed)).image);
    EXPECT_GT(noShadow.flipped, kMaxFlippedPixels);
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
