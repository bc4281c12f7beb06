// Small POD math types for the hot path: rays with precomputed reciprocals, boxes, colours.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>

namespace rs {

using Vec3 = glm::vec3;   ///< float x, y, z: POD, direct member access (thesis 4.1).
using Color = glm::vec3;  ///< Linear HDR radiance, r = x, g = y, b = z.
using Mat4 = glm::mat4;
using Mat3 = glm::mat3;

/// Four floats in one SSE/NEON register (GCC/Clang vector extension): lane-wise IEEE arithmetic,
/// so a four-wide test gives the same bits as four scalar ones.
using Float4 = float __attribute__((vector_size(16)));

/// v / s, lane by lane in one packed division: the same bits as three scalar divisions, for
/// about a third of the latency (divisions dominate the shading path).
inline Vec3 divide(const Vec3& v, float s) {
    const Float4 q = Float4{v.x, v.y, v.z, 1.0f} / Float4{s, s, s, 1.0f};
    return Vec3(q[0], q[1], q[2]);
}

/// (1/v.x, 1/v.y, 1/v.z) in one packed division; the same bits as three scalar ones.
inline Vec3 reciprocal(const Vec3& v) {
    const Float4 q = Float4{1.0f, 1.0f, 1.0f, 1.0f} / Float4{v.x, v.y, v.z, 1.0f};
    return Vec3(q[0], q[1], q[2]);
}

/// floor(x) without a library call (std::floor is one on the baseline x86-64 the project
/// builds for, which lacks SSE4.1's rounding instruction): the same value as std::floor for
/// every x (a zero may come back as +0), NaN and infinities included.
inline double floorInline(double x) {
    if (!(std::abs(x) < 4.0e15)) return std::floor(x);  // an integer already, or not finite
    const double t = double(static_cast<long long>(x));
    return t > x ? t - 1.0 : t;
}
inline float floorInline(float x) {
    if (!(std::abs(x) < 8.0e6f)) return std::floor(x);
    const float t = float(static_cast<int>(x));
    return t > x ? t - 1.0f : t;
}

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();
inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kTwoPi = 2.0f * kPi;

/// A ray with the reciprocal direction and its signs precomputed for the Williams et al. slab test.
struct Ray {
    Vec3 origin;
    Vec3 dir;
    Vec3 invDir;
    int sign[3];

    /// Builds a ray; `d` need not be normalised (t is then measured in units of |d|).
    static Ray make(const Vec3& o, const Vec3& d) {
        Ray r;
        r.origin = o;
        r.dir = d;
        r.invDir = reciprocal(d);
        r.sign[0] = r.invDir.x < 0.0f;
        r.sign[1] = r.invDir.y < 0.0f;
        r.sign[2] = r.invDir.z < 0.0f;
        return r;
    }
    Vec3 at(float t) const { return origin + dir * t; }
};

/// Axis-aligned bounding box; an empty box has min > max.
struct Aabb {
    Vec3 min{kInfinity, kInfinity, kInfinity};
    Vec3 max{-kInfinity, -kInfinity, -kInfinity};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void expand(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void expand(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    Vec3 center() const { return (min + max) * 0.5f; }
    Vec3 extent() const { return max - min; }
    float surfaceArea() const {
        if (empty()) return 0.0f;
        Vec3 e = extent();
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
    bool overlaps(const Aabb& b) const {
        return min.x <= b.max.x && max.x >= b.min.x && min.y <= b.max.y && max.y >= b.min.y &&
               min.z <= b.max.z && max.z >= b.min.z;
    }
    const Vec3& operator[](int i) const { return i ? max : min; }
    /// The box around this box's 8 corners after an affine transform.
    Aabb transformed(const Mat4& m) const;
};

/// Williams et al. ray/box slab test that also gives the entry distance max(tmin, box entry),
/// so traversal can visit the nearer child first and skip nodes beyond the closest hit.
/// NaN-robust: a ray lying exactly on a slab plane with a zero direction component gives
/// 0 * inf = NaN there; the comparisons below are ordered so a NaN never narrows the interval
/// (the ray counts as inside that slab, which is conservative). Far distances are scaled by
/// 1 + 2*gamma(3) (pbrt) so rounding can never reject a box that the ray truly touches.
inline bool intersectSlabs(const Aabb& b, const Ray& r, float tmin, float tmax, float& tEntry) {
    constexpr float kUnitRoundoff = 0.5f * std::numeric_limits<float>::epsilon();
    constexpr float kFarScale =
        1.0f + 2.0f * (3.0f * kUnitRoundoff) / (1.0f - 3.0f * kUnitRoundoff);
    float t0 = (b[r.sign[0]].x - r.origin.x) * r.invDir.x;
    float t1 = (b[1 - r.sign[0]].x - r.origin.x) * r.invDir.x * kFarScale;
    float lo = t0 > tmin ? t0 : tmin;
    float hi = t1 < tmax ? t1 : tmax;
    t0 = (b[r.sign[1]].y - r.origin.y) * r.invDir.y;
    t1 = (b[1 - r.sign[1]].y - r.origin.y) * r.invDir.y * kFarScale;
    lo = t0 > lo ? t0 : lo;
    hi = t1 < hi ? t1 : hi;
    t0 = (b[r.sign[2]].z - r.origin.z) * r.invDir.z;
    t1 = (b[1 - r.sign[2]].z - r.origin.z) * r.invDir.z * kFarScale;
    lo = t0 > lo ? t0 : lo;
    hi = t1 < hi ? t1 : hi;
    tEntry = lo;
    return lo <= hi;
}

/// Williams et al. ray/box slab test; true when [tmin, tmax] overlaps the box's span on the ray.
inline bool intersectSlabs(const Aabb& b, const Ray& r, float tmin, float tmax) {
    float tEntry;
    return intersectSlabs(b, r, tmin, tmax, tEntry);
}

/// Luminance of a linear Rec.709 colour.
inline float luminance(const Color& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

}  // namespace rs
