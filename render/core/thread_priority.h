// Tracing threads that give way to the GUI: an arena whose threads run at a lower priority.
//
// On a machine with few cores the interactive session's tracers, the designer's GUI thread
// and the display server share the CPU; at equal priority a 7 ms paint becomes a 30 ms block
// whenever the scheduler runs a tracer instead. Desktop tools run their render threads below
// the GUI; here that is per thread (Linux's nice is per thread) and only while a thread works
// in the session's arena, so oneTBB workers that go on to serve another arena (a Render Image
// job, the command line's renders) do so at the priority they had.
#pragma once

#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include <atomic>
#include <cstdint>

namespace rs {

/// How many nice steps below its own priority a thread runs inside a BackgroundArena (of 1024
/// CPU shares a nice-0 thread has, a nice-10 one has 110: the GUI gets nine tenths of a core
/// it shares with a tracer, and the tracers all of the idle time).
inline constexpr int kBackgroundNiceSteps = 10;

/// The calling thread's nice value (0 where the platform has none).
int threadNice();

/// Whether a thread of this process may go back to its priority after lowering it: Linux lets
/// a thread lower its nice value only with CAP_SYS_NICE or a large enough RLIMIT_NICE, which
/// a desktop user's process usually lacks. Found once, by trying it on a thread of its own.
bool canRestorePriority();

/// How a BackgroundArena lowers the threads that work in it.
enum class LowerMode {
    kWhileInside,  ///< Lowered on entry, back at their own priority when they leave.
    /// Lowered on their first entry and left there: where priorities cannot be restored (a
    /// desktop user's process), the workers that trace for the session stay below the GUI
    /// thread, and so do the later arenas they serve in this process (Render Image, mesh
    /// builds: background work too). Only for an arena whose calling thread is one of its
    /// own (the session's scheduler), never the GUI thread.
    kForGood,
    kNone,  ///< A plain task_arena.
};

/// kWhileInside where canRestorePriority(), else kForGood; kNone under ThreadSanitizer, whose
/// builds run arena work on std::threads (core/parallel.h).
LowerMode availableLowerMode();

/// A task_arena whose threads, the one that calls execute and the workers that join, run
/// kBackgroundNiceSteps below their own priority while they are in it (for workers, the
/// priority of the thread that made the arena, see on_scheduler_entry) and, in
/// kWhileInside mode, at their own again when they leave.
class BackgroundArena : public tbb::task_arena {
public:
    explicit BackgroundArena(int threads, LowerMode mode = availableLowerMode());
    ~BackgroundArena();
    BackgroundArena(const BackgroundArena&) = delete;
    BackgroundArena& operator=(const BackgroundArena&) = delete;

    /// Whether this arena lowers its threads, and how.
    bool lowers() const { return lowering_.mode != LowerMode::kNone; }
    LowerMode mode() const { return lowering_.mode; }
    /// Threads inside it now at the lowered priority.
    int loweredThreads() const { return lowering_.lowered.load(); }

private:
    struct Lowering : tbb::task_scheduler_observer {
        explicit Lowering(tbb::task_arena& arena);
        void on_scheduler_entry(bool isWorker) override;
        void on_scheduler_exit(bool isWorker) override;
        const uint64_t id;
        LowerMode mode = LowerMode::kNone;
        int ownNice = 0;  ///< The workers' own priority: that of the thread that made the arena.
        int forGoodNice = 0;  ///< Where kForGood puts its threads.
        std::atomic<int> lowered{0};
    };
    Lowering lowering_;
};

}  // namespace rs
