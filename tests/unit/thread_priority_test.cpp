// BackgroundArena: its threads run below their own priority inside it, and at their own outside.
#include "core/thread_priority.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "session/render_session.h"
#include "test_scenes.h"

namespace {

struct Seen {
    std::thread::id thread;
    int nice;
    int lowered;  ///< The arena's lowered-thread count while both threads are in their tasks.
};

/// The arena's count of lowered threads once it reads `want`, or after 5 s what it reads then.
int settledCount(const rs::BackgroundArena& arena, int want) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    int n = arena.loweredThreads();
    while (n != want && std::chrono::steady_clock::now() < until) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        n = arena.loweredThreads();
    }
    return n;
}

/// Runs two tasks that each wait for the other to start, so that two threads (the caller and
/// a worker) take part, and returns each one's thread and nice value, and `arena`'s count of
/// lowered threads read while both are still in their tasks (a second rendezvous keeps either
/// from leaving before the other has read it: once its task is done a worker may leave the
/// arena at any time). No clock: a worker comes once the market gives it one.
std::vector<Seen> twoThreadsNice(const rs::BackgroundArena* arena = nullptr) {
    std::mutex mutex;
    std::vector<Seen> seen;
    std::atomic<int> started{0}, read{0};
    tbb::parallel_for(
        tbb::blocked_range<int>(0, 2, 1),
        [&](const tbb::blocked_range<int>&) {
            const int nice = rs::threadNice();
            started.fetch_add(1);
            while (started.load() < 2) std::this_thread::yield();
            // oneTBB tells the observer of a worker's arrival and departure on the worker's
            // own schedule, not when its task starts: both threads are counted in the end,
            // so the count is read until it shows them (for at most 5 s).
            const int lowered = arena ? settledCount(*arena, arena->lowers() ? 2 : 0) : -1;
            {
                std::lock_guard lock(mutex);
                seen.push_back({std::this_thread::get_id(), nice, lowered});
            }
            read.fetch_add(1);
            while (read.load() < 2) std::this_thread::yield();
        },
        tbb::simple_partitioner());
    return seen;
}

bool twoDistinct(const std::vector<Seen>& seen) {
    return seen.size() == 2 && seen[0].thread != seen[1].thread;
}

}  // namespace

TEST(BackgroundArena, ThreadsRunLowerInsideAndAtTheirOwnPriorityOutside) {
    if (tbb::info::default_concurrency() < 2) GTEST_SKIP() << "needs a oneTBB worker";
    const int own = rs::threadNice();
    if (own > 19 - rs::kBackgroundNiceSteps) GTEST_SKIP() << "the test runs at nice " << own;
#if defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "ThreadSanitizer builds do not use oneTBB's arenas";
#endif
    if (!rs::canRestorePriority()) GTEST_SKIP() << "priorities cannot be restored here";
    rs::BackgroundArena arena(2);
    ASSERT_EQ(arena.mode(), rs::LowerMode::kWhileInside);
    const int inside = own + rs::kBackgroundNiceSteps;

    std::vector<Seen> seen;
    arena.execute([&] { seen = twoThreadsNice(&arena); });
    ASSERT_TRUE(twoDistinct(seen));
    for (const Seen& s : seen) {
        EXPECT_EQ(s.nice, inside);
        EXPECT_EQ(s.lowered, arena.lowers() ? 2 : 0);
    }
    EXPECT_EQ(rs::threadNice(), own) << "the caller leaves the arena at its own priority";

    // The worker leaves the arena to serve the default one: it must do so at its own priority
    // (with one worker, as on two cores, it is the very thread that was lowered).
    const std::vector<Seen> outside = twoThreadsNice();
    ASSERT_TRUE(twoDistinct(outside));
    for (const Seen& s : outside) EXPECT_EQ(s.nice, own);
    EXPECT_EQ(settledCount(arena, 0), 0);
}

TEST(BackgroundArena, RestoringIsPossibleExactlyWhenTheProbeSaysSo) {
#if defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "ThreadSanitizer builds do not use oneTBB's arenas";
#endif
    // The probe's answer is what a thread of this process finds when it tries (a thread of its
    // own: where restoring fails, it is left lowered).
    bool restored = false, lowered = false;
    std::thread t([&] {
        const int own = rs::threadNice();
        if (own > 19 - rs::kBackgroundNiceSteps) return;
        rs::BackgroundArena arena(1, rs::LowerMode::kWhileInside);
        arena.execute([&] { lowered = rs::threadNice() == own + rs::kBackgroundNiceSteps; });
        restored = rs::threadNice() == own;
    });
    t.join();
    if (!lowered) GTEST_SKIP() << "the test runs at too high a nice value";
    EXPECT_EQ(restored, rs::canRestorePriority());
    EXPECT_EQ(rs::availableLowerMode(),
              restored ? rs::LowerMode::kWhileInside : rs::LowerMode::kForGood);
}

namespace {

/// Notes the nice value of every thread that commits a tile: the session's tracers.
class NiceRecorder : public rs::SessionObserver {
public:
    void tileDone(int, int, int, int, uint64_t) override {
        std::lock_guard lock(mutex);
        seen.push_back(rs::threadNice());
    }
    std::mutex mutex;
    std::vector<int> seen;
};

}  // namespace

TEST(BackgroundArena, TheSessionTracesBelowTheCallersPriority) {
#if defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "ThreadSanitizer builds do not use oneTBB's arenas";
#endif
    const int own = rs::threadNice();
    if (own > 19 - rs::kBackgroundNiceSteps) GTEST_SKIP() << "the test runs at nice " << own;
    NiceRecorder recorder;
    {
        rs::RenderSession session(2);
        session.setObserver(&recorder);
        session.update(rs::test::smallRoom(64, 48));
        ASSERT_TRUE(session.waitUntilComplete(std::chrono::seconds(60)));
        session.setObserver(nullptr);
    }
    // Either way (restored on leaving, or lowered for good) the tracers run below the caller,
    // and the caller, which never enters the session's arena, stays where it was.
    ASSERT_FALSE(recorder.seen.empty());
    for (int nice : recorder.seen) EXPECT_EQ(nice, own + rs::kBackgroundNiceSteps);
    EXPECT_EQ(rs::threadNice(), own);
}

// It lowers this process's oneTBB workers for good, so it runs only where it can put them
// back afterwards (privileged, as CI is); elsewhere the session test above covers the mode.
TEST(BackgroundArena, ForGood_ThreadsStayLoweredAfterLeaving_AndAreNotLoweredTwice) {
#if defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "ThreadSanitizer builds do not use oneTBB's arenas";
#endif
    if (tbb::info::default_concurrency() < 2) GTEST_SKIP() << "needs a oneTBB worker";
    if (!rs::canRestorePriority()) GTEST_SKIP() << "could not put the workers back";
    const int own = rs::threadNice();
    if (own > 19 - rs::kBackgroundNiceSteps) GTEST_SKIP() << "the test runs at nice " << own;
    std::vector<Seen> first, second, outside;
    int callerAfter = -1;
    // The caller is a thread of the arena's own, as the session's scheduler is.
    std::thread caller([&] {
        {
            rs::BackgroundArena arena(2, rs::LowerMode::kForGood);
            arena.execute([&] { first = twoThreadsNice(); });
            arena.execute([&] { second = twoThreadsNice(); });
        }
        callerAfter = rs::threadNice();
        outside = twoThreadsNice();
    });
    caller.join();
    // Put the workers back (each thread that takes part resets itself).
    std::atomic<int> started{0};
    tbb::parallel_for(
        tbb::blocked_range<int>(0, 2, 1),
        [&](const tbb::blocked_range<int>&) {
            setpriority(PRIO_PROCESS, gettid(), own);
            started.fetch_add(1);
            while (started.load() < 2) std::this_thread::yield();
        },
        tbb::simple_partitioner());

    ASSERT_TRUE(twoDistinct(first));
    ASSERT_TRUE(twoDistinct(second));
    const int lowered = own + rs::kBackgroundNiceSteps;
    for (const Seen& s : first) EXPECT_EQ(s.nice, lowered);
    for (const Seen& s : second) EXPECT_EQ(s.nice, lowered) << "entering again lowers no further";
    EXPECT_EQ(callerAfter, lowered);
    ASSERT_TRUE(twoDistinct(outside));
    for (const Seen& s : outside) EXPECT_EQ(s.nice, lowered) << "the workers stay below the GUI";
    EXPECT_EQ(rs::threadNice(), own) << "a thread that never entered is untouched";
}
