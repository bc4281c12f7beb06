// Tone operators, exposure and the sRGB transfer functions against hand-computed values.
#include "image/tonemap.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

namespace rs {

namespace {

void expectColorNear(const Color& actual, const Color& expected, float tol) {
    EXPECT_NEAR(actual.x, expected.x, tol);
    EXPECT_NEAR(actual.y, expected.y, tol);
    EXPECT_NEAR(actual.z, expected.z, tol);
}

/// Written out here rather than using rs::luminance, so the test does not trust the code it checks.
float rec709Luminance(const Color& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

}  // namespace

TEST(ToneMap, Clamp_CutsBelowZeroAndAboveOne) {
    expectColorNear(toneMap(Color(0.5f, -1.0f, 2.0f), ToneMap::Clamp, 0.0f),
                    Color(0.5f, 0.0f, 1.0f), 1e-7f);
}

TEST(ToneMap, Exposure_MultipliesByTwoToThePowerOfStops) {
    expectColorNear(toneMap(Color(0.25f), ToneMap::Clamp, 1.0f), Color(0.5f), 1e-7f);
    expectColorNear(toneMap(Color(1.0f), ToneMap::Clamp, -2.0f), Color(0.25f), 1e-7f);
    // Exposure acts before the operator: Reinhard of 2^1 * 1 is 2/3, not 2 * 1/2.
    expectColorNear(toneMap(Color(1.0f), ToneMap::Reinhard, 1.0f), Color(2.0f / 3.0f), 1e-6f);
}

TEST(ToneMap, Linear_MapsZeroToFourOntoZeroToOne) {
    expectColorNear(toneMap(Color(1.0f, 2.0f, 4.0f), ToneMap::Linear, 0.0f),
                    Color(0.25f, 0.5f, 1.0f), 1e-7f);
    expectColorNear(toneMap(Color(8.0f, -1.0f, 0.0f), ToneMap::Linear, 0.0f),
                    Color(1.0f, 0.0f, 0.0f), 1e-7f);
}

TEST(ToneMap, Reinhard_MapsGreyWithXOverOnePlusX) {
    expectColorNear(toneMap(Color(1.0f), ToneMap::Reinhard, 0.0f), Color(0.5f), 1e-6f);
    expectColorNear(toneMap(Color(3.0f), ToneMap::Reinhard, 0.0f), Color(0.75f), 1e-6f);
    expectColorNear(toneMap(Color(0.0f), ToneMap::Reinhard, 0.0f), Color(0.0f), 0.0f);
}

TEST(ToneMap, Reinhard_PreservesHueAndMapsLuminance) {
    const Color hdr(2.0f, 1.0f, 0.5f);
    const Color d = toneMap(hdr, ToneMap::Reinhard, 0.0f);
    const float lum = rec709Luminance(hdr);
    EXPECT_NEAR(rec709Luminance(d), lum / (1.0f + lum), 1e-6f);
    // Per-channel Reinhard would give 2/3 : 1/2, a ratio of 1.33; the hue-preserving form keeps 2.
    EXPECT_NEAR(d.x / d.y, 2.0f, 1e-5f);
    EXPECT_NEAR(d.y / d.z, 2.0f, 1e-5f);
}

TEST(ToneMap, Aces_MatchesNarkowiczFit) {
    // (x(2.51x + 0.03)) / (x(2.43x + 0.59) + 0.14) at x = 1 and x = 0.18.
    expectColorNear(toneMap(Color(1.0f), ToneMap::Aces, 0.0f), Color(2.54f / 3.16f), 1e-6f);
    const float x = 0.18f;
    const float expected = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    EXPECT_NEAR(toneMap(Color(x), ToneMap::Aces, 0.0f).x, expected, 1e-6f);
    EXPECT_NEAR(expected, 0.2670f, 1e-3f);  // guards the formula itself, not just self-agreement
    EXPECT_EQ(toneMap(Color(0.0f), ToneMap::Aces, 0.0f).x, 0.0f);
    EXPECT_EQ(toneMap(Color(100.0f), ToneMap::Aces, 0.0f).x, 1.0f);
}

TEST(ToneMap, EveryOperator_IsMonotonicAndStaysInUnitRange) {
    for (ToneMap op : {ToneMap::Clamp, ToneMap::Linear, ToneMap::Reinhard, ToneMap::Aces}) {
        float previous = -1.0f;
        for (float x = 0.0f; x < 50.0f; x += 0.05f) {
            const float y = toneMap(Color(x), op, 0.0f).x;
            EXPECT_GE(y, previous) << "operator " << int(op) << " at " << x;
            EXPECT_GE(y, 0.0f);
            EXPECT_LE(y, 1.0f);
            previous = y;
        }
    }
}

TEST(ToneMap, NanAndInfinity_BecomeBlackAndWhite) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (ToneMap op : {ToneMap::Clamp, ToneMap::Linear, ToneMap::Reinhard, ToneMap::Aces}) {
        const Color d = toneMap(Color(nan, inf, 0.0f), op, 0.0f);
        EXPECT_EQ(d.x, 0.0f) << "operator " << int(op);
        EXPECT_FALSE(std::isnan(d.y)) << "operator " << int(op);
        EXPECT_GT(d.y, 0.9f) << "operator " << int(op);
    }
}

TEST(Srgb, Encode_MatchesPiecewiseCurve) {
    EXPECT_EQ(srgbEncode(0.0f), 0.0f);
    EXPECT_NEAR(srgbEncode(1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(srgbEncode(0.002f), 0.002f * 12.92f, 1e-7f);  // linear toe
    EXPECT_NEAR(srgbEncode(0.5f), 0.735357f, 1e-5f);
    EXPECT_NEAR(srgbEncode(0.18f), 0.461356f, 1e-5f);
    // The two pieces meet at the breakpoint.
    EXPECT_NEAR(srgbEncode(0.0031308f), 0.04045f, 1e-5f);
}

TEST(Srgb, Decode_MatchesPiecewiseCurve) {
    EXPECT_EQ(srgbDecode(0.0f), 0.0f);
    EXPECT_NEAR(srgbDecode(1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(srgbDecode(0.5f), 0.214041f, 1e-5f);
    EXPECT_NEAR(srgbDecode(0.04f), 0.04f / 12.92f, 1e-7f);
}

TEST(Srgb, EncodeThenDecode_RoundTrips) {
    for (int i = 0; i <= 1000; ++i) {
        const float x = float(i) / 1000.0f;
        EXPECT_NEAR(srgbDecode(srgbEncode(x)), x, 2e-6f) << x;
        EXPECT_NEAR(srgbEncode(srgbDecode(x)), x, 2e-6f) << x;
    }
}

TEST(ToDisplay8, RoundsToNearest) {
    uint8_t rgb[3];
    // srgbEncode(0.5) * 255 = 187.52: truncation would give 187.
    toDisplay8(Color(0.5f, 0.0f, 1.0f), ToneMap::Clamp, 0.0f, rgb);
    EXPECT_EQ(rgb[0], 188);
    EXPECT_EQ(rgb[1], 0);
    EXPECT_EQ(rgb[2], 255);
    // srgbEncode(0.18) * 255 = 117.65 -> 118; over-range clamps to 255.
    toDisplay8(Color(0.18f, 7.0f, -3.0f), ToneMap::Clamp, 0.0f, rgb);
    EXPECT_EQ(rgb[0], 118);
    EXPECT_EQ(rgb[1], 255);
    EXPECT_EQ(rgb[2], 0);
}

TEST(ToDisplay8, AppliesOperatorAndExposure) {
    uint8_t rgb[3];
    // Reinhard(1) = 0.5 -> 188, same as clamp of 0.5; with -1 stop clamp of 1 is also 0.5.
    toDisplay8(Color(1.0f), ToneMap::Reinhard, 0.0f, rgb);
    EXPECT_EQ(rgb[0], 188);
    toDisplay8(Color(1.0f), ToneMap::Clamp, -1.0f, rgb);
    EXPECT_EQ(rgb[1], 188);
}

/// The 8-bit code written out from the formulas, as toDisplay8's table must reproduce it.
static uint8_t formulaCode(float linear) {
    return uint8_t(std::lround(srgbEncode(linear) * 255.0f));
}

TEST(ToDisplay8, TableStepsAtExactlyTheFormulasSteps) {
    // Every 97th float in [0, 1], and both sides of each place the code changes (bisected
    // to the ulp): the table must give the formula's code everywhere, not just nearby.
    const uint32_t one = std::bit_cast<uint32_t>(1.0f);
    uint8_t rgb[3];
    auto check = [&](uint32_t bits) {
        const float v = std::bit_cast<float>(bits);
        toDisplay8(Color(v), ToneMap::Clamp, 0.0f, rgb);
        return rgb[0] == formulaCode(v) && rgb[1] == rgb[0] && rgb[2] == rgb[0];
    };
    int mismatches = 0, steps = 0;
    uint32_t previous = 0;
    for (uint32_t bits = 0; bits <= one; bits = bits + 97 > one && bits != one ? one : bits + 97) {
        mismatches += !check(bits);
        if (bits > 0 && formulaCode(std::bit_cast<float>(previous)) !=
                            formulaCode(std::bit_cast<float>(bits))) {
            uint32_t lo = previous, hi = bits;  // code(lo) < code(hi): find the first step.
            while (hi - lo > 1) {
                const uint32_t mid = lo + (hi - lo) / 2;
                (formulaCode(std::bit_cast<float>(mid)) ==
                         formulaCode(std::bit_cast<float>(previous))
                     ? lo
                     : hi) = mid;
            }
            mismatches += !check(lo) + !check(hi);
            ++steps;
        }
        previous = bits;
        if (bits == one) break;
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_EQ(steps, 255);
    // The row form gives the same bytes, with exposure and an operator.
    const Color row[3] = {Color(0.3f, 2.0f, 0.01f), Color(0.0f), Color(7.0f, 0.5f, 1e-4f)};
    uint8_t out[9];
    toDisplay8(row, 3, ToneMap::Aces, 0.7f, out);
    for (int i = 0; i < 3; ++i) {
        const Color d = toneMap(row[i], ToneMap::Aces, 0.7f);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(out[3 * i + c], formulaCode(d[c])) << i << c;
    }
}

TEST(ToDisplay8, RepeatedPixelsOfARow_GetTheBytesOfEachPixelMappedAlone) {
    // An undersampled frame repeats values along a row; the row form reuses a neighbour's
    // bytes only where the colour has the same bits: runs, values one ulp apart, -0 beside
    // 0, a NaN beside a number, each must give what the pixel gives alone.
    const float ulpBelow = std::nextafter(0.5f, 0.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Color row[] = {Color(0.5f),
                         Color(0.5f),
                         Color(0.5f),
                         Color(ulpBelow),
                         Color(ulpBelow),
                         Color(0.0f),
                         Color(-0.0f),
                         Color(nan, 0.2f, 0.2f),
                         Color(0.0f, 0.2f, 0.2f),
                         Color(3.0f, 0.1f, 0.0f),
                         Color(3.0f, 0.1f, 0.0f),
                         Color(0.2f)};
    constexpr std::size_t n = sizeof(row) / sizeof(row[0]);
    for (ToneMap op : {ToneMap::Clamp, ToneMap::Linear, ToneMap::Reinhard, ToneMap::Aces}) {
        uint8_t out[3 * n];
        toDisplay8(row, n, op, 0.3f, out);
        for (std::size_t i = 0; i < n; ++i) {
            uint8_t alone[3];
            toDisplay8(&row[i], 1, op, 0.3f, alone);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(out[3 * i + c], alone[c]) << i << " " << c;
        }
    }
}

}  // namespace rs
