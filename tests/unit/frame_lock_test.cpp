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

/// A commit (A) holds the frame; a reader (B) comes and waits through `takeFrame`; then a
/// commit (C) begins. Returns who got the frame in which order once A lets go (each notes
/// itself while it holds the frame).
std::vector<char> orderOfReaderAndLateCommit(const std::function<FrameHold(FrameLock&)>& takeFrame) {
    FrameLock frame;
    std::mutex logMutex;
    std::vector<char> log;
    const auto note = [&](char who) {
        std::lock_guard lock(logMutex);
        log.push_back(who);
    };
    std::atomic<bool> aHolds{false}, releaseA{false};
    std::thread a([&] {
        auto lock = frame.commit();
        aHolds = true;
        waitFor(releaseA);
    });
    waitFor(aHolds);
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
    releaseA = true;
    a.join();
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
    std::atomic<bool> aHolds{false}, releaseA{false};
    std::thread a([&] {
        auto lock = frame.commit();
        aHolds = true;
        waitFor(releaseA);
    });
    waitFor(aHolds);
    // A never lets go while the reader waits: it must come back without the frame.
    auto reader = frame.tryExclusive(2ms);
    EXPECT_FALSE(reader.owns_lock());
    EXPECT_FALSE(frame.readerWaiting());
    // And commits are not held off any more: one shares the frame with A.
    std::thread d([&] { auto lock = frame.commit(); });
    d.join();
    releaseA = true;
    a.join();
    // Free now: a reader gets it at once, even with no budget.
    EXPECT_TRUE(frame.tryExclusive(0us).owns_lock());
}

}  // namespace
}  // namespace rs
