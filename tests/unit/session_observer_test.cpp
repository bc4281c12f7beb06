// What the session promises about its observer's calls (named RenderSession* so the
// ThreadSanitizer stage of `setup.sh test` runs them): waitUntilComplete() returns after the
// calls for the completed frame have returned, and setObserver() after any call to the old
// observer, so the caller may destroy it then.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "session/render_session.h"
#include "session_test_support.h"

namespace rs {
namespace {

using namespace std::chrono_literals;

/// Takes its time in passDone and frameComplete, noting when it is inside one and when a
/// frameComplete has returned.
class SlowObserver : public SessionObserver {
public:
    void passDone(const PassInfo&) override { slowCall(); }
    void frameComplete(uint64_t) override {
        slowCall();
        completeReturned = true;
    }
    std::atomic<bool> inCall{false}, completeReturned{false};

private:
    void slowCall() {
        inCall = true;
        std::this_thread::sleep_for(100ms);
        inCall = false;
    }
};

TEST(RenderSessionObserver, WaitUntilComplete_ReturnsAfterTheObserversCallsForTheFrame) {
    SlowObserver observer;
    RenderSession session(2);
    session.setObserver(&observer);
    session.update(test::testRoom());
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_TRUE(observer.completeReturned);
    EXPECT_FALSE(observer.inCall);
    session.setObserver(nullptr);
}

TEST(RenderSessionObserver, SetObserver_WaitsForACallToTheOldOneUnderWay_ThenItMayGo) {
    auto observer = std::make_unique<SlowObserver>();
    RenderSession session(2);
    session.setObserver(observer.get());
    session.update(test::testRoom());
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (!observer->inCall && std::chrono::steady_clock::now() < deadline)
        std::this_thread::yield();
    ASSERT_TRUE(observer->inCall) << "no pass was reported";
    session.setObserver(nullptr);
    EXPECT_FALSE(observer->inCall);
    observer.reset();  // Under ASan, a call still under way would read freed memory.
    // The session goes on without an observer.
    SceneDocument doc = test::testRoom();
    doc.camera.target.x += 1e-3f;
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
}

}  // namespace
}  // namespace rs
