// largeAllocate: a malloc block with a 2 MB-aligned inside, marked MADV_HUGEPAGE.
#include "core/large_blocks.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rs {

#if defined(RS_SANITIZED_ALLOCATIONS)

void* largeAllocate(std::size_t bytes) {
    if (bytes > kLargestBlockBytes) throw std::bad_alloc();
    return ::operator new(bytes);
}

void largeFree(void* p) noexcept {
    ::operator delete(p);
}

#else

namespace {
/// The malloc block's own address is kept just below the aligned pointer handed out.
constexpr std::size_t kHeader = sizeof(void*);
}  // namespace

void* largeAllocate(std::size_t bytes) {
    if (bytes > kLargestBlockBytes) throw std::bad_alloc();
    // Whole huge pages: a range that ends inside one gets 4 KiB pages there (a 1280x720
    // image's last 0.27 of a huge page was 135 faults, a millisecond of a cold render).
    const std::size_t span = (bytes + kLargeBlockBytes - 1) & ~(kLargeBlockBytes - 1);
    // Not aligned_alloc: glibc maps and unmaps a block of that alignment every time, so each
    // new frame would fault again; a plain malloc block is reused as malloc reuses any.
    void* block = std::malloc(span + kLargeBlockBytes + kHeader);
    if (!block) throw std::bad_alloc();
    const auto raw = reinterpret_cast<std::uintptr_t>(block) + kHeader;
    const std::uintptr_t aligned = (raw + kLargeBlockBytes - 1) & ~(kLargeBlockBytes - 1);
    void* p = reinterpret_cast<void*>(aligned);
    static_cast<void**>(p)[-1] = block;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: where huge pages are off, or the call fails, the block has small pages.
    madvise(p, span, MADV_HUGEPAGE);
#endif
    return p;
}

void largeFree(void* p) noexcept {
    if (p) std::free(static_cast<void**>(p)[-1]);
}

#endif

}  // namespace rs
