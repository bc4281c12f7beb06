// Fork-join helpers: oneTBB in normal builds, plain std::threads under ThreadSanitizer.
//
// Debian's libtbb is not built with TSan, so TSan cannot see the synchronisation inside it and
// reports TBB's own task hand-offs as races (and suppressing those by frame would also hide
// races in our task bodies, which run under TBB frames). Under TSan the same bodies therefore
// run on std::threads that TSan fully understands; everything the bodies touch (the session,
// the frame, commits and locks) is the same code in both builds.
#pragma once

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace rs {

#if defined(__SANITIZE_THREAD__)

namespace detail {
/// Runs `work(k)` for k in [0, count) on a few threads, each taking the next k. The first
/// exception stops the others and is rethrown here, as oneTBB does (a std::thread that lets
/// one escape would terminate the process).
template <class Work>
void forkJoin(std::size_t count, const Work& work) {
    std::atomic<std::size_t> next{0};
    std::mutex failedMutex;
    std::exception_ptr failed;
    auto worker = [&] {
        try {
            for (std::size_t k; (k = next.fetch_add(1)) < count;) work(k);
        } catch (...) {
            next.store(count);
            std::lock_guard lock(failedMutex);
            if (!failed) failed = std::current_exception();
        }
    };
    const unsigned n = std::max(2u, std::min(4u, std::thread::hardware_concurrency()));
    std::vector<std::thread> threads;
    for (unsigned t = 1; t < n; ++t) threads.emplace_back(worker);
    worker();
    for (std::thread& t : threads) t.join();
    if (failed) std::rethrow_exception(failed);
}
}  // namespace detail

/// parallel_for over a TBB range: split into pieces, run them on std::threads.
template <class Range, class Body, class... Extra>
void parallelFor(const Range& range, const Body& body, Extra&&...) {
    std::vector<Range> pieces{range};
    for (std::size_t i = 0; i < pieces.size() && pieces.size() < 64;) {
        if (pieces[i].is_divisible())
            pieces.push_back(Range(pieces[i], tbb::split()));
        else
            ++i;
    }
    detail::forkJoin(pieces.size(), [&](std::size_t k) { body(pieces[k]); });
}

/// parallel_for over the integers [first, last).
template <class Body>
void parallelForIndex(int first, int last, const Body& body) {
    if (last > first)
        detail::forkJoin(std::size_t(last - first), [&](std::size_t k) { body(first + int(k)); });
}

/// Runs `f` (which starts parallel loops) and waits for it.
template <class F>
void arenaExecute(tbb::task_arena&, const F& f) {
    f();
}

#else

/// tbb::parallel_for over a range type, with the same arguments after the body.
template <class Range, class Body, class... Extra>
void parallelFor(const Range& range, const Body& body, Extra&&... extra) {
    tbb::parallel_for(range, body, std::forward<Extra>(extra)...);
}

/// tbb::parallel_for over the integers [first, last).
template <class Body>
void parallelForIndex(int first, int last, const Body& body) {
    tbb::parallel_for(first, last, body);
}

/// Runs `f` inside `arena`, whose threads the loops in `f` use, and waits for it.
template <class F>
void arenaExecute(tbb::task_arena& arena, const F& f) {
    arena.execute(f);
}

#endif

}  // namespace rs
