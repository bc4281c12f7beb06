// Shape intersection tests: hits, misses, exact t and normals, grazing and inside-start rays.
#include "geometry/shapes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rs {
namespace {

constexpr float kEps = 1e-5f;

void expectVecNear(const Vec3& a, const Vec3& b, float eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

const SphereShape kUnitSphereAt5{Vec3(0, 0, 5), 1.0f};

TEST(Sphere, RayThroughCentre_HitsNearSideWithOutwardNormal) {
    ShapeHit h{};
    ASSERT_TRUE(intersect(kUnitSphereAt5, Ray::make(Vec3(0), Vec3(0, 0, 1)), 0, kInfinity, h));
    EXPECT_FLOAT_EQ(h.t, 4.0f);
    expectVecNear(h.n, Vec3(0, 0, -1));
}

TEST(Sphere, NonUnitDirection_MeasuresTInUnitsOfDirection) {
    ShapeHit h{};
    const Ray ray = Ray::make(Vec3(0.6f, 0, 0), Vec3(0, 0, 2.5f));
    ASSERT_TRUE(intersect(kUnitSphereAt5, ray, 0, kInfinity, h));
    EXPECT_NEAR(h.t, 4.2f / 2.5f, kEps);  // z = 5 - sqrt(1 - 0.36) = 4.2
    expectVecNear(h.n, Vec3(0.6f, 0, -0.8f));
}

TEST(Sphere, RayStartingInside_HitsFarSide) {
    ShapeHit h{};
    ASSERT_TRUE(
        intersect(kUnitSphereAt5, Ray::make(Vec3(0, 0, 5.5f), Vec3(0, 0, -1)), 0, kInfinity, h));
    EXPECT_FLOAT_EQ(h.t, 1.5f);
    expectVecNear(h.n, Vec3(0, 0, -1));
}

TEST(Sphere, MissingOrBehindRay_ReturnsFalse) {
    ShapeHit h{};
    EXPECT_FALSE(
        intersect(kUnitSphereAt5, Ray::make(Vec3(0, 1.01f, 0), Vec3(0, 0, 1)), 0, kInfinity, h));
    EXPECT_FALSE(intersect(kUnitSphereAt5, Ray::make(Vec3(0), Vec3(0, 0, -1)), 0, kInfinity, h));
}

TEST(Sphere, TminAndTmax_AreExclusiveBounds) {
    ShapeHit h{};
    const Ray ray = Ray::make(Vec3(0), Vec3(0, 0, 1));
    EXPECT_FALSE(intersect(kUnitSphereAt5, ray, 0, 4.0f, h));  // near hit at exactly tmax
    ASSERT_TRUE(intersect(kUnitSphereAt5, ray, 0, 4.001f, h));
    ASSERT_TRUE(intersect(kUnitSphereAt5, ray, 4.0f, kInfinity, h));  // near hit at tmin: far side
    EXPECT_FLOAT_EQ(h.t, 6.0f);
    EXPECT_FALSE(intersect(kUnitSphereAt5, ray, 4.5f, 6.0f, h));
}

TEST(Sphere, GrazingRays_HitJustInsideMissJustOutsideNeverNaN) {
    ShapeHit h{};
    ASSERT_TRUE(
        intersect(kUnitSphereAt5, Ray::make(Vec3(0, 0.9999f, 0), Vec3(0, 0, 1)), 0, kInfinity, h));
    EXPECT_NEAR(h.t, 5.0f, 0.02f);
    EXPECT_NEAR(glm::length(h.n), 1.0f, kEps);
    EXPECT_FALSE(
        intersect(kUnitSphereAt5, Ray::make(Vec3(0, 1.0001f, 0), Vec3(0, 0, 1)), 0, kInfinity, h));
    // Exactly tangent: either answer is fine, but a hit must be finite and at the tangent point.
    if (intersect(kUnitSphereAt5, Ray::make(Vec3(0, 1, 0), Vec3(0, 0, 1)), 0, kInfinity, h)) {
        EXPECT_NEAR(h.t, 5.0f, 1e-3f);
        expectVecNear(h.n, Vec3(0, 1, 0), 1e-3f);
    }
}

TEST(Sphere, DistantOrigin_KeepsPrecisionThanksToRecentring) {
    // |o - c|^2 - r^2 = 1e8 - 1e-4 loses r entirely in float; the re-centred solve does not.
    const SphereShape tiny{Vec3(0), 0.01f};
    ShapeHit h{};
    ASSERT_TRUE(intersect(tiny, Ray::make(Vec3(0.005f, 0, -1e4f), Vec3(0, 0, 1)), 0, kInfinity, h));
    EXPECT_NEAR(h.t, 1e4f - 0.01f * std::sqrt(0.75f), 2e-3f);
    expectVecNear(h.n, Vec3(0.5f, 0, -std::sqrt(0.75f)), 1e-3f);
}

TEST(Sphere, Bounds_AreCentrePlusMinusRadius) {
    const Aabb b = bounds(SphereShape{Vec3(1, 2, 3), 0.5f});
    expectVecNear(b.min, Vec3(0.5f, 1.5f, 2.5f));
    expectVecNear(b.max, Vec3(1.5f, 2.5f, 3.5f));
}

TEST(Plane, HitFromEitherSide_KeepsGivenNormal) {
    const PlaneShape floor{Vec3(0, -1, 0), Vec3(0, 1, 0)};
    ShapeHit h{};
    ASSERT_TRUE(intersect(floor, Ray::make(Vec3(0, 1, 0), Vec3(0, -4, 0)), 0, kInfinity, h));
    EXPECT_FLOAT_EQ(h.t, 0.5f);
    expectVecNear(h.n, Vec3(0, 1, 0));
    ASSERT_TRUE(intersect(floor, Ray::make(Vec3(3, -3, 0), Vec3(0, 1, 0)), 0, kInfinity, h));
    EXPECT_FLOAT_EQ(h.t, 2.0f);
    expectVecNear(h.n, Vec3(0, 1, 0));
}

TEST(Plane, ParallelRayOrRangeExcludingHit_Misses) {
    const PlaneShape floor{Vec3(0, -1, 0), Vec3(0, 1, 0)};
    ShapeHit h{};
    EXPECT_FALSE(intersect(floor, Ray::make(Vec3(0), Vec3(1, 0, 0)), 0, kInfinity, h));
    EXPECT_FALSE(intersect(floor, Ray::make(Vec3(0, -1, 0), Vec3(1, 0, 0)), 0, kInfinity, h));
    EXPECT_FALSE(intersect(floor, Ray::make(Vec3(0), Vec3(0, -1, 0)), 0, 1.0f, h));
    EXPECT_FALSE(intersect(floor, Ray::make(Vec3(0), Vec3(0, -1, 0)), 1.0f, 2.0f, h));
    EXPECT_FALSE(intersect(floor, Ray::make(Vec3(0), Vec3(0, 1, 0)), 0, kInfinity, h));
}

TEST(Rectangle, Make_GivesUnitNormalAndDualsThatRecoverCoordinates) {
    const Vec3 u(2, 0, 0), v(1, 1, 0);  // sheared, as after a non-uniform scale
    const RectangleShape r = RectangleShape::make(Vec3(1, 1, 1), u, v);
    expectVecNear(r.normal, Vec3(0, 0, 1));
    const Vec3 p = 0.3f * u - 0.7f * v;
    EXPECT_NEAR(glm::dot(p, r.uDual), 0.3f, kEps);
    EXPECT_NEAR(glm::dot(p, r.vDual), -0.7f, kEps);
}

TEST(Rectangle, ShearedParallelogram_HitsInsideMissesOutside) {
    const RectangleShape r = RectangleShape::make(Vec3(0), Vec3(2, 0, 0), Vec3(1, 1, 0));
    ShapeHit h{};
    // (2.5, 0.9) is inside the parallelogram but right of any axis-aligned 2x1 rectangle.
    ASSERT_TRUE(intersect(r, Ray::make(Vec3(2.5f, 0.9f, 3), Vec3(0, 0, -2)), 0, kInfinity, h));
    EXPECT_FLOAT_EQ(h.t, 1.5f);
    expectVecNear(h.n, Vec3(0, 0, 1));
    // (-2.5, 0.9) is inside the 6x2 box around it but outside the parallelogram.
    EXPECT_FALSE(intersect(r, Ray::make(Vec3(-2.5f, 0.9f, 3), Vec3(0, 0, -1)), 0, kInfinity, h));
}

TEST(Rectangle, HitFromBehind_KeepsUCrossVNormal) {
    const RectangleShape r = RectangleShape::make(Vec3(0, 0, 2), Vec3(1, 0, 0), Vec3(0, 1, 0));
    ShapeHit h{};
    ASSERT_TRUE(intersect(r, Ray::make(Vec3(0.5f, -0.5f, 0), Vec3(0, 0, 1)), 0, kInfinity, h));
    EXPECT_FLOAT_EQ(h.t, 2.0f);
    expectVecNear(h.n, Vec3(0, 0, 1));
}

TEST(Rectangle, ParallelRayAndTRange_Miss) {
    const RectangleShape r = RectangleShape::make(Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0));
    ShapeHit h{};
    EXPECT_FALSE(intersect(r, Ray::make(Vec3(-2, 0, 0), Vec3(1, 0, 0)), 0, kInfinity, h));
    EXPECT_FALSE(intersect(r, Ray::make(Vec3(0, 0, 1), Vec3(0, 0, -1)), 0, 1.0f, h));
    EXPECT_TRUE(intersect(r, Ray::make(Vec3(0, 0, 1), Vec3(0, 0, -1)), 0, 1.001f, h));
}

TEST(Rectangle, Bounds_CoverAllFourCorners) {
    const Aabb b = bounds(RectangleShape::make(Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 0, 2)));
    expectVecNear(b.min, Vec3(0, -1, -2));
    expectVecNear(b.max, Vec3(2, 1, 2));
}

const BoxShape kCube{{Vec3(-1), Vec3(1)}};

TEST(Box, RayFromEachSide_HitsEnteringFaceWithOutwardNormal) {
    for (int axis = 0; axis < 3; ++axis) {
        for (float side : {-1.0f, 1.0f}) {
            Vec3 o(0.2f, -0.3f, 0.1f), d(0);
            o[axis] = 3.0f * side;
            d[axis] = -2.0f * side;  // non-unit
            ShapeHit h{};
            ASSERT_TRUE(intersect(kCube, Ray::make(o, d), 0, kInfinity, h)) << axis << side;
            EXPECT_FLOAT_EQ(h.t, 1.0f);
            Vec3 n(0);
            n[axis] = side;
            expectVecNear(h.n, n);
        }
    }
}

TEST(Box, RayStartingInside_ReturnsExitWithOutwardNormal) {
    ShapeHit h{};
    ASSERT_TRUE(intersect(kCube, Ray::make(Vec3(0, 0.5f, 0), Vec3(0, 1, 1)), 0, kInfinity, h));
    EXPECT_FLOAT_EQ(h.t, 0.5f);
    expectVecNear(h.n, Vec3(0, 1, 0));
}

TEST(Box, RayThroughEdge_HitsWithOneOfTheTwoFaceNormals) {
    ShapeHit h{};
    ASSERT_TRUE(intersect(kCube, Ray::make(Vec3(-2, -2, 0), Vec3(1, 1, 0)), 0, kInfinity, h));
    EXPECT_FLOAT_EQ(h.t, 1.0f);
    EXPECT_TRUE(h.n == Vec3(-1, 0, 0) || h.n == Vec3(0, -1, 0));
}

TEST(Box, RayParallelToFaces_HitsInsideSlabMissesOutside) {
    ShapeHit h{};
    // Lying exactly in the top face's plane: 0 * inf there must not turn into a NaN miss.
    ASSERT_TRUE(intersect(kCube, Ray::make(Vec3(-3, 1, 0), Vec3(1, 0, 0)), 0, kInfinity, h));
    EXPECT_FLOAT_EQ(h.t, 2.0f);
    expectVecNear(h.n, Vec3(-1, 0, 0));
    EXPECT_FALSE(intersect(kCube, Ray::make(Vec3(-3, 1.001f, 0), Vec3(1, 0, 0)), 0, kInfinity, h));
}

TEST(Box, TminAndTmax_SelectEntryExitOrNothing) {
    ShapeHit h{};
    const Ray ray = Ray::make(Vec3(0, 0, -3), Vec3(0, 0, 1));
    EXPECT_FALSE(intersect(kCube, ray, 0, 2.0f, h));
    ASSERT_TRUE(intersect(kCube, ray, 2.0f, kInfinity, h));  // entry at tmin: exit instead
    EXPECT_FLOAT_EQ(h.t, 4.0f);
    expectVecNear(h.n, Vec3(0, 0, 1));
    EXPECT_FALSE(intersect(kCube, ray, 2.5f, 4.0f, h));
    EXPECT_FALSE(intersect(kCube, ray, 4.0f, kInfinity, h));
}

TEST(Slabs, RayInSlabPlaneWithZeroDirection_CountsAsInside) {
    const Aabb box{Vec3(0), Vec3(1)};
    float tEntry = -1.0f;
    EXPECT_TRUE(
        intersectSlabs(box, Ray::make(Vec3(0, 0.5f, -1), Vec3(0, 0, 1)), 0, kInfinity, tEntry));
    EXPECT_FLOAT_EQ(tEntry, 1.0f);
    EXPECT_TRUE(
        intersectSlabs(box, Ray::make(Vec3(1, 1, -1), Vec3(0, 0, -1e-3f)), -kInfinity, kInfinity));
    EXPECT_FALSE(
        intersectSlabs(box, Ray::make(Vec3(1.001f, 0.5f, -1), Vec3(0, 0, 1)), 0, kInfinity));
    EXPECT_FALSE(intersectSlabs(box, Ray::make(Vec3(0, 0.5f, -1), Vec3(0, 0, 1)), 0, 0.5f));
}

TEST(Triangle, HitInside_GivesTAndBarycentricsOfTheHitPoint) {
    const Vec3 p0(0, 0, 2), p1(2, 0, 2), p2(0, 2, 2);
    const TriangleShape tri = TriangleShape::make(p0, p1, p2);
    const Ray ray = Ray::make(Vec3(0.5f, 0.25f, 0), Vec3(0, 0, 4));
    float t, b1, b2;
    ASSERT_TRUE(intersect(tri, ray, 0, kInfinity, t, b1, b2));
    EXPECT_FLOAT_EQ(t, 0.5f);
    expectVecNear((1 - b1 - b2) * p0 + b1 * p1 + b2 * p2, ray.at(t));
    EXPECT_NEAR(b1, 0.25f, kEps);
    EXPECT_NEAR(b2, 0.125f, kEps);
}

TEST(Triangle, TwoSided_HitsFromBehindToo) {
    const TriangleShape tri = TriangleShape::make(Vec3(0, 0, 2), Vec3(2, 0, 2), Vec3(0, 2, 2));
    float t, b1, b2;
    ASSERT_TRUE(
        intersect(tri, Ray::make(Vec3(0.5f, 0.5f, 5), Vec3(0, 0, -1)), 0, kInfinity, t, b1, b2));
    EXPECT_FLOAT_EQ(t, 3.0f);
}

TEST(Triangle, OutsideParallelOrOutOfRange_Misses) {
    const TriangleShape tri = TriangleShape::make(Vec3(0, 0, 2), Vec3(2, 0, 2), Vec3(0, 2, 2));
    float t, b1, b2;
    EXPECT_FALSE(
        intersect(tri, Ray::make(Vec3(1.5f, 1.5f, 0), Vec3(0, 0, 1)), 0, kInfinity, t, b1, b2));
    EXPECT_FALSE(
        intersect(tri, Ray::make(Vec3(-1, 0.5f, 2), Vec3(1, 0, 0)), 0, kInfinity, t, b1, b2));
    EXPECT_FALSE(intersect(tri, Ray::make(Vec3(0.5f, 0.5f, 0), Vec3(0, 0, 1)), 0, 2.0f, t, b1, b2));
    EXPECT_FALSE(
        intersect(tri, Ray::make(Vec3(0.5f, 0.5f, 0), Vec3(0, 0, 1)), 2.0f, 5.0f, t, b1, b2));
}

TEST(Triangle, ZeroArea_NeverHits) {
    const TriangleShape tri = TriangleShape::make(Vec3(0), Vec3(1, 1, 0), Vec3(2, 2, 0));
    float t, b1, b2;
    EXPECT_FALSE(intersect(tri, Ray::make(Vec3(1, 1, -1), Vec3(0, 0, 1)), 0, kInfinity, t, b1, b2));
}

TEST(Triangle, Bounds_CoverTheThreeVertices) {
    const Aabb b = bounds(TriangleShape::make(Vec3(0, 1, 2), Vec3(-1, 3, 0), Vec3(2, 0, 1)));
    expectVecNear(b.min, Vec3(-1, 0, 0));
    expectVecNear(b.max, Vec3(2, 3, 2));
}

}  // namespace
}  // namespace rs
