// The frame's lock: tiles commit their pixels under shared ownership, edits and readers take
// it whole. A reader that finds it busy may hold off the commits that have not yet begun for
// a bounded moment instead of coming back later: with two tracers committing half-resolution
// tiles back to back (an orbit), a plain try-lock found the frame free about one time in ten.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <shared_mutex>
#include <thread>

namespace rs {

class FrameLock {
public:
    /// A tile's commit. While a reader is waiting its turn it waits too (never longer than
    /// that reader's budget), then shares the frame with the other commits.
    std::shared_lock<std::shared_mutex> commit() {
        while (readersWaiting_.load(std::memory_order_acquire) > 0) std::this_thread::yield();
        return std::shared_lock(mutex_);
    }
    /// The whole frame, waiting as long as it takes (edits: no tile commits then).
    std::unique_lock<std::shared_mutex> exclusive() { return std::unique_lock(mutex_); }
    /// The whole frame for a reader that waits as long as it takes; new commits hold off
    /// meanwhile (a reader-preferring shared mutex would otherwise let them go first).
    std::unique_lock<std::shared_mutex> read() {
        readersWaiting_.fetch_add(1, std::memory_order_acq_rel);
        std::unique_lock lock(mutex_);
        readersWaiting_.fetch_sub(1, std::memory_order_acq_rel);
        return lock;
    }
    /// The whole frame if it can be had within `budget`; while waiting, new commits hold off,
    /// so only the commits already running (or an edit's marking) delay it. Does not own the
    /// lock when the budget ran out.
    std::unique_lock<std::shared_mutex> tryExclusive(std::chrono::microseconds budget) {
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (lock.owns_lock() || budget.count() <= 0) return lock;
        readersWaiting_.fetch_add(1, std::memory_order_acq_rel);
        const auto deadline = std::chrono::steady_clock::now() + budget;
        while (!lock.try_lock() && std::chrono::steady_clock::now() < deadline)
            std::this_thread::yield();
        readersWaiting_.fetch_sub(1, std::memory_order_acq_rel);
        return lock;
    }
    /// Whether a reader is waiting its turn now (commits hold off meanwhile).
    bool readerWaiting() const { return readersWaiting_.load(std::memory_order_acquire) > 0; }

private:
    std::shared_mutex mutex_;
    std::atomic<int> readersWaiting_{0};
};

}  // namespace rs
