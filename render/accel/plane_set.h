// The unbounded planes, tested outside any tree four at a time (thesis 3.1, 4.1): the one
// place every engine tests planes.
#pragma once

#include "accel/primitive.h"
#include "core/math.h"

#include <vector>

namespace rs {

class PlaneSet {
public:
    PlaneSet() = default;
    explicit PlaneSet(const std::vector<PlanePrimitive>& planes);

    /// The nearest plane with t in (tmin, tmax): shrinks tmax to it and returns its index into
    /// the planes, or -1. Scanning in order with a strict < keeps the first of equally near
    /// planes.
    int closest(const Vec3& origin, const Vec3& dir, float tmin, float& tmax) const;
    int closest(const Ray& ray, float tmin, float& tmax) const {
        return closest(ray.origin, ray.dir, tmin, tmax);
    }
    /// True when a plane lies within (tmin, tmax).
    bool any(const Vec3& origin, const Vec3& dir, float tmin, float tmax) const;
    bool any(const Ray& ray, float tmin, float tmax) const { return any(ray.origin, ray.dir, tmin, tmax); }
    bool empty() const { return blocks_.empty(); }

private:
    /// Four planes as structure-of-arrays; padding lanes have a zero normal (never hit).
    struct Block {
        Float4 px, py, pz, nx, ny, nz;
    };
    std::vector<Block> blocks_;
};

}  // namespace rs
