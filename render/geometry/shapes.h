// Render-ready shapes and their ray intersection routines (world space unless noted).
#pragma once

#include <cmath>
#include <utility>

#include "core/math.h"

namespace rs {

/// Result of a shape test: distance along the ray and the unit geometric/shading normal.
/// Normals face out of the surface (out of a closed body; along u x v for a rectangle; along the
/// plane's normal), never flipped toward the ray: the integrator decides inside/outside.
struct ShapeHit {
    float t;
    Vec3 n;
};

/// Sphere in world space.
struct SphereShape {
    Vec3 center;
    float radius;
};

/// Infinite plane through `point` with unit `normal`; never in the BVH.
struct PlaneShape {
    Vec3 point;
    Vec3 normal;
};

/// Parallelogram c + a*u + b*v, a, b in [-1, 1]. `uDual`/`vDual` give (a, b) of a point in the
/// plane by a dot product, so u and v need not stay orthogonal under a non-uniform scale.
struct RectangleShape {
    Vec3 center, u, v, normal, uDual, vDual;
    /// Precomputes normal and duals from centre and half-extent edges.
    static RectangleShape make(const Vec3& center, const Vec3& u, const Vec3& v);
};

/// Axis-aligned box (in the frame it is tested in).
struct BoxShape {
    Aabb box;
};

/// Single triangle with precomputed edges (Moeller-Trumbore).
struct TriangleShape {
    Vec3 p0, e1, e2;
    static TriangleShape make(const Vec3& a, const Vec3& b, const Vec3& c) {
        return {a, b - a, c - a};
    }
};

/// Closest hit in (tmin, tmax): true and fills `hit` when found. Robust for grazing rays and
/// rays that start inside (they hit the far side). `ray.dir` need not be unit length.
inline bool intersect(const SphereShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit);
inline bool intersect(const PlaneShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit);
bool intersect(const RectangleShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit);
bool intersect(const BoxShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit);
/// Triangle test; also returns barycentrics (b1, b2) of the hit for normal interpolation.
bool intersect(const TriangleShape& s, const Ray& ray, float tmin, float tmax, float& t, float& b1,
               float& b2);

/// Second half of the sphere test, from the re-centred quadratic (see intersect(SphereShape)):
/// picks the root in (tmin, tmax), giving t and its offset from the closest approach tProj.
/// Shared with the four-wide sphere test of the scene queries so both give identical bits.
inline bool solveRecentredSphere(float a, float tProj, float bHalf, float c, float tmin, float tmax,
                                 float& t, float& offset) {
    const float disc = bHalf * bHalf - a * c;
    if (!(disc >= 0.0f)) return false;  // also rejects NaN (zero direction)
    const float root = std::sqrt(disc);
    // Stable pair of roots (Numerical Recipes); q == 0 only for an exact tangent at f = 0.
    const float q = bHalf >= 0.0f ? -(bHalf + root) : -(bHalf - root);
    float s0 = 0.0f, s1 = 0.0f;
    if (q != 0.0f) {
        s0 = q / a;
        s1 = c / q;
        if (s0 > s1) std::swap(s0, s1);
    }
    // NaN-safe open range: a NaN t is never a hit.
    t = tProj + s0;
    offset = s0;
    if (t > tmin && t < tmax) return true;
    // Origin inside (or the near hit clipped by tmin): the far side is the answer.
    t = tProj + s1;
    offset = s1;
    return t > tmin && t < tmax;
}

// Inline: these two run for nearly every ray, and a call costs as much as the test.
inline bool intersect(const SphereShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit) {
    // Mitsuba's trick: move the origin to the point of the ray closest to the centre, then solve
    // for the offset from there. The quadratic then has tiny, well-conditioned coefficients
    // (f is ~perpendicular to d and |f| <= radius for a hit), so distant origins and near-grazing
    // rays keep their precision instead of cancelling |o - c|^2 - r^2.
    const float a = glm::dot(ray.dir, ray.dir);
    const float tProj = glm::dot(s.center - ray.origin, ray.dir) / a;
    const Vec3 f = (ray.origin - s.center) + tProj * ray.dir;
    const float bHalf = glm::dot(f, ray.dir);  // ~0 by construction; kept for exactness
    const float c = glm::dot(f, f) - s.radius * s.radius;
    float t, offset;
    if (!solveRecentredSphere(a, tProj, bHalf, c, tmin, tmax, t, offset)) return false;
    hit.t = t;
    // From the re-centred origin the hit point is computed with small numbers, hence accurately.
    hit.n = divide(f + offset * ray.dir, s.radius);
    return true;
}

inline bool intersect(const PlaneShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit) {
    // Two-sided; a ray parallel to the plane (denom == 0) misses, even one lying in it.
    const float denom = glm::dot(ray.dir, s.normal);
    if (denom == 0.0f) return false;
    const float t = glm::dot(s.point - ray.origin, s.normal) / denom;
    if (!(t > tmin && t < tmax)) return false;
    hit.t = t;
    hit.n = s.normal;
    return true;
}

/// World bounds of each bounded shape.
Aabb bounds(const SphereShape& s);
Aabb bounds(const RectangleShape& s);
Aabb bounds(const BoxShape& s);
Aabb bounds(const TriangleShape& s);

}  // namespace rs
