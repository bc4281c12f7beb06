// Frame-sized allocations faulted in 2 MB at a time (transparent huge pages).
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <vector>

// Whether this is an ASan or TSan build (GCC names them with __SANITIZE_*__, clang before 16
// only through __has_feature): their allocators then serve every block at exactly the size
// asked, so they keep checking bounds, use and races.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define RS_SANITIZED_ALLOCATIONS 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define RS_SANITIZED_ALLOCATIONS 1
#endif

namespace rs {

#if defined(RS_SANITIZED_ALLOCATIONS)
constexpr bool kSanitizedAllocations = true;
#else
constexpr bool kSanitizedAllocations = false;
#endif

/// Blocks of at least this many bytes come from largeAllocate().
constexpr std::size_t kLargeBlockBytes = std::size_t(2) << 20;
/// The largest block largeAllocate() tries for (1 TiB, far beyond any frame): bigger asks throw
/// std::bad_alloc in every build, where the sanitizers' allocators would abort instead.
constexpr std::size_t kLargestBlockBytes = std::size_t(1) << 40;

/// `bytes` of memory aligned to 2 MB, which the kernel is asked to back with transparent huge
/// pages (Debian's default "madvise" mode gives them only to memory that asks). The first
/// write to each 4 KiB page of fresh memory faults, and on a VM a fault can cost 10
/// microseconds: writing a 1280x720 float image (11 MB, 2,700 pages) for the first time took
/// 25-30 ms here, longer than tracing it, against 0.5-3 ms for its six huge pages. The block
/// comes from malloc, so memory freed earlier is reused as malloc reuses it (without faults).
/// Throws std::bad_alloc when no memory is left or `bytes` exceeds kLargestBlockBytes.
/// Sanitizer builds use plain operator new.
void* largeAllocate(std::size_t bytes);
/// Gives back a block largeAllocate() returned.
void largeFree(void* p) noexcept;

/// std::allocator that takes blocks of kLargeBlockBytes and more from largeAllocate().
template <class T>
struct LargeBlockAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = LargeBlockAllocator<U>;
    };
    LargeBlockAllocator() = default;
    template <class U>
    LargeBlockAllocator(const LargeBlockAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) {
        if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        if (n * sizeof(T) < kLargeBlockBytes) return std::allocator<T>::allocate(n);
        return static_cast<T*>(largeAllocate(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept {
        if (n * sizeof(T) < kLargeBlockBytes) return std::allocator<T>::deallocate(p, n);
        largeFree(p);
    }
    template <class U>
    bool operator==(const LargeBlockAllocator<U>&) const noexcept {
        return true;
    }
    template <class U>
    bool operator!=(const LargeBlockAllocator<U>&) const noexcept {
        return false;
    }
};

/// A vector that may grow frame-sized (a per-pixel buffer): a first pass after a resize
/// faults its memory in huge pages, not 4 KiB at a time.
template <class T>
using LargeVector = std::vector<T, LargeBlockAllocator<T>>;

}  // namespace rs
