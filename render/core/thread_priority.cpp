// BackgroundArena: lower a thread's nice value on entering the arena, restore it on leaving.
#include "core/thread_priority.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <thread>

#if defined(__linux__)
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace rs {

namespace {

#if defined(__linux__)
/// Linux's setpriority(PRIO_PROCESS, tid) sets one thread's nice value (not POSIX's per process).
bool setThreadNice(int nice) {
    return setpriority(PRIO_PROCESS, gettid(), nice) == 0;
}
#else
bool setThreadNice(int) {
    return false;
}
#endif

/// The thread's own priority while it is in a BackgroundArena at a lowered one. A thread is
/// lowered once however many such arenas it is in, and restored when it leaves one of them.
/// `by` names the observer that lowered it: one whose arena went away while the thread was in
/// it sent no exit, and the next BackgroundArena the thread leaves restores it.
struct Saved {
    bool lowered = false;
    int nice = 0;
    uint64_t by = 0;
};
thread_local Saved saved;

/// Where kForGood arenas put their threads: below the priority of the thread that made the
/// first BackgroundArena (the GUI thread, in the designer), however lowered a later maker is.
int forGoodNice() {
    static const int nice = std::min(19, threadNice() + kBackgroundNiceSteps);
    return nice;
}

std::atomic<uint64_t> nextObserverId{1};

}  // namespace

int threadNice() {
#if defined(__linux__)
    errno = 0;
    const int nice = getpriority(PRIO_PROCESS, gettid());
    return errno == 0 ? nice : 0;
#else
    return 0;
#endif
}

bool canRestorePriority() {
    static const bool can = [] {
        bool ok = false;
        // A thread of its own, so that a failed restore leaves no thread that matters lowered.
        std::thread probe([&ok] {
            const int own = threadNice();
            if (own >= 19 || !setThreadNice(own + 1)) return;
            ok = setThreadNice(own) && threadNice() == own;
        });
        probe.join();
        return ok;
    }();
    return can;
}

LowerMode availableLowerMode() {
#if defined(__SANITIZE_THREAD__)
    // Under ThreadSanitizer arenaExecute runs on std::threads (core/parallel.h): no thread
    // ever joins, and observing would initialise oneTBB's arena for nothing.
    return LowerMode::kNone;
#else
    return canRestorePriority() ? LowerMode::kWhileInside : LowerMode::kForGood;
#endif
}

BackgroundArena::BackgroundArena(int threads, LowerMode mode)
    : tbb::task_arena(threads), lowering_(*this) {
    lowering_.ownNice = threadNice();
    lowering_.mode = mode;
    lowering_.forGoodNice = forGoodNice();
    if (lowers()) lowering_.observe(true);
}

BackgroundArena::~BackgroundArena() {
    // Workers still inside keep the lowered priority until they next leave a BackgroundArena
    // (oneTBB sends no exit notification once the observer stops observing).
    if (lowers()) lowering_.observe(false);
}

BackgroundArena::Lowering::Lowering(tbb::task_arena& arena)
    : tbb::task_scheduler_observer(arena), id(nextObserverId.fetch_add(1)) {}

void BackgroundArena::Lowering::on_scheduler_entry(bool isWorker) {
    if (mode == LowerMode::kForGood) {
        // Idempotent: a thread already there (or lower) is left alone.
        if (threadNice() < forGoodNice) setThreadNice(forGoodNice);
        if (threadNice() >= forGoodNice) lowered.fetch_add(1);
        return;
    }
    if (saved.lowered) return;
    // A thread inherits its creator's nice value, and oneTBB starts a worker from the thread
    // that asked for one: a lowered one, when this arena's work did. So a worker's own
    // priority is the one of the thread that made the arena, not the one it was born with.
    const int own = isWorker ? ownNice : threadNice();
    if (!setThreadNice(std::min(19, own + kBackgroundNiceSteps))) return;
    saved = {true, own, id};
    lowered.fetch_add(1);
}

void BackgroundArena::Lowering::on_scheduler_exit(bool) {
    if (mode == LowerMode::kForGood) {
        if (threadNice() >= forGoodNice) lowered.fetch_sub(1);  // ... and stays lowered.
        return;
    }
    if (!saved.lowered) return;
    setThreadNice(saved.nice);  // Cannot fail where canRestorePriority() held.
    saved.lowered = false;
    if (saved.by == id) lowered.fetch_sub(1);
}

}  // namespace rs
