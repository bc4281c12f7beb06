// Engine names, single-ray queries over the batch interface, and the engine factory.
#include "accel/ray_engine.h"

#include "accel/bvh_engine.h"
#include "accel/embree_engine.h"

namespace rs {

const char* engineName(EngineKind kind) {
    return kind == EngineKind::Embree ? "embree" : "builtin";
}

bool parseEngineKind(std::string_view text, EngineKind& kind) {
    if (text == "embree") {
        kind = EngineKind::Embree;
        return true;
    }
    if (text == "builtin") {
        kind = EngineKind::Builtin;
        return true;
    }
    return false;
}

bool RayEngine::closestHit(const Ray& ray, float tmax, EngineHit& hit) const {
    const RayBatch rays{&ray.origin.x, &ray.origin.y, &ray.origin.z, &ray.dir.x,
                        &ray.dir.y,    &ray.dir.z,    &tmax,         1};
    hit = EngineHit{};
    closestHit(rays, HitBatch{&hit.t, &hit.n.x, &hit.n.y, &hit.n.z, &hit.slot});
    return hit.slot != kNoSlot;
}

bool RayEngine::anyHit(const Ray& ray, float tmax) const {
    const RayBatch rays{&ray.origin.x, &ray.origin.y, &ray.origin.z, &ray.dir.x,
                        &ray.dir.y,    &ray.dir.z,    &tmax,         1};
    uint8_t occluded = 0;
    anyHit(rays, &occluded);
    return occluded != 0;
}

std::shared_ptr<const RayEngine> buildEngine(EngineKind kind, const SceneGeometry& geometry,
                                             const RayEngine* previous) {
    if (kind == EngineKind::Embree)
        return std::make_shared<const EmbreeEngine>(geometry,
                                                    dynamic_cast<const EmbreeEngine*>(previous));
    return std::make_shared<const BvhEngine>(geometry);
}

}  // namespace rs
