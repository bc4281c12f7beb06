// The snapshot's ray queries: planes and spheres four at a time, the BVH for the rest.
#include "snapshot/compiled_scene.h"

#include <cmath>
#include <limits>

namespace rs {

namespace {

/// Tests one bounded shape against a ray given in the shape's own frame.
bool intersectShape(const BoundedShape& shape, const Ray& ray, float tmin, float tmax,
                    ShapeHit& hit) {
    return std::visit(
        [&](const auto& s) -> bool {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, MeshShape>) {
                return s.accel->intersect(ray, tmin, tmax, hit);
            } else {
                return rs::intersect(s, ray, tmin, tmax, hit);
            }
        },
        shape);
}

}  // namespace

bool CompiledScene::intersectPrimitive(const Primitive& p, const Ray& ray, float tmin, float tmax,
                                       ShapeHit& hit) const {
    if (!p.hasFrame) return intersectShape(p.shape, ray, tmin, tmax, hit);
    // Test in the object's frame: t is unchanged because the direction is mapped linearly too.
    const Frame& f = p.frame;
    const Ray local = Ray::make(Vec3(f.objectFromWorld * glm::vec4(ray.origin, 1.0f)),
                                f.dirToObject * ray.dir);
    if (!intersectShape(p.shape, local, tmin, tmax, hit)) return false;
    hit.n = glm::normalize(f.normalToWorld * hit.n);
    return true;
}

// Ray queries: helpers for the four-wide plane and sphere tests.
namespace {

/// Up to this many world spheres (and nothing else bounded) are tested flat, without the BVH
/// (measured: the room's 8 spheres, two SIMD blocks, cost less than the walk over 7 nodes).
constexpr std::size_t kFlatLimit = 16;

/// Distances to four planes, with the operations of intersect(PlaneShape) in the same order, so
/// t is bit-identical. A ray parallel to a plane gets +-inf or NaN here, which the open-range
/// test rejects like the denom == 0 branch there (tmax is never above infinity).
inline Float4 planeDistances(const PlaneBlock4& b, const Ray& ray) {
    const Float4 denom = ray.dir.x * b.nx + ray.dir.y * b.ny + ray.dir.z * b.nz;
    const Float4 num = (b.px - ray.origin.x) * b.nx + (b.py - ray.origin.y) * b.ny +
                       (b.pz - ray.origin.z) * b.nz;
    return num / denom;
}

/// First half of intersect(SphereShape) for four spheres, same operations in the same order;
/// lanes with disc >= 0 are finished one by one with solveRecentredSphere.
struct SpherePrelude {
    Float4 tProj, fx, fy, fz, bHalf, c, disc;
};

inline SpherePrelude spherePrelude(const SphereBlock4& s, const Ray& ray, float a) {
    SpherePrelude p;
    p.tProj = ((s.cx - ray.origin.x) * ray.dir.x + (s.cy - ray.origin.y) * ray.dir.y +
               (s.cz - ray.origin.z) * ray.dir.z) /
              a;
    p.fx = (ray.origin.x - s.cx) + p.tProj * ray.dir.x;
    p.fy = (ray.origin.y - s.cy) + p.tProj * ray.dir.y;
    p.fz = (ray.origin.z - s.cz) + p.tProj * ray.dir.z;
    p.bHalf = p.fx * ray.dir.x + p.fy * ray.dir.y + p.fz * ray.dir.z;
    p.c = (p.fx * p.fx + p.fy * p.fy + p.fz * p.fz) - s.radius2;
    p.disc = p.bHalf * p.bHalf - a * p.c;
    return p;
}

}  // namespace

void CompiledScene::prepareQueries() {
    planeBlocks_.assign((planes_.size() + 3) / 4, PlaneBlock4{});
    for (std::size_t i = 0; i < planes_.size(); ++i) {
        PlaneBlock4& b = planeBlocks_[i / 4];
        const PlaneShape& s = planes_[i].shape;
        const int k = int(i % 4);
        b.px[k] = s.point.x, b.py[k] = s.point.y, b.pz[k] = s.point.z;
        b.nx[k] = s.normal.x, b.ny[k] = s.normal.y, b.nz[k] = s.normal.z;
    }
    // Flat only when every primitive is a world sphere: measured, testing boxes and meshes on
    // every ray (glass-and-mirrors, mesh scenes) is 12-27% slower than the BVH walk.
    sphereBlocks_.clear();
    flat_ = primitives_.size() <= kFlatLimit;
    for (const Primitive& p : primitives_)
        flat_ = flat_ && !p.hasFrame && std::holds_alternative<SphereShape>(p.shape);
    if (!flat_) return;
    for (std::size_t i = 0; i < primitives_.size(); ++i) {
        const SphereShape& s = std::get<SphereShape>(primitives_[i].shape);
        const int k = int(i % 4);
        if (k == 0) {
            SphereBlock4& b = sphereBlocks_.emplace_back();
            b.radius2 = Float4{} + std::numeric_limits<float>::quiet_NaN();
        }
        SphereBlock4& b = sphereBlocks_.back();
        b.cx[k] = s.center.x, b.cy[k] = s.center.y, b.cz[k] = s.center.z;
        b.radius2[k] = s.radius * s.radius;
        b.radius[k] = s.radius;
        b.prim[k] = uint32_t(i);
    }
}

bool CompiledScene::intersect(const Ray& ray, float tmin, float tmax, SurfaceHit& hit) const {
    // Planes first: in a closed room almost every ray hits one, and its t culls the rest.
    // Scanning in order with a strict < keeps the first of equally near planes, as before.
    std::size_t nearestPlane = planes_.size();
    for (std::size_t b = 0; b < planeBlocks_.size(); ++b) {
        const Float4 t = planeDistances(planeBlocks_[b], ray);
        for (int k = 0; k < 4; ++k) {
            if (t[k] > tmin && t[k] < tmax) {
                tmax = t[k];
                nearestPlane = 4 * b + std::size_t(k);
            }
        }
    }
    bool found = false;
    if (nearestPlane < planes_.size()) {
        const PlanePrimitive& p = planes_[nearestPlane];
        hit = {tmax, p.shape.normal, p.material, p.id};
        found = true;
    }
    if (flat_) return intersectFlat(ray, tmin, tmax, hit, found);
    ShapeHit sh;
    found |= bvh_.closestHit(ray, tmin, tmax, [&](uint32_t index, float& tmaxRef) {
        const Primitive& p = primitives_[index];
        if (!intersectPrimitive(p, ray, tmin, tmaxRef, sh)) return false;
        tmaxRef = sh.t;
        hit = {sh.t, sh.n, p.material, p.id};
        return true;
    });
    return found;
}

bool CompiledScene::intersectFlat(const Ray& ray, float tmin, float tmax, SurfaceHit& hit,
                                  bool found) const {
    // The sphere normal is only worked out for the winner, once, after all tests.
    const SphereBlock4* best = nullptr;
    int bestLane = 0;
    float bestOffset = 0.0f;
    const float a = glm::dot(ray.dir, ray.dir);
    for (const SphereBlock4& b : sphereBlocks_) {
        const SpherePrelude p = spherePrelude(b, ray, a);
        for (int k = 0; k < 4; ++k) {
            float t, offset;
            if (p.disc[k] >= 0.0f &&
                solveRecentredSphere(a, p.tProj[k], p.bHalf[k], p.c[k], tmin, tmax, t, offset)) {
                tmax = t;
                best = &b;
                bestLane = k;
                bestOffset = offset;
            }
        }
    }
    if (best) {
        // Recomputed with the operations of intersect(SphereShape), so n is bit-identical.
        const Primitive& p = primitives_[best->prim[bestLane]];
        const SphereShape& s = std::get<SphereShape>(p.shape);
        const float tProj = glm::dot(s.center - ray.origin, ray.dir) / a;
        const Vec3 f = (ray.origin - s.center) + tProj * ray.dir;
        hit = {tmax, (f + bestOffset * ray.dir) / s.radius, p.material, p.id};
        found = true;
    }
    return found;
}

bool CompiledScene::occluded(const Ray& ray, float tmin, float tmax) const {
    // Bounded objects first: a shadow ray toward a light inside a room never reaches a wall.
    if (flat_) {
        if (occludedFlat(ray, tmin, tmax)) return true;
    } else {
        ShapeHit sh;
        if (bvh_.anyHit(ray, tmin, tmax, [&](uint32_t index) {
                return intersectPrimitive(primitives_[index], ray, tmin, tmax, sh);
            }))
            return true;
    }
    for (const PlaneBlock4& b : planeBlocks_) {
        const Float4 t = planeDistances(b, ray);
        for (int k = 0; k < 4; ++k)
            if (t[k] > tmin && t[k] < tmax) return true;
    }
    return false;
}

bool CompiledScene::occludedFlat(const Ray& ray, float tmin, float tmax) const {
    const float a = glm::dot(ray.dir, ray.dir);
    for (const SphereBlock4& b : sphereBlocks_) {
        const SpherePrelude p = spherePrelude(b, ray, a);
        for (int k = 0; k < 4; ++k) {
            float t, offset;
            if (p.disc[k] >= 0.0f &&
                solveRecentredSphere(a, p.tProj[k], p.bHalf[k], p.c[k], tmin, tmax, t, offset))
                return true;
        }
    }
    return false;
}

}  // namespace rs
