// Per-thread scratch memory in huge pages: a bump arena per thread for workspaces that only grow.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

#include "core/large_blocks.h"

namespace rs {

/// Bytes of each thread's arena: two huge pages (a tile's trace workspace and tile buffers
/// take about 1.5 MB of it after doubling growth); only the pages written are faulted.
constexpr std::size_t kScratchArenaBytes = std::size_t(4) << 20;

/// Whether scratch memory comes from arenas at all: not in sanitizer builds, whose own
/// allocators then serve every block, so ASan and TSan keep checking bounds, use and races.
constexpr bool kScratchArenas = !kSanitizedAllocations;

/// `bytes` aligned to `align` (a power of two, at most 64) from the calling thread's arena,
/// or nullptr when the arena is full (or there is none: sanitizer builds, or more threads
/// than arenas). The arena is one huge-page-advised block from largeAllocate(): on a VM the
/// first write to a fresh 4 KiB page costs about 10 microseconds, and the workspaces of a
/// cold render's first tiles wrote some 600 of them.
void* scratchAllocate(std::size_t bytes, std::size_t align) noexcept;
/// Whether `p` lies in any thread's arena. Such blocks are never given back one by one: an
/// arena is reused whole once its thread has ended. Safe from any thread.
bool scratchOwns(const void* p) noexcept;
/// Makes sure the calling thread's arena bookkeeping exists, so that it outlives every
/// thread_local object constructed after this call (those are destroyed first at thread exit).
void scratchTouch() noexcept;
/// Bytes handed out from the calling thread's arena so far (for tests).
std::size_t scratchBytesUsed() noexcept;

/// An allocator for per-thread scratch that only grows (the trace kernel's workspace, a
/// tile's buffers): blocks come from the calling thread's arena, or std::allocator once it
/// is full. Deallocating an arena block does nothing; doubling growth bounds the waste by
/// the final sizes. Meant for thread_local and automatic objects of the thread that
/// allocates: every constructor touches the thread's arena so that thread_local owners are
/// destroyed before it is released. A block freed on another thread is recognised
/// (scratchOwns) and ignored, so that is safe too, but an object holding arena blocks must
/// not outlive the thread that made them (its arena may then be handed to a new thread).
template <class T>
struct ScratchAllocator {
    using value_type = T;
    using is_always_equal = std::true_type;
    using propagate_on_container_move_assignment = std::true_type;

    ScratchAllocator() noexcept { scratchTouch(); }
    ScratchAllocator(const ScratchAllocator&) noexcept { scratchTouch(); }
    template <class U>
    ScratchAllocator(const ScratchAllocator<U>&) noexcept {
        scratchTouch();
    }
    ScratchAllocator& operator=(const ScratchAllocator&) noexcept = default;

    T* allocate(std::size_t n) {
        if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        if constexpr (alignof(T) <= 64)
            if (void* p = scratchAllocate(n * sizeof(T), alignof(T))) return static_cast<T*>(p);
        return std::allocator<T>().allocate(n);
    }
    void deallocate(T* p, std::size_t n) noexcept {
        if (!scratchOwns(p)) std::allocator<T>().deallocate(p, n);
    }
    template <class U>
    bool operator==(const ScratchAllocator<U>&) const noexcept {
        return true;
    }
};

/// A vector of per-thread scratch that only grows (see ScratchAllocator).
template <class T>
using ScratchVector = std::vector<T, ScratchAllocator<T>>;

}  // namespace rs
