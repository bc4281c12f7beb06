// Growing an edit's marks by a pixel (markDirtyPixels' second step), eight pixels a word,
// against the definition: a pixel is marked when it or one of its 8 neighbours is.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "session/dirty_region.h"

namespace rs {
namespace {

uint8_t grownByDefinition(const std::vector<uint8_t>& core, int w, int h, int x, int y) {
    for (int yy = std::max(0, y - 1); yy <= std::min(h - 1, y + 1); ++yy)
        for (int xx = std::max(0, x - 1); xx <= std::min(w - 1, x + 1); ++xx)
            if (core[std::size_t(yy) * std::size_t(w) + std::size_t(xx)]) return 1;
    return 0;
}

// Sparse random marks, so that most grown pixels owe their mark to one neighbour: a lost
// left or right neighbour byte, a shift the wrong way or a missed row shows. Frame sides that
// are and are not whole blocks (a block cut by the right or bottom edge goes pixel by pixel).
TEST(DirtyGrow, BlockMarks_EachPixelMarkedWhenItOrANeighbourIs) {
    std::mt19937 rng(7);
    for (const auto& [w, h] :
         {std::pair{64, 48}, std::pair{45, 37}, std::pair{9, 8}, std::pair{8, 9}}) {
        for (const int oneIn : {2, 11, 40}) {
            std::vector<uint8_t> core(std::size_t(w) * std::size_t(h));
            for (uint8_t& m : core) m = rng() % unsigned(oneIn) == 0;
            // Pixels outside the block must keep what they had.
            std::vector<uint8_t> out(core.size(), 0xAA);
            std::size_t total = 0, want = 0;
            for (int y0 = 0; y0 < h; y0 += DeepFrame::kBlock)
                for (int x0 = 0; x0 < w; x0 += DeepFrame::kBlock)
                    total += growBlockMarks(core.data(), w, h, x0, y0, out.data());
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const uint8_t d = grownByDefinition(core, w, h, x, y);
                    ASSERT_EQ(out[std::size_t(y) * std::size_t(w) + std::size_t(x)], d)
                        << w << "x" << h << ", one in " << oneIn << ", pixel " << x << "," << y;
                    want += d;
                }
            EXPECT_EQ(total, want);
        }
    }
}

TEST(DirtyGrow, BlockMarks_WriteOnlyTheirBlock) {
    const int w = 24, h = 24;
    std::vector<uint8_t> core(std::size_t(w) * std::size_t(h), 1);
    std::vector<uint8_t> out(core.size(), 0xAA);
    EXPECT_EQ(growBlockMarks(core.data(), w, h, 8, 8, out.data()), 64u);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool inside = x >= 8 && x < 16 && y >= 8 && y < 16;
            EXPECT_EQ(out[std::size_t(y) * std::size_t(w) + std::size_t(x)], inside ? 1 : 0xAA)
                << x << "," << y;
        }
}

}  // namespace
}  // namespace rs
