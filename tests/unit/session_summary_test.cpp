// Per-tile summaries: an edit's marking and the next pass visit only the tiles its dirty
// region covers (counted through the session's statistics), the tile state counts and
// summaries keep describing the pixels, and the refined frame still equals a full render.
#include <gtest/gtest.h>

#include <algorithm>

#include "session/dirty_region.h"
#include "session_test_support.h"

namespace rs {
namespace {

using namespace std::chrono_literals;
using test::maxDiffToFullRender;

constexpr int kWidth = 256, kHeight = 192;  // 8 x 6 tiles of 32, 32 x 24 blocks of 8.
constexpr int kTileX = 3, kTileY = 2;       // The tile the small ball sits in.

/// A diffuse room (no mirror or glass, so only footprints and shadows can be dirty) with a
/// small ball seen through the centre of tile (kTileX, kTileY).
SceneDocument diffuseRoomWithBall(ObjectId& ball) {
    SceneDocument doc;
    doc.render.width = kWidth;
    doc.render.height = kHeight;
    doc.camera.position = Vec3(0, 0, 0);
    doc.camera.target = Vec3(0, -0.5f, -4);
    test::addMaterial(doc, "white", Color(0.75f), 0.9f, 0.3f);
    test::addMaterial(doc, "red", Color(0.8f, 0.2f, 0.2f), 1.0f);
    test::addPlane(doc, "floor", Vec3(0, -2, 0), Vec3(0, 1, 0), "white");
    test::addPlane(doc, "back", Vec3(0, 0, -8), Vec3(0, 0, 1), "red");
    test::addSphere(doc, "big ball", Vec3(-1.5f, -1.2f, -5), 0.8f, "white");
    test::addPointLight(doc, "key", Vec3(0, 3, -3));
    const CompiledScene probe(doc);
    const Ray ray = probe.camera().generateRay(float(kTileX * 32 + 16), float(kTileY * 32 + 16));
    ball = test::addSphere(doc, "small ball", ray.origin + ray.dir * 4.0f, 0.06f, "white");
    return doc;
}

bool summariesHold(const RenderSession& session) {
    bool ok = false;
    session.withFrame([&](const DeepFrame& f, const auto&) { ok = f.summariesMatchPixels(); });
    return ok;
}

TEST(SessionSummaries, StepInsideOneTile_VisitsOnlyThatTile_AndFrameEqualsFullRender) {
    ObjectId ball = kNoObject;
    SceneDocument doc = diffuseRoomWithBall(ball);
    RenderSession session(2);
    InteractionPolicy policy;
    policy.shadows = MovingShadows::Off;  // Shadows are marked on release: footprints only.
    policy.governorTargetMs = 0.0;
    session.setPolicy(policy);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    ASSERT_TRUE(summariesHold(session));

    session.beginInteraction(ball);
    for (int step = 0; step < 3; ++step) {
        const Aabb before = CompiledScene(doc).objectBounds(ball);
        doc.findObject(ball)->transform.translate += Vec3(0.004f, 0.003f, 0.0f);
        const CompiledScene after(doc);
        Aabb both = before;
        both.expand(after.objectBounds(ball));
        // Precondition: the step's footprint, grown by the pixel marking adds, lies in the tile.
        const PixelRect r = screenFootprint(after.camera(), both);
        ASSERT_GE(r.x0 - 1, kTileX * 32);
        ASSERT_LE(r.x1 + 1, (kTileX + 1) * 32);
        ASSERT_GE(r.y0 - 1, kTileY * 32);
        ASSERT_LE(r.y1 + 1, (kTileY + 1) * 32);

        const uint64_t gen = session.update(doc);
        PassInfo info;
        ASSERT_TRUE(session.waitForPass(gen, 60s, &info)) << "step " << step;
        const SessionStats stats = session.stats();
        EXPECT_GT(stats.lastDirtyPixels, 0u) << "step " << step;
        // Marking tested the blocks of the one tile whose summary the edit can reach (16 of
        // the frame's 768), grew marks only around the footprint's blocks, and the pass was
        // planned over that tile alone.
        EXPECT_GT(stats.lastMarkBlocksTested, 0u) << "step " << step;
        EXPECT_LE(stats.lastMarkBlocksTested, 16u) << "step " << step;
        const int bx0 = r.x0 / 8, bx1 = (r.x1 - 1) / 8, by0 = r.y0 / 8, by1 = (r.y1 - 1) / 8;
        EXPECT_LE(stats.lastMarkBlocksGrown, std::size_t((bx1 - bx0 + 3) * (by1 - by0 + 3)))
            << "step " << step;
        EXPECT_EQ(stats.lastPassTiles, 1u) << "step " << step;
        EXPECT_EQ(info.totalPixels, std::size_t(kWidth) * std::size_t(kHeight));
        EXPECT_LE(info.tracedPixels, std::size_t(32 * 32)) << "step " << step;
        EXPECT_TRUE(summariesHold(session)) << "step " << step;
    }
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_TRUE(summariesHold(session));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

TEST(SessionSummaries, CountsAndSummariesFollowEdits_WithSupersampling) {
    // Drags with deferred shadows, a retint, a camera move and adaptive supersampling: after
    // every pass the tile state counts, the sample flags and the tile and block summaries
    // equal what the pixels give, and the refined frame equals a full render.
    SceneDocument doc = test::testRoom();
    doc.render.supersampling = 4;
    doc.render.adaptiveSupersampling = true;
    RenderSession session(2);
    InteractionPolicy policy;
    policy.governorTargetMs = 0.0;
    session.setPolicy(policy);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    ASSERT_TRUE(summariesHold(session));
    Object* ball = nullptr;
    for (Object& o : doc.objects.editable())
        if (o.name == "mirror ball") ball = &o;
    ASSERT_NE(ball, nullptr);
    const ObjectId id = ball->id;
    session.beginInteraction(id);
    for (int step = 0; step < 4; ++step) {
        doc.findObject(id)->transform.translate += Vec3(0.05f, 0.02f, 0.0f);
        const uint64_t gen = session.update(doc);
        ASSERT_TRUE(session.waitForPass(gen, 60s)) << "step " << step;
        EXPECT_TRUE(summariesHold(session)) << "step " << step;
    }
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_TRUE(summariesHold(session));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);

    doc.materials[0].color = Color(0.3f, 0.6f, 0.9f);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_TRUE(summariesHold(session));
    doc.camera.target.x += 0.05f;
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_TRUE(summariesHold(session));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

}  // namespace
}  // namespace rs
