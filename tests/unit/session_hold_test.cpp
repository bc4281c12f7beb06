// Edits posted while a governed interactive pass runs: a pass predicted within its budget
// finishes and the edits wait (the latest wins); one that is not is cut. Either way the
// refined frame equals a full render. The edit is posted from inside the pass (its first
// tile's callback), so no test here depends on how fast the machine is.
#include "session_test_support.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <vector>

namespace rs {
namespace {

using namespace std::chrono_literals;
using test::maxDiffToFullRender;

/// Posts `next` to the session from the first tile committed by an interactive pass of
/// `during` (a worker thread, while that pass runs), and records every pass.
class EditDuringPass : public SessionObserver {
public:
    RenderSession* session = nullptr;
    std::atomic<uint64_t> during{0};
    SceneDocument next;
    std::atomic<uint64_t> postedAs{0};

    void tileDone(int, int, int, int, uint64_t generation) override {
        if (generation != during.load() || posted_.exchange(true)) return;
        postedAs = session->update(next);
    }
    void passDone(const PassInfo& info) override {
        std::lock_guard lock(mutex_);
        passes_.push_back(info);
    }
    /// The interactive pass of `generation` (kind Base when there was none).
    PassInfo interactivePass(uint64_t generation) {
        std::lock_guard lock(mutex_);
        for (const PassInfo& p : passes_)
            if (p.generation == generation && p.kind == PassKind::Interactive) return p;
        return {};
    }

private:
    std::atomic<bool> posted_{false};
    std::mutex mutex_;
    std::vector<PassInfo> passes_;
};

/// Orbits the camera of a room that spans several tiles under a governor aiming at
/// `targetMs`, posting a second orbit step from inside the first step's pass.
struct OrbitTwoSteps {
    SceneDocument step1, step2;
    uint64_t generation1 = 0;
    PassInfo pass1, pass2;
    SessionStats stats;
    float diff = 1.0f;

    explicit OrbitTwoSteps(double targetMs) {
        SceneDocument doc = test::smallRoom(160, 120);  // 5 x 4 tiles.
        RenderSession session(2);
        EditDuringPass observer;
        observer.session = &session;
        session.setObserver(&observer);
        InteractionPolicy policy;  // Deferred shadows under the governor.
        policy.governorTargetMs = targetMs;
        session.setPolicy(policy);
        session.update(doc);
        EXPECT_TRUE(session.waitUntilComplete(60s));

        step1 = doc;
        step1.camera.position.x += 0.3f;  // An orbit step: every pixel changes.
        step2 = step1;
        step2.camera.position.x += 0.3f;
        observer.next = step2;
        session.beginInteraction(kNoObject);
        // Set before the update: its pass's first tile posts step2.
        observer.during = session.generation() + 1;
        generation1 = session.update(step1);
        EXPECT_EQ(generation1, observer.during.load());
        // The second step's interactive pass before the release: its level is checked.
        EXPECT_TRUE(session.waitForPass(generation1 + 1, 60s));
        session.endInteraction();
        EXPECT_TRUE(session.waitUntilComplete(60s));
        session.setObserver(nullptr);
        EXPECT_EQ(observer.postedAs.load(), generation1 + 1);
        pass1 = observer.interactivePass(generation1);
        pass2 = observer.interactivePass(generation1 + 1);
        stats = session.stats();
        diff = maxDiffToFullRender(session, step2);
    }
};

TEST(SessionHold, AnEditDuringAPassWithinBudget_WaitsForIt_AndTheFrameEqualsAFullRender) {
    // A generous target: every pass is predicted within its budget.
    const OrbitTwoSteps run(1e6);
    EXPECT_EQ(run.pass1.kind, PassKind::Interactive);
    EXPECT_FALSE(run.pass1.cancelled);  // It finished: the whole frame at step 1.
    EXPECT_EQ(run.pass1.tracedPixels, run.pass1.totalPixels);
    EXPECT_EQ(run.stats.heldUpdates, 1u);
    EXPECT_LE(run.diff, 1e-5f);
}

TEST(SessionHold, AnEditDuringAPassOverBudget_CutsIt_AndTheFrameEqualsAFullRender) {
    // No level meets a microsecond: the governor takes the cheapest and expects to miss.
    const OrbitTwoSteps run(1e-3);
    EXPECT_EQ(run.pass1.kind, PassKind::Interactive);
    EXPECT_TRUE(run.pass1.cancelled);
    EXPECT_EQ(run.stats.heldUpdates, 0u);
    EXPECT_LE(run.diff, 1e-5f);
}

TEST(SessionHold, WithoutTheGovernor_AnEditCutsThePass) {
    const OrbitTwoSteps run(0.0);
    EXPECT_TRUE(run.pass1.cancelled);
    EXPECT_EQ(run.stats.heldUpdates, 0u);
    EXPECT_LE(run.diff, 1e-5f);
}

}  // namespace
}  // namespace rs
