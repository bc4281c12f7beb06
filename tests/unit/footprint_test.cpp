// A ray cone's footprint on a surface, for one ray and for a lane of rays, and the checker
// batch that runs a level's checkered points' footprints and box filters in lanes.
#include "snapshot/footprint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "snapshot/surface_patterns.h"

namespace rs {
namespace {

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(Footprint, SlantedRay_StretchesAlongItsProjectionByOneOverTheCosine) {
    // A cone 0.2 wide meets the floor (normal +Y) at 60 degrees from the normal.
    const float angle = 60.0f * kPi / 180.0f;
    const Vec3 dir(std::sin(angle), -std::cos(angle), 0.0f), n(0.0f, 1.0f, 0.0f);
    const Footprint f = footprintAt(dir, n, 0.2f);
    EXPECT_NEAR(glm::length(f.a1), 0.1f / std::cos(angle), 1e-6f);
    EXPECT_NEAR(glm::length(f.a2), 0.1f, 1e-6f);
    EXPECT_NEAR(glm::dot(f.a1, n), 0.0f, 1e-7f);  // both in the surface
    EXPECT_NEAR(glm::dot(f.a2, n), 0.0f, 1e-7f);
    EXPECT_GT(f.a1.x, 0.0f);  // along the ray's travel over the floor
    EXPECT_NEAR(glm::dot(f.a1, f.a2), 0.0f, 1e-7f);
}

TEST(Footprint, HeadOnIsACircle_GrazingIsCapped_NoWidthIsAPoint) {
    const Vec3 n(0.0f, 0.0f, 1.0f);
    const Footprint headOn = footprintAt(-n, n, 0.5f);
    EXPECT_NEAR(glm::length(headOn.a1), 0.25f, 1e-6f);
    EXPECT_NEAR(glm::length(headOn.a2), 0.25f, 1e-6f);
    EXPECT_NEAR(glm::dot(headOn.a1, headOn.a2), 0.0f, 1e-7f);
    EXPECT_NEAR(glm::dot(headOn.a1, n), 0.0f, 1e-7f);
    // Parallel to the surface: 1 / max(|cos|, 0.01), 100 times at most.
    const Footprint grazing = footprintAt(Vec3(1.0f, 0.0f, 0.0f), n, 0.5f);
    EXPECT_NEAR(glm::length(grazing.a1), 25.0f, 1e-4f);
    for (const float width : {0.0f, -1.0f, NAN}) {
        const Footprint none = footprintAt(Vec3(0.6f, 0.0f, -0.8f), n, width);
        EXPECT_EQ(none.a1, Vec3(0.0f));
        EXPECT_EQ(none.a2, Vec3(0.0f));
    }
}

/// Unit vectors at random, and the directions each branch of footprintAt tells apart.
struct RayMaker {
    std::mt19937 rng{29};
    std::uniform_real_distribution<float> unit{-1.0f, 1.0f};

    Vec3 direction() {
        for (;;) {
            const Vec3 v(unit(rng), unit(rng), unit(rng));
            const float length = glm::length(v);
            if (length > 0.1f && length <= 1.0f) return v / length;
        }
    }
    /// (dir, n, width): random, head-on, nearly head-on, grazing, or a bad width.
    void next(Vec3& dir, Vec3& n, float& width) {
        n = direction(), dir = direction();
        width = std::ldexp(std::abs(unit(rng)), int(rng() % 30) - 20);
        switch (rng() % 6) {
            case 1:
                dir = -n;
                break;
            case 2:
                dir = -n, dir.x += unit(rng) * 1e-7f;
                break;
            case 3:
                dir = glm::normalize(glm::cross(n, direction()) + n * (unit(rng) * 1e-3f));
                break;
            case 4: {
                const float bad[] = {0.0f, -0.0f, -1.0f, NAN, INFINITY, 1e-39f};
                width = bad[rng() % std::size(bad)];
                break;
            }
            case 5:
                n = Vec3(rng() % 2 ? 0.95f : 0.5f, 0.3f, 0.1f), n = glm::normalize(n);
                break;
            default:
                break;
        }
    }
};

TEST(Footprint, ManyRaysAtOnce_GiveEachRayTheBitsItGetsAlone) {
    // The checker batch takes footprints four rays at a time; image lookups and shadows
    // through glass take them one at a time. One template body: the bits must agree.
    RayMaker make;
    for (int round = 0; round < 20000; ++round) {
        Vec3 dir[kLaneWidth], n[kLaneWidth];
        float width[kLaneWidth];
        FloatLanes l[7];
        for (int k = 0; k < kLaneWidth; ++k) {
            make.next(dir[k], n[k], width[k]);
            l[0][k] = dir[k].x, l[1][k] = dir[k].y, l[2][k] = dir[k].z;
            l[3][k] = n[k].x, l[4][k] = n[k].y, l[5][k] = n[k].z, l[6][k] = width[k];
        }
        const FootprintAxes<FloatLanes> f = footprintAxes(l[0], l[1], l[2], l[3], l[4], l[5], l[6]);
        for (int k = 0; k < kLaneWidth; ++k) {
            const Footprint alone = footprintAt(dir[k], n[k], width[k]);
            const float lane[6] = {f.a1x[k], f.a1y[k], f.a1z[k], f.a2x[k], f.a2y[k], f.a2z[k]};
            const float want[6] = {alone.a1.x, alone.a1.y, alone.a1.z,
                                   alone.a2.x, alone.a2.y, alone.a2.z};
            for (int c = 0; c < 6; ++c)
                ASSERT_TRUE(sameBits(lane[c], want[c]))
                    << "round " << round << " lane " << k << " component " << c << ": " << lane[c]
                    << " alone " << want[c];
        }
    }
}

TEST(CheckerBatch, GivesEachPointTheColourPatternColorGivesItAlone) {
    // A level's checkered points, gathered: footprints and box filters in lanes, planes in
    // world space and other shapes through their object transforms, mixed in one batch; the
    // colours are patternColor's for each point alone, bit for bit, for counts that leave
    // lanes over.
    MaterialPattern checker;
    checker.kind = MaterialPattern::Kind::Checker;
    checker.even = Color(0.85f, 0.12f, 0.08f), checker.odd = Color(0.92f, 0.82f, 0.15f);
    checker.checkerScale = 0.7f;
    PatternSurface plane;
    plane.shape = PatternSurface::Shape::Plane;
    plane.b = Vec3(0.0f, 1.0f, 0.0f);
    PatternSurface sphere;
    sphere.shape = PatternSurface::Shape::Sphere;
    const Mat4 worldFromObject =
        glm::scale(glm::rotate(glm::translate(Mat4(1.0f), Vec3(1.5f, 0.5f, -2.0f)), 0.7f,
                               glm::normalize(Vec3(1.0f, 2.0f, 0.5f))),
                   Vec3(1.0f, 2.0f, 0.5f));
    sphere.objectFromWorld = glm::inverse(worldFromObject);
    sphere.dirToObject = Mat3(sphere.objectFromWorld);
    sphere.normalToObject = glm::transpose(Mat3(worldFromObject));
    sphere.r = 1.0f;

    RayMaker make;
    std::uniform_real_distribution<float> spread(-50.0f, 50.0f);
    CheckerBatch batch;
    for (std::size_t count : {1u, 2u, 3u, 4u, 5u, 7u, 9u, 1001u}) {
        std::vector<Vec3> p(count), dir(count), n(count);
        std::vector<float> width(count);
        std::vector<const PatternSurface*> on(count);
        batch.reset(count);
        for (std::size_t i = 0; i < count; ++i) {
            make.next(dir[i], n[i], width[i]);
            p[i] = Vec3(spread(make.rng), spread(make.rng) * 0.1f, spread(make.rng));
            on[i] = make.rng() % 3 ? &plane : &sphere;
            batch.add(uint32_t(count - i), *on[i], p[i], dir[i], n[i], width[i],
                      checker.checkerScale);
        }
        ASSERT_EQ(batch.size(), count);
        const float* odd = batch.evaluate();
        for (std::size_t i = 0; i < count; ++i) {
            EXPECT_EQ(batch.point(i), uint32_t(count - i));
            const Color batched = checkerColor(checker, odd[i]);
            const Color alone = patternColor(checker, *on[i], p[i], n[i], dir[i], width[i]);
            for (int c = 0; c < 3; ++c)
                ASSERT_TRUE(sameBits(batched[c], alone[c]))
                    << count << " points, point " << i << " channel " << c << ": " << batched[c]
                    << " alone " << alone[c];
        }
    }
}

}  // namespace
}  // namespace rs
