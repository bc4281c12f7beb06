// BackgroundArena: its threads run below their own priority inside it, and at their own outside.
#include "core/thread_priority.h"

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

#include "session/render_session.h"
#include "test_scenes.h"

namespace {

struct Seen {
    std::thread::id thread;
    int nice;
};

/// Runs two tasks that each wait for the other to start, so that two threads (the caller and
/// a worker) take part, and returns each one's thread and nice value. No clock: a worker
/// comes once the market gives it one.
std::vector<Seen> twoThreadsNice() {
    std::mutex mutex;
    std::vector<Seen> seen;
    std::atomic<int> started{0};
    tbb::parallel_for(
        tbb::blocked_range<int>(0, 2, 1),
        [&](const tbb::blocked_range<int>&) {
            {
                std::lock_guard lock(mutex);
                seen.push_back({std::this_thread::get_id(), rs::threadNice()});
            }
            started.fetch_add(1);
            while (started.load() < 2) std::this_thread::yield();
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
    rs::BackgroundArena arena(2);
#if defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "ThreadSanitizer builds do not use oneTBB's arenas";
#endif
    ASSERT_EQ(arena.lowers(), rs::canRestorePriority());
    const int inside = arena.lowers() ? own + rs::kBackgroundNiceSteps : own;

    std::vector<Seen> seen;
    int loweredInside = -1;
    arena.execute([&] {
        seen = twoThreadsNice();
        loweredInside = arena.loweredThreads();
    });
    ASSERT_TRUE(twoDistinct(seen));
    for (const Seen& s : seen) EXPECT_EQ(s.nice, inside);
    EXPECT_EQ(loweredInside, arena.lowers() ? 2 : 0);
    EXPECT_EQ(rs::threadNice(), own) << "the caller leaves the arena at its own priority";

    // The worker leaves the arena to serve the default one: it must do so at its own priority
    // (with one worker, as on two cores, it is the very thread that was lowered).
    const std::vector<Seen> outside = twoThreadsNice();
    ASSERT_TRUE(twoDistinct(outside));
    for (const Seen& s : outside) EXPECT_EQ(s.nice, own);
    EXPECT_EQ(arena.loweredThreads(), 0);
}

TEST(BackgroundArena, RestoringIsPossibleExactlyWhenTheProbeSaysSo) {
    // The probe's answer is what a thread of this process finds when it tries.
    bool restored = false, lowered = false;
    std::thread t([&] {
        const int own = rs::threadNice();
        rs::BackgroundArena arena(1);
        arena.execute([&] { lowered = rs::threadNice() > own; });
        restored = rs::threadNice() == own;
    });
    t.join();
#if defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "ThreadSanitizer builds do not use oneTBB's arenas";
#endif
    EXPECT_EQ(lowered, rs::canRestorePriority());
    EXPECT_TRUE(restored);
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
    const int inside = rs::canRestorePriority() ? own + rs::kBackgroundNiceSteps : own;
    ASSERT_FALSE(recorder.seen.empty());
    for (int nice : recorder.seen) EXPECT_EQ(nice, inside);
    EXPECT_EQ(rs::threadNice(), own);
}
