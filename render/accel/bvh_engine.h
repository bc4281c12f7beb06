// The thesis's engine: a binned-SAH AABB BVH with the Williams et al. slab test, refitted
// bottom-up on moves (thesis 3.1, 3.2), planes outside it, and light buffers for shadows.
#pragma once

#include "accel/bvh.h"
#include "accel/plane_set.h"
#include "accel/ray_engine.h"
#include "snapshot/light_buffer.h"

#include <vector>

namespace rs {

class BvhEngine final : public RayEngine {
public:
    explicit BvhEngine(const SceneGeometry& geometry);

    EngineKind kind() const override { return EngineKind::Builtin; }
    void closestHit(const RayBatch& rays, const HitBatch& hits) const override;
    void anyHit(const RayBatch& rays, uint8_t* occluded) const override;
    std::shared_ptr<const RayEngine> updated(const SceneGeometry& geometry,
                                             std::span<const uint32_t> moved) const override;

    const Bvh& bvh() const { return bvh_; }
    /// True when the bounded objects are a few world spheres, tested without the BVH.
    bool testsFlat() const { return flat_; }
    /// The shadow-ray candidates around light `light`, or null (only for flat scenes).
    const LightBuffer* lightBuffer(std::size_t light) const {
        return light < lightBuffers_.size() ? &lightBuffers_[light] : nullptr;
    }

private:
    /// Four world spheres as structure-of-arrays. Padding lanes have a NaN radius2.
    struct SphereBlock {
        Float4 cx, cy, cz, radius2;
        uint32_t prim[4];
    };

    bool closest(const Ray& ray, float tmax, EngineHit& hit) const;
    bool occluded(const Ray& ray, float tmax) const;
    bool occludedToLight(uint32_t light, const Ray& ray, float tmax) const;
    /// Calls onHit(t, prim) for each flat sphere hit within (0, tmax) until it returns true.
    template <class OnHit>
    bool forEachFlatHit(const Ray& ray, float& tmax, OnHit&& onHit) const;
    bool closestFlat(const Ray& ray, float& tmax, EngineHit& hit) const;
    bool occludedFlat(const Ray& ray, float tmax) const;
    /// The flat blocks and light buffers from the primitives; after any change to them.
    void prepareFlat();

    SceneGeometry geometry_;
    PlaneSet planes_;
    Bvh bvh_;
    bool flat_ = false;
    std::vector<SphereBlock> sphereBlocks_;
    std::vector<LightBuffer> lightBuffers_;
};

}  // namespace rs
