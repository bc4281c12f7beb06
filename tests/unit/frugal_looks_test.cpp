// The session stays frugal for the looks of version 2: an environment edit re-traces only the
// pixels with a ray that left the scene, turning a spot light only what its cone can reach,
// a pattern edit only the pixels that see the material, an image saved again on disk only
// the pixels that see it; each ends exact.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "session_test_support.h"
#include "test_scenes.h"

namespace rs {
namespace {

using namespace std::chrono_literals;
const std::string kScenes = RAYSTUDIO_SCENES_DIR;

/// An open scene: a floor, a diffuse ball and a mirror ball under the sky; the upper part of
/// the image sees the sky directly, the mirror ball sees it reflected.
SceneDocument openAir() {
    SceneDocument doc;
    doc.render.width = 64;
    doc.render.height = 48;
    doc.camera.position = Vec3(0, 0, 0);
    doc.camera.target = Vec3(0, -0.3f, -4);
    test::addMaterial(doc, "white", Color(0.75f), 0.9f);
    test::addMaterial(doc, "mirror", Color(0.9f), 0.0f, 0.0f, 0.9f);
    test::addPlane(doc, "floor", Vec3(0, -2, 0), Vec3(0, 1, 0), "white");
    test::addSphere(doc, "diffuse ball", Vec3(-1.5f, -1.2f, -5), 0.8f, "white");
    test::addSphere(doc, "mirror ball", Vec3(1.0f, -1.0f, -6), 1.0f, "mirror");
    test::addPointLight(doc, "key", Vec3(0, 3, -3));
    doc.environment.image = {"textures/sky.hdr", kScenes + "/textures/sky.hdr"};
    return doc;
}

/// Pixels showing what `seen` says, grown by one pixel (marking grows its marks so).
std::size_t grownCount(RenderSession& session, const std::function<bool(ObjectId)>& seen) {
    std::size_t count = 0;
    session.withFrame([&](const DeepFrame& f, const auto&) {
        for (int y = 0; y < f.height(); ++y)
            for (int x = 0; x < f.width(); ++x) {
                bool near = false;
                for (int dy = -1; dy <= 1 && !near; ++dy)
                    for (int dx = -1; dx <= 1 && !near; ++dx) {
                        const int xx = x + dx, yy = y + dy;
                        if (xx >= 0 && yy >= 0 && xx < f.width() && yy < f.height())
                            near = seen(f.id()[f.index(xx, yy)]);
                    }
                count += near;
            }
    });
    return count;
}

void environmentEdits(int supersampling) {
    SceneDocument doc = openAir();
    doc.render.supersampling = supersampling;
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const ObjectId mirror = doc.objects[2].id;
    const std::size_t sky = grownCount(session, [](ObjectId id) { return id == kNoObject; });
    const std::size_t skyOrMirror =
        grownCount(session, [&](ObjectId id) { return id == kNoObject || id == mirror; });
    const std::size_t total = std::size_t(doc.render.width) * std::size_t(doc.render.height);
    ASSERT_GT(sky, total / 10) << "the view must see the sky";
    ASSERT_LT(skyOrMirror, total * 3 / 4) << "and mostly something else";

    for (int k = 0; k < 3; ++k) {
        if (k == 0) doc.environment.rotation = 90.0f;
        if (k == 1) doc.environment.intensity = 1.7f;
        if (k == 2) doc.environment = Environment{};  // back to the background colour
        ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
        const std::size_t marked = session.stats().lastDirtyPixels;
        EXPECT_GE(marked, sky - std::size_t(doc.render.width)) << "edit " << k;
        // A supersample may see the sky from a pixel whose centre and neighbours do not.
        const std::size_t slack = supersampling > 1 ? std::size_t(doc.render.width) : 0;
        EXPECT_LE(marked, skyOrMirror + slack) << "edit " << k;
        ASSERT_TRUE(session.waitUntilComplete(60s));
        EXPECT_LE(test::maxDiffToFullRender(session, doc), 1e-5f) << "edit " << k;
    }
}

TEST(FrugalLooks, EnvironmentEdit_RetracesThePixelsThatSeeTheSky_AndEndsExact) {
    environmentEdits(1);
}

TEST(FrugalLooks, EnvironmentEdit_Supersampled_RetracesThePixelsWhoseSamplesSeeTheSky) {
    environmentEdits(4);
}

TEST(FrugalLooks, TurningANarrowSpot_RetracesOnlyWhatItsConeReaches_AndEndsExact) {
    SceneDocument doc = openAir();
    doc.environment = Environment{};
    Light spot;
    spot.name = "spot";
    spot.type = LightType::Spot;
    spot.position = Vec3(-1.5f, 2.0f, -5.0f);
    spot.target = Vec3(-1.5f, -2.0f, -5.0f);  // straight down onto the diffuse ball
    spot.coneRadius = 8.0f;
    spot.coneFalloff = 12.0f;
    doc.addLight(spot);
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const std::size_t total = std::size_t(doc.render.width) * std::size_t(doc.render.height);
    for (int k = 0; k < 2; ++k) {
        Light& l = doc.lights.back();
        if (k == 0) l.target.x += 0.3f;     // turn it
        if (k == 1) l.coneFalloff = 14.0f;  // widen its edge
        ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
        const std::size_t marked = session.stats().lastDirtyPixels;
        EXPECT_GT(marked, 0u) << "edit " << k;
        // Without the cone every pixel above the spot's horizon (nearly all) would re-trace.
        EXPECT_LT(marked, total / 3) << "edit " << k;
        ASSERT_TRUE(session.waitUntilComplete(60s));
        EXPECT_LE(test::maxDiffToFullRender(session, doc), 1e-5f) << "edit " << k;
    }
}

void checkerOnTheBall(int supersampling) {
    SceneDocument doc = openAir();
    doc.environment = Environment{};
    doc.render.supersampling = supersampling;
    test::addMaterial(doc, "ball paint", Color(0.8f, 0.3f, 0.2f), 1.0f);
    doc.objects[1].material = "ball paint";
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const std::size_t total = std::size_t(doc.render.width) * std::size_t(doc.render.height);
    CheckerPattern c;
    c.even = Color(0.9f, 0.9f, 0.1f);
    c.odd = Color(0.1f, 0.1f, 0.9f);
    c.scale = 0.25f;
    doc.materials.back().pattern = c;
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
    const std::size_t marked = session.stats().lastDirtyPixels;
    EXPECT_GT(marked, 0u);
    EXPECT_LT(marked, total / 3);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(test::maxDiffToFullRender(session, doc), 1e-5f);
}

TEST(FrugalLooks, ACheckerOnTheBallsMaterial_RetracesTheBallAndItsReflection_AndEndsExact) {
    checkerOnTheBall(1);
}

TEST(FrugalLooks, ACheckerOnTheBallsMaterial_Supersampled_RetracesOnlyPixelsWhoseSamplesSeeIt) {
    // A supersampled pixel is re-traced only when its centre or one of its samples saw the
    // ball (or it touched a mirror), not because it is supersampled.
    checkerOnTheBall(4);
}

/// A 4 x 4 image of one colour, written over `path` (PNG: 8-bit sRGB; HDR: float), and
/// dated `age` seconds from now so that each version has a stamp of its own.
void writeFlatImage(const std::string& path, const Color& c, int age) {
    const bool png = path.size() > 4 && path.substr(path.size() - 4) == ".png";
    std::vector<float> pixels(4 * 4 * 3);
    for (std::size_t i = 0; i < pixels.size(); i += 3)
        pixels[i] = c.x, pixels[i + 1] = c.y, pixels[i + 2] = c.z;
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << OIIO::geterror();
    const OIIO::ImageSpec spec(4, 4, 3, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
    ASSERT_TRUE(out->close());
    namespace fs = std::filesystem;
    fs::last_write_time(path, fs::file_time_type::clock::now() + std::chrono::seconds(age));
}

/// A fresh folder for the images a test writes, removed after it.
struct ScratchFolder {
    std::filesystem::path path;
    ScratchFolder() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "rs-frugal-XXXXXX").string();
        path = ::mkdtemp(pattern.data());
    }
    ~ScratchFolder() { std::filesystem::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

/// The colour the session shows at the centre of object `id`'s pixels (their mean).
Color meanColourOf(RenderSession& session, ObjectId id) {
    Color sum(0.0f);
    int n = 0;
    session.withFrame([&](const DeepFrame& f, const auto&) {
        for (int y = 0; y < f.height(); ++y)
            for (int x = 0; x < f.width(); ++x)
                if (f.id()[f.index(x, y)] == id) sum += f.color()[f.index(x, y)], ++n;
    });
    return n ? sum / float(n) : sum;
}

/// Posts `doc` again to a session that shows it whole: no pass runs.
void expectNothingRetraced(RenderSession& session, const SceneDocument& doc, const char* what) {
    const uint64_t passes = session.stats().passes;
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s)) << what;
    ASSERT_TRUE(session.waitUntilComplete(60s)) << what;
    EXPECT_EQ(session.stats().passes, passes) << what;
}

TEST(FrugalLooks, ATextureSavedAgainOnDisk_RetracesTheBallAndItsReflection_AndEndsExact) {
    const ScratchFolder folder;
    const std::string paint = folder.file("paint.png");
    writeFlatImage(paint, Color(0.9f, 0.1f, 0.1f), -20);
    SceneDocument doc = openAir();
    doc.environment = Environment{};
    test::addMaterial(doc, "ball paint", Color(0.8f), 1.0f);
    ImageTexture texture;
    texture.image = {paint, paint};
    doc.materials.back().pattern = texture;
    doc.objects[1].material = "ball paint";
    const ObjectId ball = doc.objects[1].id;
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const Color red = meanColourOf(session, ball);
    ASSERT_GT(red.x, 2.0f * red.y) << "the ball shows the red image";

    // The same document again: nothing changed on disk, nothing is re-traced.
    expectNothingRetraced(session, doc, "unchanged");

    // The image saved again, green, as a paint program would: the same document, posted
    // again (the designer does so when its window becomes active), shows it.
    writeFlatImage(paint, Color(0.1f, 0.9f, 0.1f), -10);
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
    const std::size_t marked = session.stats().lastDirtyPixels;
    const std::size_t total = std::size_t(doc.render.width) * std::size_t(doc.render.height);
    EXPECT_GT(marked, 0u);
    EXPECT_LT(marked, total / 3);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const Color green = meanColourOf(session, ball);
    EXPECT_GT(green.y, 2.0f * green.x) << "the ball shows the green image";
    EXPECT_LE(test::maxDiffToFullRender(session, doc), 1e-5f);

    // Gone from disk: the missing pattern, exact too; then nothing more to re-trace.
    std::filesystem::remove(paint);
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
    EXPECT_GT(session.stats().lastDirtyPixels, 0u);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(test::maxDiffToFullRender(session, doc), 1e-5f);
    expectNothingRetraced(session, doc, "still gone");
}

TEST(FrugalLooks, TheSkySavedAgainOnDisk_RetracesThePixelsThatSeeIt_AndEndsExact) {
    const ScratchFolder folder;
    const std::string sky = folder.file("sky.hdr");
    writeFlatImage(sky, Color(0.2f, 0.3f, 0.9f), -20);
    SceneDocument doc = openAir();
    doc.environment.image = {sky, sky};
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const std::size_t sees = grownCount(
        session, [&](ObjectId id) { return id == kNoObject || id == doc.objects[2].id; });
    const std::size_t total = std::size_t(doc.render.width) * std::size_t(doc.render.height);

    writeFlatImage(sky, Color(0.9f, 0.5f, 0.2f), -10);
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
    const std::size_t marked = session.stats().lastDirtyPixels;
    EXPECT_GT(marked, total / 10);
    EXPECT_LE(marked, sees);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const Color evening = meanColourOf(session, kNoObject);
    EXPECT_GT(evening.x, evening.z) << "the sky shows the new image";
    EXPECT_LE(test::maxDiffToFullRender(session, doc), 1e-5f);
}

}  // namespace
}  // namespace rs
