// The solid checker's analytic box filter against point parities and brute-force integrals.
#include "texture/checker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace rs {
namespace {

/// POV-Ray's rule as documented, written out independently: floor(c / s + 0.001) per axis,
/// odd sum -> 1.
int oddAt(double x, double y, double z, double scale) {
    const long long i = static_cast<long long>(std::floor(x / scale + 0.001));
    const long long j = static_cast<long long>(std::floor(y / scale + 0.001));
    const long long k = static_cast<long long>(std::floor(z / scale + 0.001));
    return static_cast<int>(((i + j + k) % 2 + 2) % 2);
}

/// The odd fraction of a box by the midpoint rule on n^3 (or n^2, n) sub-samples: slow,
/// independent of the separable closed form.
double bruteForce(const Vec3& p, const Vec3& h, float scale, int n) {
    const int nx = h.x > 0 ? n : 1, ny = h.y > 0 ? n : 1, nz = h.z > 0 ? n : 1;
    long long odd = 0;
    for (int a = 0; a < nx; ++a) {
        const double x = p.x - h.x + 2.0 * h.x * (a + 0.5) / nx;
        for (int b = 0; b < ny; ++b) {
            const double y = p.y - h.y + 2.0 * h.y * (b + 0.5) / ny;
            for (int c = 0; c < nz; ++c) {
                const double z = p.z - h.z + 2.0 * h.z * (c + 0.5) / nz;
                odd += oddAt(x, y, z, scale);
            }
        }
    }
    return double(odd) / (double(nx) * ny * nz);
}

TEST(Checker, PointValuesFollowTheCellParity) {
    const Vec3 zero(0.0f);
    const float points[][3] = {{0.5f, 0.5f, 0.5f},   {1.5f, 0.5f, 0.5f},   {-0.5f, 0.5f, 0.5f},
                               {-0.5f, -0.5f, 0.5f}, {2.5f, -3.5f, 7.25f}, {-4.2f, 1.3f, -0.6f},
                               {10.3f, 20.6f, 30.9f}};
    for (float scale : {1.0f, 0.5f, 2.0f, 3.7f}) {
        for (const auto& q : points) {
            const float expected = float(oddAt(q[0], q[1], q[2], scale));
            EXPECT_EQ(checkerOddFraction(Vec3(q[0], q[1], q[2]), zero, scale), expected)
                << q[0] << " " << q[1] << " " << q[2] << " scale " << scale;
        }
    }
    // The first colour at the origin's cell, the second one cell over on any axis.
    EXPECT_EQ(checkerOddFraction(Vec3(0.2f, 0.2f, 0.2f), zero, 1.0f), 0.0f);
    EXPECT_EQ(checkerOddFraction(Vec3(0.2f, 0.2f, 1.2f), zero, 1.0f), 1.0f);
    EXPECT_EQ(checkerOddFraction(Vec3(0.2f, -0.8f, 0.2f), zero, 1.0f), 1.0f);
}

TEST(Checker, PointsOnACellBoundaryBelongToTheCellAbove) {
    const Vec3 zero(0.0f);
    // The plane y = 0 with its hit points' rounding either side: always cell j = 0.
    for (float y : {0.0f, -0.0f, 1e-7f, -1e-7f, -1e-5f, -5e-4f * 2.0f * 0.45f})
        EXPECT_EQ(checkerOddFraction(Vec3(0.5f, y, 0.5f), zero, 1.0f), 0.0f) << y;
    // At any scale, and on the other axes and at other integers.
    EXPECT_EQ(checkerOddFraction(Vec3(0.25f, -1e-6f, 0.25f), zero, 0.5f), 0.0f);
    EXPECT_EQ(checkerOddFraction(Vec3(1.0f, 0.5f, 0.5f), zero, 1.0f), 1.0f);
    EXPECT_EQ(checkerOddFraction(Vec3(1.0f - 1e-6f, 0.5f, 0.5f), zero, 1.0f), 1.0f);
    EXPECT_EQ(checkerOddFraction(Vec3(0.5f, 0.5f, -1.0f), zero, 1.0f), 1.0f);
    EXPECT_EQ(checkerOddFraction(Vec3(0.5f, 0.5f, -1.0f - 1e-6f), zero, 1.0f), 1.0f);
    // Beyond the tolerance the cell below is taken.
    EXPECT_EQ(checkerOddFraction(Vec3(0.5f, -0.01f, 0.5f), zero, 1.0f), 1.0f);
    EXPECT_EQ(checkerOddFraction(Vec3(0.5f, -0.002f, 0.5f), zero, 1.0f), 1.0f);
}

TEST(Checker, BoxFilterMatchesBruteForceIntegration) {
    struct Case {
        Vec3 p, h;
        float scale;
    };
    const Case cases[] = {
        {Vec3(0.3f, 0.7f, -0.2f), Vec3(0.45f, 0.6f, 0.35f), 1.0f},
        {Vec3(1.1f, -0.4f, 2.3f), Vec3(0.8f, 0.25f, 1.3f), 1.0f},
        {Vec3(0.05f, 0.0f, 0.4f), Vec3(0.3f, 0.0f, 0.2f), 0.5f},  // on the plane y = 0
        {Vec3(-3.3f, 5.2f, 0.9f), Vec3(2.4f, 0.0f, 0.0f), 2.0f},
        {Vec3(0.9f, 0.1f, 0.6f), Vec3(0.15f, 0.05f, 0.12f), 0.25f},
    };
    for (const Case& c : cases) {
        const double expected = bruteForce(c.p, c.h, c.scale, 160);
        const float got = checkerOddFraction(c.p, c.h, c.scale);
        // The midpoint rule is off by at most one sub-sample slab per boundary plane.
        EXPECT_NEAR(got, expected, 0.015) << c.p.x << " " << c.p.y << " " << c.p.z;
    }
}

TEST(Checker, OneAxisFilterIsTheClosedFormTriangleDifference) {
    // Box [0.75, 1.25] in x inside cell (., 0, 0): half odd, half even.
    EXPECT_NEAR(checkerOddFraction(Vec3(1.0f - 0.001f, 0.5f, 0.5f), Vec3(0.25f, 0, 0), 1.0f), 0.5f,
                1e-6f);
    // [0.5, 1.3] (shifted by the tolerance): 0.3 of 0.8 odd.
    EXPECT_NEAR(checkerOddFraction(Vec3(0.9f - 0.001f, 0.5f, 0.5f), Vec3(0.4f, 0, 0), 1.0f),
                0.3f / 0.8f, 1e-5f);
    // [0, 3.25]: odd on [1, 2] and [3, 3.25] -> 1.25 / 3.25.
    EXPECT_NEAR(checkerOddFraction(Vec3(1.625f - 0.001f, 0.5f, 0.5f), Vec3(1.625f, 0, 0), 1.0f),
                1.25f / 3.25f, 1e-5f);
}

TEST(Checker, WideBoxesTendToOneHalf) {
    for (float h : {10.0f, 100.0f, 1000.0f}) {
        // Per axis the square wave's average is at most 1 / (2h) in magnitude.
        const float f1 = checkerOddFraction(Vec3(0.3f, 0.6f, 0.2f), Vec3(h, 0, 0), 1.0f);
        EXPECT_NEAR(f1, 0.5f, 0.5f / (2.0f * h) + 1e-6f) << h;
        const float f3 = checkerOddFraction(Vec3(0.3f, 0.6f, 0.2f), Vec3(h), 1.0f);
        EXPECT_NEAR(f3, 0.5f, 0.5f / (8.0f * h * h * h) + 1e-6f) << h;
    }
    EXPECT_FLOAT_EQ(checkerOddFraction(Vec3(0.3f), Vec3(1e9f), 1.0f), 0.5f);
}

TEST(Checker, IsContinuousAcrossBoundariesWhenFiltered) {
    const float h = 0.1f;
    const float step = 1e-3f;
    float previous = checkerOddFraction(Vec3(0.7f, 0.5f, 0.5f), Vec3(h, 0.05f, 0.0f), 1.0f);
    float low = previous, high = previous;
    for (int i = 1; i <= 600; ++i) {
        const float x = 0.7f + step * i;
        const float f = checkerOddFraction(Vec3(x, 0.5f, 0.5f), Vec3(h, 0.05f, 0.0f), 1.0f);
        // Slope of the box average of a +-1 wave: at most 2 / (2h) per unit, halved.
        EXPECT_LE(std::abs(f - previous), step / (2.0f * h) + 1e-5f) << x;
        previous = f;
        low = std::min(low, f);
        high = std::max(high, f);
    }
    EXPECT_LT(low, 0.01f);  // it did cross from one colour to the other
    EXPECT_GT(high, 0.99f);
}

TEST(Checker, SymmetriesOfThePattern) {
    const Vec3 h(0.3f, 0.2f, 0.45f);
    const Vec3 p(0.37f, -1.41f, 2.62f);
    const float f = checkerOddFraction(p, h, 1.0f);
    ASSERT_GT(f, 0.05f);
    ASSERT_LT(f, 0.95f);
    // Two cells over on any axis: the same; one cell over: the colours swap.
    EXPECT_NEAR(checkerOddFraction(p + Vec3(2, 0, 0), h, 1.0f), f, 1e-5f);
    EXPECT_NEAR(checkerOddFraction(p + Vec3(0, -4, 0), h, 1.0f), f, 1e-5f);
    EXPECT_NEAR(checkerOddFraction(p + Vec3(0, 0, 1), h, 1.0f), 1.0f - f, 1e-5f);
    // Axes are interchangeable.
    EXPECT_NEAR(checkerOddFraction(Vec3(p.y, p.z, p.x), Vec3(h.y, h.z, h.x), 1.0f), f, 1e-5f);
    // Scale: the pattern at scale s is the unit pattern of p / s.
    EXPECT_NEAR(checkerOddFraction(p * 2.5f, h * 2.5f, 2.5f), f, 1e-5f);
    // Mirror about a cell boundary (x -> 2 - x): the colours swap.
    const Vec3 m(2.0f - p.x, p.y, p.z);
    EXPECT_NEAR(checkerOddFraction(m, h, 1.0f), 1.0f - f, 0.002f);
    // Negative half-widths are widths.
    EXPECT_NEAR(checkerOddFraction(p, -h, 1.0f), f, 1e-6f);
}

TEST(Checker, DegenerateScaleIsTheFirstColour) {
    EXPECT_EQ(checkerOddFraction(Vec3(1.5f, 0.5f, 0.5f), Vec3(0.0f), 0.0f), 0.0f);
    EXPECT_EQ(checkerOddFraction(Vec3(1.5f, 0.5f, 0.5f), Vec3(0.0f), -1.0f), 0.0f);
    EXPECT_EQ(checkerOddFraction(Vec3(1.5f, 0.5f, 0.5f), Vec3(0.0f), NAN), 0.0f);
}

TEST(Checker, ManyPointsAtOnce_GiveEachPointTheBitsItGetsAlone) {
    // checkerOddFractions runs four points in the lanes of a vector (AVX2 where the processor
    // has it, whose floor is one instruction); the renderer's shading takes a level's checkered
    // points that way and shadows through glass take them one at a time, so the two must agree
    // bit for bit. Inputs: random cells and widths at every scale, cell boundaries, and the
    // values each branch of the scalar definition tells apart (zero, denormal, tiny and huge
    // widths, huge and non-finite coordinates, bad scales); counts that leave lanes over.
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const float specials[] = {0.0f,   -0.0f, 1e-39f, -1e-39f, 1e-7f,    1e-6f,     0.001f,
                              0.999f, 1.0f,  -1.0f,  0.5f,    -0.999f,  1e6f,      2e6f,
                              3e9f,   -3e9f, 5e15f,  1e30f,   INFINITY, -INFINITY, NAN};
    const auto value = [&](unsigned kind) -> float {
        switch (kind % 5) {
            case 0:
                return specials[rng() % std::size(specials)];
            case 1:
                return unit(rng) * 10.0f;
            case 2:
                return std::ldexp(unit(rng), int(rng() % 100) - 50);
            case 3:
                return float(int(rng() % 21) - 10) * 0.5f + (rng() % 2 ? 0.0f : unit(rng) * 1e-3f);
            default:
                return unit(rng) * 1e4f;
        }
    };
    for (std::size_t count : {1u, 2u, 3u, 4u, 5u, 7u, 9u, 4099u}) {
        std::vector<float> in[7], odd(count, -1.0f);
        for (auto& axis : in) {
            axis.resize(count);
            for (float& v : axis) v = value(unsigned(rng()));
        }
        for (std::size_t i = 0; i < count; i += 3) in[6][i] = std::abs(in[6][i]);  // mostly valid
        checkerOddFractions(count,
                            {in[0].data(), in[1].data(), in[2].data(), in[3].data(), in[4].data(),
                             in[5].data(), in[6].data()},
                            odd.data());
        for (std::size_t i = 0; i < count; ++i) {
            const Vec3 p(in[0][i], in[1][i], in[2][i]), h(in[3][i], in[4][i], in[5][i]);
            const float alone = checkerOddFraction(p, h, in[6][i]);
            ASSERT_EQ(std::memcmp(&alone, &odd[i], sizeof alone), 0)
                << "point " << i << " of " << count << ": (" << p.x << ", " << p.y << ", " << p.z
                << ") +- (" << h.x << ", " << h.y << ", " << h.z << "), scale " << in[6][i]
                << ": alone " << alone << ", with others " << odd[i];
        }
    }
}

}  // namespace
}  // namespace rs
