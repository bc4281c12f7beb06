// The arena the session's tiles are traced on, sized by the thread count the UI asks for.
#pragma once

#include <memory>

#include "core/thread_priority.h"

namespace rs {

/// Guarded by the session's mutex; the arena is used by the scheduler thread alone.
class TileArena {
public:
    /// `threads` = 0: all cores.
    explicit TileArena(int threads)
        : threads_(threads), arena_(std::make_unique<BackgroundArena>(size(threads))) {}

    /// Takes effect at the next refresh() (between passes).
    void setThreads(int threads) {
        if (threads == threads_) return;
        threads_ = threads;
        changed_ = true;
    }
    /// Makes the arena anew when setThreads changed the count. Not while a pass runs.
    void refresh() {
        if (!changed_) return;
        arena_ = std::make_unique<BackgroundArena>(size(threads_));
        changed_ = false;
    }
    /// Its tracers run below the GUI thread.
    BackgroundArena& arena() { return *arena_; }

private:
    /// The arena's size for a thread count (0: the machine's).
    static int size(int threads);

    int threads_ = 0;
    bool changed_ = false;
    std::unique_ptr<BackgroundArena> arena_;
};

}  // namespace rs
