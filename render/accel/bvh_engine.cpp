// The built-in engine's queries: planes four at a time, a few world spheres tested flat,
// the BVH walk for everything else, light buffers for shadow rays of flat scenes.
#include "accel/bvh_engine.h"

#include <cmath>
#include <limits>

namespace rs {

namespace {

/// Up to this many world spheres (and nothing else bounded) are tested flat, without the BVH
/// (measured: the room's 8 spheres, two SIMD blocks, cost less than the walk over 7 nodes).
constexpr std::size_t kFlatLimit = 16;

/// First half of intersect(SphereShape) for four spheres, same operations in the same order;
/// lanes with disc >= 0 are finished one by one with solveRecentredSphere.
struct SpherePrelude {
    Float4 tProj, bHalf, c, disc;
};

template <class Block>
inline SpherePrelude spherePrelude(const Block& s, const Ray& ray, float a) {
    SpherePrelude p;
    p.tProj = ((s.cx - ray.origin.x) * ray.dir.x + (s.cy - ray.origin.y) * ray.dir.y +
               (s.cz - ray.origin.z) * ray.dir.z) /
              a;
    const Float4 fx = (ray.origin.x - s.cx) + p.tProj * ray.dir.x;
    const Float4 fy = (ray.origin.y - s.cy) + p.tProj * ray.dir.y;
    const Float4 fz = (ray.origin.z - s.cz) + p.tProj * ray.dir.z;
    p.bHalf = fx * ray.dir.x + fy * ray.dir.y + fz * ray.dir.z;
    p.c = (fx * fx + fy * fy + fz * fz) - s.radius2;
    p.disc = p.bHalf * p.bHalf - a * p.c;
    return p;
}

inline Ray rayAt(const RayBatch& rays, std::size_t i) {
    return Ray::make(Vec3(rays.ox[i], rays.oy[i], rays.oz[i]),
                     Vec3(rays.dx[i], rays.dy[i], rays.dz[i]));
}

}  // namespace

BvhEngine::BvhEngine(const SceneGeometry& geometry) : geometry_(geometry), planes_(*geometry.planes) {
    const auto& prims = *geometry_.primitives;
    std::vector<Aabb> boxes;
    boxes.reserve(prims.size());
    for (const Primitive& p : prims) {
        boxes.push_back(p.worldBounds);
        // Triangle BVHs are built here, on the thread that builds the snapshot, never by a
        // worker's first query.
        if (const auto* m = std::get_if<MeshShape>(&p.shape)) m->accel->ensureBvh();
    }
    bvh_.build(boxes, 2);
    prepareFlat();
}

std::shared_ptr<const RayEngine> BvhEngine::updated(const SceneGeometry& geometry,
                                                    std::span<const uint32_t> moved) const {
    auto out = std::make_shared<BvhEngine>(*this);
    out->geometry_ = geometry;
    out->planes_ = PlaneSet(*geometry.planes);
    const auto& prims = *geometry.primitives;
    for (uint32_t index : moved) {
        if (const auto* m = std::get_if<MeshShape>(&prims[index].shape)) m->accel->ensureBvh();
        out->bvh_.refitPrimitive(index, prims[index].worldBounds);
    }
    out->prepareFlat();
    return out;
}

void BvhEngine::prepareFlat() {
    const auto& prims = *geometry_.primitives;
    // Flat only when every primitive is a world sphere: measured, testing boxes and meshes on
    // every ray is 12-27% slower than the BVH walk.
    flat_ = prims.size() <= kFlatLimit;
    for (const Primitive& p : prims)
        flat_ = flat_ && !p.hasFrame && std::holds_alternative<SphereShape>(p.shape);
    sphereBlocks_.clear();
    lightBuffers_.clear();
    if (!flat_) return;
    std::vector<BoundingSphere> spheres;
    for (std::size_t i = 0; i < prims.size(); ++i) {
        const SphereShape& s = std::get<SphereShape>(prims[i].shape);
        spheres.push_back({s.center, s.radius});
        const int k = int(i % 4);
        if (k == 0) {
            SphereBlock& b = sphereBlocks_.emplace_back();
            b.radius2 = Float4{} + std::numeric_limits<float>::quiet_NaN();
        }
        SphereBlock& b = sphereBlocks_.back();
        b.cx[k] = s.center.x, b.cy[k] = s.center.y, b.cz[k] = s.center.z;
        b.radius2[k] = s.radius * s.radius;
        b.prim[k] = uint32_t(i);
    }
    // Light buffers where they pay (measured): with a few world spheres a shadow ray then
    // tests about one shape. With boxes or meshes the BVH's any-hit walk was faster.
    std::vector<BufferPlane> planes;
    for (const PlanePrimitive& p : *geometry_.planes) planes.push_back({p.shape.point, p.shape.normal});
    for (const LightBounds& l : geometry_.lights)
        lightBuffers_.emplace_back(l.center, l.radius + 4.0f * geometry_.epsilon, spheres, planes);
}

void BvhEngine::closestHit(const RayBatch& rays, const HitBatch& hits) const {
    for (std::size_t i = 0; i < rays.count; ++i) {
        EngineHit h;
        closest(rayAt(rays, i), rays.tmax[i], h);
        hits.t[i] = h.t;
        hits.nx[i] = h.n.x, hits.ny[i] = h.n.y, hits.nz[i] = h.n.z;
        hits.slot[i] = h.slot;
    }
}

void BvhEngine::anyHit(const RayBatch& rays, uint8_t* occludedOut) const {
    for (std::size_t i = 0; i < rays.count; ++i) {
        const Ray ray = rayAt(rays, i);
        occludedOut[i] = rays.light ? occludedToLight(rays.light[i], ray, rays.tmax[i])
                                    : occluded(ray, rays.tmax[i]);
    }
}

bool BvhEngine::closest(const Ray& ray, float tmax, EngineHit& hit) const {
    constexpr float tmin = 0.0f;
    // Planes first: in a closed room almost every ray hits one, and its t culls the rest.
    bool found = false;
    if (const int plane = planes_.closest(ray, tmin, tmax); plane >= 0) {
        hit = {tmax, (*geometry_.planes)[std::size_t(plane)].shape.normal,
               kPlaneSlot | uint32_t(plane)};
        found = true;
    }
    if (flat_) return closestFlat(ray, tmax, hit) || found;
    const auto& prims = *geometry_.primitives;
    ShapeHit sh;
    found |= bvh_.closestHit(ray, tmin, tmax, [&](uint32_t index, float& tmaxRef) {
        if (!intersectPrimitive(prims[index], ray, tmin, tmaxRef, sh)) return false;
        tmaxRef = sh.t;
        hit = {sh.t, sh.n, index};
        return true;
    });
    return found;
}

template <class OnHit>
bool BvhEngine::forEachFlatHit(const Ray& ray, float& tmax, OnHit&& onHit) const {
    const float a = glm::dot(ray.dir, ray.dir);
    for (const SphereBlock& b : sphereBlocks_) {
        const SpherePrelude p = spherePrelude(b, ray, a);
        for (int k = 0; k < 4; ++k) {
            float t, offset;
            if (p.disc[k] >= 0.0f &&
                solveRecentredSphere(a, p.tProj[k], p.bHalf[k], p.c[k], 0.0f, tmax, t, offset) &&
                onHit(t, b.prim[k]))
                return true;
        }
    }
    return false;
}

bool BvhEngine::closestFlat(const Ray& ray, float& tmax, EngineHit& hit) const {
    // The sphere normal is only worked out for the winner, once, after all tests.
    uint32_t best = kNoSlot;
    forEachFlatHit(ray, tmax, [&](float t, uint32_t prim) {
        tmax = t;
        best = prim;
        return false;  // keep looking for a nearer one
    });
    if (best == kNoSlot) return false;
    // The winner again with intersect(SphereShape) itself: the same t, and its normal.
    ShapeHit sh;
    const SphereShape& s = std::get<SphereShape>((*geometry_.primitives)[best].shape);
    if (!rs::intersect(s, ray, 0.0f, kInfinity, sh)) return false;
    hit = {tmax, sh.n, best};
    return true;
}

bool BvhEngine::occluded(const Ray& ray, float tmax) const {
    // Bounded objects first: a shadow ray toward a light inside a room never reaches a wall.
    if (flat_) {
        if (occludedFlat(ray, tmax)) return true;
    } else {
        const auto& prims = *geometry_.primitives;
        ShapeHit sh;
        if (bvh_.anyHit(ray, 0.0f, tmax, [&](uint32_t index) {
                return intersectPrimitive(prims[index], ray, 0.0f, tmax, sh);
            }))
            return true;
    }
    return planes_.any(ray, 0.0f, tmax);
}

bool BvhEngine::occludedFlat(const Ray& ray, float tmax) const {
    return forEachFlatHit(ray, tmax, [](float, uint32_t) { return true; });
}

bool BvhEngine::occludedToLight(uint32_t light, const Ray& ray, float tmax) const {
    if (light >= lightBuffers_.size()) return occluded(ray, tmax);
    // The cell's candidates are world spheres and planes, tested with the same shape tests.
    const auto& prims = *geometry_.primitives;
    const auto& planes = *geometry_.planes;
    ShapeHit sh;
    const int hit = lightBuffers_[light].anyHit(ray.origin, [&](uint32_t item) {
        if (item & LightBuffer::kPlaneBit)
            return intersect(planes[item & ~LightBuffer::kPlaneBit].shape, ray, 0.0f, tmax, sh);
        return intersect(std::get<SphereShape>(prims[item].shape), ray, 0.0f, tmax, sh);
    });
    return hit < 0 ? occluded(ray, tmax) : hit == 1;
}

}  // namespace rs
