// Ray intersection and bounds for the render-ready shapes (rectangle, box, triangle; the sphere
// and plane tests are inline in the header).
#include "geometry/shapes.h"

#include <cmath>

namespace rs {

namespace {

// Comparisons are written so that a NaN t (e.g. from a degenerate shape) is never inside the range.
inline bool inOpenRange(float t, float tmin, float tmax) {
    return t > tmin && t < tmax;
}

}  // namespace

RectangleShape RectangleShape::make(const Vec3& center, const Vec3& u, const Vec3& v) {
    RectangleShape r;
    r.center = center;
    r.u = u;
    r.v = v;
    r.normal = glm::normalize(glm::cross(u, v));
    // Dual basis inside the plane: dot(u, uDual) = 1, dot(v, uDual) = 0 and vice versa, so
    // (a, b) come out right even when u and v are sheared by a non-uniform scale.
    const Vec3 vPerp = glm::cross(v, r.normal);
    const Vec3 uPerp = glm::cross(r.normal, u);
    r.uDual = vPerp / glm::dot(u, vPerp);
    r.vDual = uPerp / glm::dot(v, uPerp);
    return r;
}

bool intersect(const RectangleShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit) {
    const float denom = glm::dot(ray.dir, s.normal);
    if (denom == 0.0f) return false;
    const Vec3 oc = ray.origin - s.center;
    const float t = -glm::dot(oc, s.normal) / denom;
    if (!inOpenRange(t, tmin, tmax)) return false;
    // Relative to the centre so a far-away origin does not swamp the in-plane coordinates.
    const Vec3 p = oc + t * ray.dir;
    const float a = glm::dot(p, s.uDual);
    const float b = glm::dot(p, s.vDual);
    if (!(std::abs(a) <= 1.0f && std::abs(b) <= 1.0f)) return false;
    hit.t = t;
    hit.n = s.normal;
    return true;
}

bool intersect(const BoxShape& s, const Ray& ray, float tmin, float tmax, ShapeHit& hit) {
    // Same arithmetic and NaN ordering as intersectSlabs (unscaled), so a box primitive is hit
    // only where its BVH node also passes; remember which axis set the entry and exit.
    float tEnter = -kInfinity, tExit = kInfinity;
    int enterAxis = -1, exitAxis = -1;
    for (int k = 0; k < 3; ++k) {
        const float t0 = (s.box[ray.sign[k]][k] - ray.origin[k]) * ray.invDir[k];
        const float t1 = (s.box[1 - ray.sign[k]][k] - ray.origin[k]) * ray.invDir[k];
        if (t0 > tEnter) {
            tEnter = t0;
            enterAxis = k;
        }
        if (t1 < tExit) {
            tExit = t1;
            exitAxis = k;
        }
    }
    if (!(tEnter <= tExit)) return false;
    Vec3 n(0.0f);
    if (tEnter > tmin) {
        if (!(tEnter < tmax) || enterAxis < 0) return false;
        hit.t = tEnter;
        // Entering through the max face when travelling in -k, so the outward normal is +k.
        n[enterAxis] = ray.sign[enterAxis] ? 1.0f : -1.0f;
    } else {
        // Started inside (or the entry lies before tmin): report where the ray leaves.
        if (!inOpenRange(tExit, tmin, tmax) || exitAxis < 0) return false;
        hit.t = tExit;
        n[exitAxis] = ray.sign[exitAxis] ? -1.0f : 1.0f;
    }
    hit.n = n;
    return true;
}

bool intersect(const TriangleShape& s, const Ray& ray, float tmin, float tmax, float& t, float& b1,
               float& b2) {
    // Moeller-Trumbore, two-sided: only an exactly zero determinant (ray parallel to the plane or
    // a zero-area triangle) is rejected; the range checks below also reject NaN.
    const Vec3 pvec = glm::cross(ray.dir, s.e2);
    const float det = glm::dot(s.e1, pvec);
    if (det == 0.0f) return false;
    const float invDet = 1.0f / det;
    const Vec3 tvec = ray.origin - s.p0;
    const float u = glm::dot(tvec, pvec) * invDet;
    if (!(u >= 0.0f && u <= 1.0f)) return false;
    const Vec3 qvec = glm::cross(tvec, s.e1);
    const float v = glm::dot(ray.dir, qvec) * invDet;
    if (!(v >= 0.0f && u + v <= 1.0f)) return false;
    const float tHit = glm::dot(s.e2, qvec) * invDet;
    if (!inOpenRange(tHit, tmin, tmax)) return false;
    t = tHit;
    b1 = u;
    b2 = v;
    return true;
}

Aabb bounds(const SphereShape& s) {
    const Vec3 r(std::abs(s.radius));
    return {s.center - r, s.center + r};
}

Aabb bounds(const RectangleShape& s) {
    Aabb b;
    b.expand(s.center - s.u - s.v);
    b.expand(s.center + s.u - s.v);
    b.expand(s.center + s.u + s.v);
    b.expand(s.center - s.u + s.v);
    return b;
}

Aabb bounds(const BoxShape& s) {
    return s.box;
}

Aabb bounds(const TriangleShape& s) {
    Aabb b;
    b.expand(s.p0);
    b.expand(s.p0 + s.e1);
    b.expand(s.p0 + s.e2);
    return b;
}

}  // namespace rs
