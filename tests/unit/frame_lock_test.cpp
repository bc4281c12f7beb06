// FrameLock: a reader waiting its turn (blocking, or within a budget) goes before the tile
// commits that had not begun, and one whose budget runs out gives up with commits resuming.
#include "session/frame_lock.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rs {
namespace {

using namespace std::chrono_literals;

void waitFor(const std::atomic<bool>& flag) {
    while (!flag.load()) std::this_thread::yield();
}

using FrameHold = std::unique_lock<std::shared_mutex>;

/// A commit already running: a thread that holds the frame shared until release().
class RunningCommit {
public:
    explicit RunningCommit(FrameLock& frame)
        : thread_([this, &frame] {
              auto lock = frame.commit();
              holds_ = true;
              waitFor(release_);
          }) {
        waitFor(holds_);
    }
    ~RunningCommit() { release(); }
    void release() {
        release_ = true;
        if (thread_.joinable()) thread_.join();
    }

private:
    std::atomic<bool> holds_{false}, release_{false};
    std::thread thread_;
};

/// A commit (A) holds the frame; a reader (B) comes and waits through `takeFrame`; then a
/// commit (C) begins. Returns who got the frame in which order once A lets go (each notes
/// itself while it holds the frame).
std::vector<char> orderOfReaderAndLateCommit(
    const std::function<FrameHold(FrameLock&)>& takeFrame) {
    FrameLock frame;
    std::mutex logMutex;
    std::vector<char> log;
    const auto note = [&](char who) {
        std::lock_guard lock(logMutex);
        log.push_back(who);
    };
    RunningCommit a(frame);
    std::thread b([&] {
        const FrameHold hold = takeFrame(frame);
        if (hold.owns_lock()) note('B');
    });
    while (!frame.readerWaiting()) std::this_thread::yield();
    std::thread c([&] {
        auto lock = frame.commit();
        note('C');
    });
    // Without the hold-off C would share the frame with A at once and go first; the pause
    // gives it that chance (the right order does not depend on it).
    std::this_thread::sleep_for(20ms);
    a.release();
    b.join();
    c.join();
    EXPECT_FALSE(frame.readerWaiting());
    return log;
}

TEST(FrameLock, AReaderWithABudgetGoesBeforeCommitsThatHadNotBegun) {
    const auto log = orderOfReaderAndLateCommit(
        [](FrameLock& f) { return f.tryExclusive(std::chrono::hours(1)); });
    EXPECT_EQ(log, (std::vector<char>{'B', 'C'}));
}

TEST(FrameLock, ABlockingReaderGoesBeforeCommitsThatHadNotBegun) {
    const auto log = orderOfReaderAndLateCommit([](FrameLock& f) { return f.read(); });
    EXPECT_EQ(log, (std::vector<char>{'B', 'C'}));
}

TEST(FrameLock, AReaderWhoseBudgetRunsOutGivesUp_AndCommitsGoOn) {
    FrameLock frame;
    RunningCommit a(frame);
    // A never lets go while the reader waits: it must come back without the frame.
    auto reader = frame.tryExclusive(2ms);
    EXPECT_FALSE(reader.owns_lock());
    EXPECT_FALSE(frame.readerWaiting());
    // And commits are not held off any more: one shares the frame with A.
    std::thread d([&] { auto lock = frame.commit(); });
    d.join();
    a.release();
    // Free now: a reader gets it at once, even with no budget.
    EXPECT_TRUE(frame.tryExclusive(0us).owns_lock());
}

}  // namespace
}  // namespace rs
