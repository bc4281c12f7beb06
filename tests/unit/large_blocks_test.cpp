// Frame-sized blocks: aligned to a huge page, advised for huge pages, usable end to end.
#include "core/large_blocks.h"
#include "image/image.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace rs {
namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kMapped = false;  // The sanitizers' own allocators serve every block.
#else
constexpr bool kMapped = true;
#endif

/// Whether the kernel gives transparent huge pages at all (not "[never]", not built without).
bool kernelHasHugePages() {
    std::ifstream enabled("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string mode;
    return std::getline(enabled, mode) && mode.find("[never]") == std::string::npos;
}

/// The VmFlags line of /proc/self/smaps for the mapping that holds `p` ("" if none).
std::string vmFlagsOf(const void* p) {
    std::ifstream smaps("/proc/self/smaps");
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(' ') != std::string::npos &&
            line.find(':') > line.find(' ')) {
            inside = lo <= at && at < hi;
            continue;
        }
        if (inside && line.rfind("VmFlags:", 0) == 0) return line;
    }
    return "";
}

TEST(LargeBlocks, FrameSizedBlockIsHugePageAlignedAndAdvised) {
    if (!kMapped) GTEST_SKIP() << "sanitizer build: plain operator new";
    const std::size_t bytes = 1280 * 720 * sizeof(Color);
    auto* p = static_cast<unsigned char*>(largeAllocate(bytes));
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % kLargeBlockBytes, 0u);
    for (std::size_t i = 0; i < bytes; i += 4096) p[i] = 1;  // All of it is ours to write.
    p[bytes - 1] = 2;
#if defined(__linux__)
    // "hg": the mapping asked for huge pages (MADV_HUGEPAGE), which Debian's THP "madvise"
    // default requires before it gives any.
    if (kernelHasHugePages()) {
        const std::string flags = vmFlagsOf(p);
        EXPECT_NE(flags.find(" hg"), std::string::npos) << "VmFlags: " << flags;
    }
#endif
    largeFree(p);
}

TEST(LargeBlocks, BlocksEitherSideOfTheThresholdAreUsable) {
    LargeBlockAllocator<float> a;
    float* small = a.allocate(16);
    small[15] = 1.0f;
    const std::size_t n = kLargeBlockBytes / sizeof(float);
    float* large = a.allocate(n);
    large[n - 1] = 1.0f;
    if (kMapped) {
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large) % kLargeBlockBytes, 0u);
    }
    a.deallocate(large, n);
    a.deallocate(small, 16);
}

TEST(LargeBlocks, VectorsGrowCopyAndShrinkAcrossTheThreshold) {
    LargeVector<uint32_t> v(100, 7u);
    v.resize(kLargeBlockBytes / sizeof(uint32_t) * 3, 9u);  // small -> large: copied over
    EXPECT_EQ(v[99], 7u);
    EXPECT_EQ(v.back(), 9u);
    LargeVector<uint32_t> copy = v;
    EXPECT_EQ(copy, v);
    v.resize(10);
    v.shrink_to_fit();  // large -> small
    EXPECT_EQ(v.size(), 10u);
    EXPECT_EQ(v[9], 7u);
    // ImageRgb's pixels use the same blocks and stay uninitialised when asked.
    ImageRgb image = ImageRgb::uninitialized(1280, 720);
    image.at(1279, 719) = Color(1.0f);
    EXPECT_EQ(image.pixels.back(), Color(1.0f));
}

TEST(LargeBlocks, ImpossibleSizesThrowBadAlloc) {
    EXPECT_THROW(largeAllocate(SIZE_MAX - 16), std::bad_alloc);
    LargeBlockAllocator<double> a;
    EXPECT_THROW(a.allocate(SIZE_MAX / 4), std::bad_array_new_length);
}

}  // namespace
}  // namespace rs
