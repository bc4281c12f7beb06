// Render-ready shapes and their ray intersection routines (world space unless noted).
#pragma once

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
bool intersect(const SphereShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit);
bool intersect(const PlaneShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit);
bool intersect(const RectangleShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit);
bool intersect(const BoxShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit);
/// Triangle test; also returns barycentrics (b1, b2) of the hit for normal interpolation.
bool intersect(const TriangleShape& s, const Ray& ray, float tmin, float tmax, float& t, float& b1,
               float& b2);

/// World bounds of each bounded shape.
Aabb bounds(const SphereShape& s);
Aabb bounds(const RectangleShape& s);
Aabb bounds(const BoxShape& s);
Aabb bounds(const TriangleShape& s);

}  // namespace rs
