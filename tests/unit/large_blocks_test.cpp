// Frame-sized blocks: aligned to a huge page, advised for huge pages, usable end to end.
#include "core/large_blocks.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "image/image.h"
#include "vm_flags.h"

namespace rs {
namespace {

constexpr bool kMapped = !kSanitizedAllocations;  // Else plain operator new serves every block.

using test::kernelHasHugePages;
using test::vmFlagsOf;

TEST(LargeBlocks, FrameSizedBlockIsHugePageAlignedAndAdvised) {
    if (!kMapped) GTEST_SKIP() << "sanitizer build: plain operator new";
    const std::size_t bytes = 1280 * 720 * sizeof(Color);
    auto* p = static_cast<unsigned char*>(largeAllocate(bytes));
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % kLargeBlockBytes, 0u);
    for (std::size_t i = 0; i < bytes; i += 4096) p[i] = 1;  // All of it is ours to write.
    p[bytes - 1] = 2;
#if defined(__linux__)
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
