// Documents posted to the session: update() returns before the snapshot build, rapid
// updates coalesce, and a failed build is reported while the session keeps its frame.
#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <future>
#include <mutex>
#include <thread>

#include "session_test_support.h"

namespace rs {
namespace {

using namespace std::chrono_literals;
using test::maxDiffToFullRender;
using test::mixedRoom;
using test::testRoom;

/// The session's scene updater with a gate: while closed, every snapshot build (updateScene)
/// waits at the gate, as a slow mesh BVH build would; open() lets them all through.
class GatedUpdater {
public:
    SceneUpdater updater() {
        return [this](const SceneDocument& before, const std::shared_ptr<const CompiledScene>& snap,
                      const SceneDocument& after, EngineKind engine) {
            {
                std::unique_lock lock(mutex_);
                ++entered_;
                cv_.notify_all();
                cv_.wait(lock, [&] { return open_; });
            }
            SceneUpdate u = updateScene(before, snap, after, engine);
            std::lock_guard lock(mutex_);
            ++finished_;
            return u;
        };
    }
    void close() {
        std::lock_guard lock(mutex_);
        open_ = false;
    }
    void open() {
        {
            std::lock_guard lock(mutex_);
            open_ = true;
        }
        cv_.notify_all();
    }
    /// Waits until `n` builds have reached the gate.
    bool waitEntered(int n) {
        std::unique_lock lock(mutex_);
        return cv_.wait_for(lock, 30s, [&] { return entered_ >= n; });
    }
    int finished() {
        std::lock_guard lock(mutex_);
        return finished_;
    }

private:
    std::mutex mutex_;
    std::condition_variable cv_;
    bool open_ = true;
    int entered_ = 0, finished_ = 0;
};

/// update(doc) from another thread; false (and the gate opened, so nothing hangs) when it has
/// not returned within 10 s.
bool updateReturnsPromptly(RenderSession& session, const SceneDocument& doc, GatedUpdater& gate,
                           uint64_t* generation = nullptr) {
    auto call = std::async(std::launch::async, [&] { return session.update(doc); });
    if (call.wait_for(10s) != std::future_status::ready) {
        gate.open();
        return false;
    }
    if (generation) *generation = call.get();
    return true;
}

TEST(RenderSession, UpdateReturnsBeforeTheSnapshotBuildFinishes_AndRapidUpdatesCoalesce) {
    SceneDocument doc = mixedRoom(false);
    GatedUpdater gate;
    RenderSession session(2);
    session.setSceneUpdater(gate.updater());
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    ASSERT_EQ(gate.finished(), 1);

    // An edit (a second mesh object) whose snapshot build cannot finish yet.
    gate.close();
    Object mesh = *doc.findObject(doc.objects.back().id);
    mesh.name = "second mesh";
    mesh.transform.translate += Vec3(-1.6f, 0.2f, -0.5f);
    doc.addObject(mesh);
    uint64_t first = 0;
    ASSERT_TRUE(updateReturnsPromptly(session, doc, gate, &first));
    ASSERT_TRUE(gate.waitEntered(2));
    EXPECT_EQ(gate.finished(), 1);  // update() returned while the build was still held.
    EXPECT_FALSE(session.waitForUpdate(first, 50ms));

    // More edits while that one is applied: each returns at once, and only the last is applied.
    const ObjectId ball = doc.objects[2].id;
    uint64_t last = 0;
    for (int k = 0; k < 5; ++k) {
        doc.findObject(ball)->transform.translate.x += 0.1f;
        ASSERT_TRUE(updateReturnsPromptly(session, doc, gate, &last));
    }
    EXPECT_GT(last, first);
    gate.open();
    ASSERT_TRUE(session.waitForUpdate(last, 30s));
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_EQ(gate.finished(), 3);  // The held build, then the last document only.
    const SessionStats stats = session.stats();
    EXPECT_EQ(stats.postedUpdates, 7u);
    EXPECT_EQ(stats.appliedUpdates, 3u);
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

/// Records the errors the session reports.
class ErrorLog : public SessionObserver {
public:
    void error(const std::string& message) override {
        std::lock_guard lock(mutex_);
        messages_.push_back(message);
    }
    std::vector<std::string> messages() {
        std::lock_guard lock(mutex_);
        return messages_;
    }

private:
    std::mutex mutex_;
    std::vector<std::string> messages_;
};

TEST(RenderSession, AFailedSnapshotBuild_IsReportedToTheObserver_AndTheNextUpdateRenders) {
    SceneDocument doc = testRoom();
    ErrorLog log;
    std::atomic<bool> fail{false};
    RenderSession session(2);
    session.setObserver(&log);
    session.setSceneUpdater([&fail](const SceneDocument& before,
                                    const std::shared_ptr<const CompiledScene>& snap,
                                    const SceneDocument& after, EngineKind engine) {
        if (fail) throw std::runtime_error("mesh 'x.obj': no faces");
        return updateScene(before, snap, after, engine);
    });
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const SceneDocument shown = doc;
    fail = true;
    doc.objects[2].transform.translate.x += 0.3f;
    const uint64_t failed = session.update(doc);
    EXPECT_FALSE(session.waitForUpdate(failed, 30s));
    ASSERT_EQ(log.messages().size(), 1u);
    EXPECT_NE(log.messages()[0].find("mesh 'x.obj': no faces"), std::string::npos);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, shown), 1e-5f);  // The document applied last stays.
    fail = false;
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
    EXPECT_EQ(log.messages().size(), 1u);
}

TEST(RenderSession, WhileMoving_EditsSlowerToApplyThanTheMouseIsFast_StillGetPasses) {
    // Applying each document takes 25 ms (a refit of 100,000 objects) and the mouse posts one
    // every 5 ms: were every pending document applied before any pass, none would run until
    // the mouse stopped.
    SceneDocument doc = testRoom();
    RenderSession session(2);
    session.setSceneUpdater([](const SceneDocument& before,
                               const std::shared_ptr<const CompiledScene>& snap,
                               const SceneDocument& after, EngineKind engine) {
        std::this_thread::sleep_for(25ms);
        return updateScene(before, snap, after, engine);
    });
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const ObjectId ball = doc.objects[2].id;
    session.beginInteraction(ball);
    const uint64_t passesBefore = session.stats().passes;
    for (int k = 0; k < 120; ++k) {
        doc.findObject(ball)->transform.translate.x += 0.002f;
        session.update(doc);
        std::this_thread::sleep_for(5ms);
    }
    const uint64_t passesWhileMoving = session.stats().passes - passesBefore;
    session.endInteraction();
    EXPECT_GE(passesWhileMoving, 4u);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);  // Refined frame == full render.
}

}  // namespace
}  // namespace rs
