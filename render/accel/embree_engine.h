// The production engine: Embree 3. Meshes are triangle scenes of their own, placed by
// instances, so moving one re-commits only the top level; world-space spheres are Embree's
// own (SIMD) spheres; boxes, rectangles and spheres in a frame of their own are user
// geometry calling the project's shape tests; planes stay outside (FlatSet). A scene of a
// few world spheres is answered by the flat set alone, which costs less there.
#pragma once

#include "accel/flat_set.h"
#include "accel/ray_engine.h"

#include <embree3/rtcore.h>

#include <memory>
#include <vector>

namespace rs {

/// One mesh's committed Embree triangle scene, shared by every engine that shows the mesh.
struct EmbreeMesh;

class EmbreeEngine final : public RayEngine {
public:
    /// Builds the top level over `geometry`, reusing `previous`'s mesh scenes (may be null).
    EmbreeEngine(const SceneGeometry& geometry, const EmbreeEngine* previous);
    ~EmbreeEngine() override;
    EmbreeEngine(const EmbreeEngine&) = delete;
    EmbreeEngine& operator=(const EmbreeEngine&) = delete;

    EngineKind kind() const override { return EngineKind::Embree; }
    void closestHit(const RayBatch& rays, const HitBatch& hits) const override;
    void anyHit(const RayBatch& rays, uint8_t* occluded) const override;
    std::shared_ptr<const RayEngine> updated(const SceneGeometry& geometry,
                                             std::span<const uint32_t> moved) const override;

    // For the user-geometry callbacks (embree_engine.cpp).
    const Primitive& userPrimitive(unsigned primID) const {
        return (*geometry_.primitives)[userPrims_[primID]];
    }
    const std::vector<Primitive>& primitives() const { return *geometry_.primitives; }

private:
    SceneGeometry geometry_;
    FlatSet planes_;         ///< The planes, and the spheres too when flatOnly_.
    bool flatOnly_ = false;  ///< A few world spheres only: no Embree scene is traversed.
    RTCScene scene_ = nullptr;
    unsigned userGeomID_ = RTC_INVALID_GEOMETRY_ID;
    unsigned sphereGeomID_ = RTC_INVALID_GEOMETRY_ID;
    std::vector<uint32_t> spherePrims_;    ///< Primitive index of each sphere primID.
    std::vector<uint32_t> userPrims_;      ///< Primitive index of each user-geometry primID.
    std::vector<uint32_t> instancePrims_;  ///< Primitive index of each geomID (meshes only).
    std::vector<std::shared_ptr<const EmbreeMesh>> meshes_;  ///< Per primitive; null if no mesh.
};

}  // namespace rs
