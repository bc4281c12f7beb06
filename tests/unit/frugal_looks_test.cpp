// The session stays frugal for the looks of version 2: an environment edit re-traces only the
// pixels with a ray that left the scene, turning a spot light only what its cone can reach,
// a pattern edit only the pixels that see the material; each ends exact.
#include <gtest/gtest.h>

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

TEST(FrugalLooks, ACheckerOnTheBallsMaterial_RetracesTheBallAndItsReflection_AndEndsExact) {
    SceneDocument doc = openAir();
    doc.environment = Environment{};
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

}  // namespace
}  // namespace rs
