// filteredLookup over an in-memory pyramid: exact texels through both the whole-level and the
// block path, each fetched once, and footprints elongated along one axis kept sharp across it;
// magnifiedSpots, four sky lookups at once, against filteredLookup of each.
#include "texture/texel_cache.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace rs {
namespace {

/// A pyramid whose level-`l` texel (x, y) is value(l, x, y) (grey), counting fetches.
class FunctionTexels final : public TexelSource {
public:
    FunctionTexels(int w, int h, std::function<float(int, int, int)> value)
        : value_(std::move(value)) {
        for (levels = 0; levels < kMaxMipLevels; ++levels) {
            width[std::size_t(levels)] = w;
            height[std::size_t(levels)] = h;
            if (w == 1 && h == 1) {
                ++levels;
                break;
            }
            w = w > 1 ? w / 2 : 1;
            h = h > 1 ? h / 2 : 1;
        }
    }
    bool fetch(int level, int x0, int x1, int y0, int y1, float* out) const override {
        ++fetches;
        texelsFetched += (x1 - x0) * (y1 - y0);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                for (int c = 0; c < 3; ++c) *out++ = value_(level, x, y) + 0.25f * float(c);
        return true;
    }
    mutable std::atomic<long> fetches{0}, texelsFetched{0};

private:
    std::function<float(int, int, int)> value_;
};

/// A texel value no neighbour shares: exact comparisons tell which texel came back.
float code(int level, int x, int y) {
    return float(level * 1000000 + y * 2048 + x) * 1e-6f;
}

Color at(const TexelSource& source, float s, float t) {
    Color c(-1.0f);
    EXPECT_TRUE(filteredLookup(source, s, t, 0, 0, 0, 0, false, c));
    return c;
}

void expectTexel(const Color& got, float value) {
    EXPECT_FLOAT_EQ(got.x, value);
    EXPECT_FLOAT_EQ(got.y, value + 0.25f);
    EXPECT_FLOAT_EQ(got.z, value + 0.5f);
}

TEST(TexelCache, TexelCentresAreExactInALevelTooLargeToKeepWhole) {
    // 2048 x 1024 is over kMaxResidentTexels: read in blocks.
    FunctionTexels big(2048, 1024, code);
    ASSERT_GT(std::size_t(2048) * 1024, kMaxResidentTexels);
    for (int y : {0, 15, 16, 517, 1023})
        for (int x : {0, 15, 16, 1000, 2047})
            expectTexel(at(big, (float(x) + 0.5f) / 2048.0f, (float(y) + 0.5f) / 1024.0f),
                        code(0, x, y));
    // Blocks, never the whole level; each block once while it stays in the table.
    EXPECT_LE(big.texelsFetched.load(), 25 * 16 * 16);
    const long before = big.fetches.load();
    expectTexel(at(big, 1000.5f / 2048.0f, 517.5f / 1024.0f), code(0, 1000, 517));
    EXPECT_EQ(big.fetches.load(), before);
    // Halfway between the last and the first column wraps: the mean of the two.
    const Color seam = at(big, 0.0f, 0.5f / 1024.0f);
    EXPECT_NEAR(seam.x, 0.5f * (code(0, 2047, 0) + code(0, 0, 0)), 1e-6f);
}

TEST(TexelCache, SmallLevelsAreFetchedWholeOnceAndAgreeWithBlocks) {
    FunctionTexels kept(64, 32, code);
    FunctionTexels blocks(64, 32, code);
    std::vector<Color> whole;
    for (int i = 0; i < 500; ++i) whole.push_back(at(kept, 0.0137f * i, 0.0071f * i));
    EXPECT_EQ(kept.fetches.load(), 1);
    EXPECT_EQ(kept.texelsFetched.load(), 64 * 32);
    setResidentTexelBudget(0);  // `blocks` is asked first now: no room, blocks instead
    for (int i = 0; i < 500; ++i) EXPECT_EQ(at(blocks, 0.0137f * i, 0.0071f * i), whole[i]);
    setResidentTexelBudget(std::size_t(128) << 20);
    EXPECT_GT(blocks.fetches.load(), 1);
    EXPECT_LE(blocks.texelsFetched.load(), 64 * 32);
}

TEST(TexelCache, AFootprintLongAcrossStripesIsSharpAlongThem) {
    // 64 x 64, horizontal stripes 8 rows high: 1, 0, 1, ... A footprint the image's whole
    // width long in s and a texel in t sees only its stripe: the mean along s is 1 there.
    // Filtering over the long axis alone (one isotropic lookup) would give about 0.5.
    FunctionTexels stripes(64, 64, [](int level, int, int y) {
        const int rows = 64 >> level;  // stripes of 8 >> level rows each level down
        const int stripe = rows >= 8 ? (y * 8) / rows : -1;
        return stripe < 0 ? 0.5f : float((stripe + 1) % 2);
    });
    Color c;
    ASSERT_TRUE(
        filteredLookup(stripes, 0.3f, 4.0f / 64.0f, 1.0f, 0.0f, 0.0f, 1.0f / 64.0f, false, c));
    EXPECT_GT(c.x, 0.9f);
    EXPECT_LE(c.x, 1.0f + 1e-6f);
    // The same footprint turned along t averages the stripes.
    ASSERT_TRUE(
        filteredLookup(stripes, 0.3f, 4.0f / 64.0f, 0.0f, 1.0f, 1.0f / 64.0f, 0.0f, false, c));
    EXPECT_NEAR(c.x, 0.5f, 0.1f);
}

bool sameBits(const Color& a, const Color& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(TexelCache, MagnifiedSpotsAreEachSpotsOwnLookupBitForBit) {
    // Four environment spots at once (t clamped, derivatives (ds, 0) and (0, dt)) give what
    // filteredLookup gives each alone, for floats and for 16-bit fractions, over the seam in
    // s and past the first and last rows in t.
    FunctionTexels floats(64, 32, code);
    FunctionTexels fractions(64, 32, [](int level, int x, int y) {
        return float((x * 37 + y * 11 + level * 5) % 64) / 128.0f;
    });
    fractions.unitRange = true;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coordinate(-0.2f, 1.2f), narrow(0.0f, 1.0f / 160.0f);
    const TexelSource* sources[] = {&floats, &fractions};
    for (const TexelSource* source : sources) {
        for (int round = 0; round < 2000; ++round) {
            EnvironmentSpot spots[4];
            for (auto& spot : spots)
                spot = {coordinate(rng), coordinate(rng), narrow(rng), narrow(rng)};
            if (round % 7 == 0) spots[round % 4].s = 1.0f;  // wraps to 0
            Color got[4];
            ASSERT_TRUE(magnifiedSpots(*source, spots, got)) << "round " << round;
            for (int k = 0; k < 4; ++k) {
                Color alone;
                ASSERT_TRUE(filteredLookup(*source, spots[k].s, spots[k].t, spots[k].ds, 0.0f, 0.0f,
                                           spots[k].dt, true, alone));
                ASSERT_TRUE(sameBits(got[k], alone)) << "round " << round << " spot " << k << ": "
                                                     << got[k].x << " alone " << alone.x;
            }
        }
    }
}

TEST(TexelCache, MagnifiedSpotsLeaveOtherLookupsToTheFilter) {
    // One spot wider than half a texel, a coordinate that is not a number, or a level too
    // large to keep whole: false, and nothing written.
    FunctionTexels small(64, 32, code);
    const Color untouched(-7.0f);
    const auto refused = [&](const TexelSource& source, const EnvironmentSpot(&spots)[4]) {
        Color out[4] = {untouched, untouched, untouched, untouched};
        const bool answered = magnifiedSpots(source, spots, out);
        for (const Color& c : out) EXPECT_EQ(c, untouched);
        return !answered;
    };
    const EnvironmentSpot narrow{0.3f, 0.4f, 0.001f, 0.001f};
    EXPECT_TRUE(refused(small, {narrow, narrow, {0.3f, 0.4f, 0.05f, 0.001f}, narrow}));
    EXPECT_TRUE(refused(small, {narrow, {0.3f, 0.4f, 0.001f, 0.05f}, narrow, narrow}));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(refused(small, {narrow, narrow, narrow, {nan, 0.4f, 0.001f, 0.001f}}));
    EXPECT_TRUE(refused(small, {{0.3f, nan, 0.001f, 0.001f}, narrow, narrow, narrow}));
    FunctionTexels big(2048, 1024, code);
    EXPECT_TRUE(refused(big, {narrow, narrow, narrow, {0.3f, 0.4f, 0.0001f, 0.0001f}}));
}

}  // namespace
}  // namespace rs
