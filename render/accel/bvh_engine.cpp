// The built-in engine's queries: a few world spheres and the planes eight rays at a time
// (FlatSet), else the BVH walk with the planes four at a time.
#include "accel/bvh_engine.h"

#include <cmath>
#include <limits>

namespace rs {

namespace {

inline Ray rayAt(const RayBatch& rays, std::size_t i) {
    return Ray::make(Vec3(rays.ox[i], rays.oy[i], rays.oz[i]),
                     Vec3(rays.dx[i], rays.dy[i], rays.dz[i]));
}

}  // namespace

BvhEngine::BvhEngine(const SceneGeometry& geometry) : geometry_(geometry) {
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
    flatOnly_ = FlatSet::suits(prims);
    flat_ = FlatSet(*geometry_.planes, flatOnly_ ? &prims : nullptr);
}

void BvhEngine::closestHit(const RayBatch& rays, const HitBatch& hits) const {
    // Planes (and a small scene's spheres) eight rays at a time; in a closed room almost
    // every ray hits a plane, and its t bounds the walk.
    flat_.closestHit(rays, hits);
    if (flatOnly_) return;
    const auto& prims = *geometry_.primitives;
    for (std::size_t i = 0; i < rays.count; ++i) {
        const Ray ray = rayAt(rays, i);
        float tmax = hits.slot[i] != kNoSlot ? hits.t[i] : rays.tmax[i];
        ShapeHit sh;
        bvh_.closestHit(ray, 0.0f, tmax, [&](uint32_t index, float& tmaxRef) {
            if (!intersectPrimitive(prims[index], ray, 0.0f, tmaxRef, sh)) return false;
            tmaxRef = sh.t;
            hits.t[i] = sh.t;
            hits.nx[i] = sh.n.x, hits.ny[i] = sh.n.y, hits.nz[i] = sh.n.z;
            hits.slot[i] = index;
            return true;
        });
    }
}

void BvhEngine::anyHit(const RayBatch& rays, uint8_t* occluded) const {
    if (flatOnly_) return flat_.anyHit(rays, occluded);
    // Bounded objects first: a shadow ray toward a light inside a room never reaches a wall.
    const auto& prims = *geometry_.primitives;
    for (std::size_t i = 0; i < rays.count; ++i) {
        const Ray ray = rayAt(rays, i);
        const float tmax = rays.tmax[i];
        ShapeHit sh;
        occluded[i] = bvh_.anyHit(ray, 0.0f, tmax, [&](uint32_t index) {
            return intersectPrimitive(prims[index], ray, 0.0f, tmax, sh);
        });
    }
    flat_.anyHit(rays, occluded, /*skipBlocked=*/true);
}

}  // namespace rs
