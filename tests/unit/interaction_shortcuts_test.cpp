// Two of the session's shortcuts while the user drags, each checked for what it promises:
// interleaving traces one half of the stale pixels per pass and the other half in the next,
// and the box proxy is shown while moving but never kept in the refined frame.
#include <gtest/gtest.h>

#include <thread>

#include "session_test_support.h"

namespace rs {
namespace {

using namespace std::chrono_literals;
using test::firstDragStep;
using test::maxDiffToFullRender;
using test::testRoom;

/// Pixels of the session's frame in `state`.
std::size_t pixelsIn(RenderSession& session, uint8_t state) {
    std::size_t n = 0;
    session.withFrame([&](const DeepFrame& f, const auto&) {
        for (std::size_t i = 0; i < f.pixelCount(); ++i) n += f.state()[i] == state;
    });
    return n;
}

TEST(InteractionShortcuts, Interleaved_OnePassTracesHalfTheStalePixels_TheNextTheOtherHalf) {
    SceneDocument doc = testRoom();
    const std::size_t all = std::size_t(doc.render.width) * std::size_t(doc.render.height);
    ASSERT_EQ(all % 2, 0u);
    RenderSession session(2);
    InteractionPolicy p;
    p.interleaved = true;
    PassInfo info;
    ASSERT_TRUE(firstDragStep(session, doc, p, info));
    // One colour of the checkerboard: half the frame (every pixel was stale).
    EXPECT_EQ(info.tracedPixels, all / 2);
    // Still dragging and no further edit: the next pass takes the other half, so soon no
    // pixel is left stale while the user holds the object still.
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (pixelsIn(session, kStale) > 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(2ms);
    EXPECT_EQ(pixelsIn(session, kStale), 0u) << "the second interleaved half was never traced";
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

TEST(InteractionShortcuts, BoxProxy_ShownWhileMoving_NeverKeptInTheRefinedFrame) {
    // Each way of shading shadows while moving: with Full ones the pass would otherwise
    // count as full quality, with Deferred ones its shading records would be resolved
    // instead of the pixels traced again.
    for (const MovingShadows shadows : {MovingShadows::Full, MovingShadows::Deferred}) {
        SCOPED_TRACE(shadows == MovingShadows::Full ? "full shadows" : "deferred shadows");
        SceneDocument doc = testRoom();
        const std::size_t all = std::size_t(doc.render.width) * std::size_t(doc.render.height);
        const ObjectId ball = doc.objects[2].id;
        RenderSession session(2);
        InteractionPolicy p;
        p.boxProxy = true;
        p.shadows = shadows;
        PassInfo info;
        ASSERT_TRUE(firstDragStep(session, doc, p, info));
        // The box covers more pixels than the ball it stands for: the proxy is on screen.
        const RenderResult exact = renderImage(CompiledScene(doc, nullptr, session.engine()));
        std::size_t ballPixels = 0, shownAsBall = 0, refined = 0;
        for (const ObjectId id : exact.ids) ballPixels += id == ball;
        session.withFrame([&](const DeepFrame& f, const auto&) {
            for (std::size_t i = 0; i < f.pixelCount(); ++i) {
                shownAsBall += f.id()[i] == ball;
                refined += f.state()[i] >= kBase;
            }
        });
        ASSERT_GT(ballPixels, 0u);
        EXPECT_GT(shownAsBall, ballPixels);
        // What the proxy pass traced is interaction quality, left for refinement.
        EXPECT_EQ(refined, 0u);
        EXPECT_EQ(pixelsIn(session, kInteractive), all);
        session.endInteraction();
        ASSERT_TRUE(session.waitUntilComplete(60s));
        EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
    }
}

}  // namespace
}  // namespace rs
