// The thesis's engine: a binned-SAH AABB BVH with the Williams et al. slab test, refitted
// bottom-up on moves (thesis 3.1, 3.2), planes outside it; a few world spheres are tested flat
// instead.
#pragma once

#include <vector>

#include "accel/bvh.h"
#include "accel/flat_set.h"
#include "accel/ray_engine.h"

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
    bool testsFlat() const { return flatOnly_; }

private:
    /// The flat set from the primitives and planes; after any change to them.
    void prepareFlat();

    SceneGeometry geometry_;
    Bvh bvh_;
    FlatSet flat_;           ///< The planes, and the spheres too when flatOnly_.
    bool flatOnly_ = false;  ///< The bounded objects are a few world spheres: no walk.
};

}  // namespace rs
