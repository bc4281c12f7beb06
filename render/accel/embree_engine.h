// The production engine: Embree 3. Meshes are triangle scenes of their own, placed by
// instances, so moving one re-commits only the top level; world-space spheres are Embree's
// own (SIMD) spheres; boxes, rectangles and spheres in a frame of their own are user
// geometry calling the project's shape tests; planes stay outside (FlatSet). A scene of a
// few world spheres is answered by the flat set alone, which costs less there.
#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <vector>

#include "accel/flat_set.h"
#include "accel/ray_engine.h"

namespace rs {

/// One mesh's committed Embree triangle scene, shared by every engine that shows the mesh.
struct EmbreeMesh;
/// A committed Embree scene of world spheres that have not moved lately, shared by the
/// engines of consecutive refits (embree_engine.cpp).
struct EmbreeStillSpheres;

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
    /// A scene of many world spheres keeps the ones that have not moved in a committed scene
    /// shared with this engine, instanced once; only the moved ones (kMaxMovedSpheres at
    /// most) and the rest of the top level are committed anew. Otherwise as the constructor.
    std::shared_ptr<const RayEngine> updated(const SceneGeometry& geometry,
                                             std::span<const uint32_t> moved) const override;
    /// How many world spheres this engine answers through the scene updated() kept still
    /// (0 when it did not split them).
    std::size_t stillSpheres() const;
    /// World spheres from which updated() keeps the unmoved ones apart.
    static constexpr std::size_t kSplitSpheres = 4096;
    static constexpr std::size_t kMaxMovedSpheres = 64;

    // For the user-geometry callbacks (embree_engine.cpp).
    const Primitive& userPrimitive(unsigned primID) const {
        return (*geometry_.primitives)[userPrims_[primID]];
    }
    const std::vector<Primitive>& primitives() const { return *geometry_.primitives; }

private:
    /// updated()'s engine: the world spheres `moved` (sorted primitive indices) in the top
    /// level, every other one in `still`.
    EmbreeEngine(const SceneGeometry& geometry, const EmbreeEngine* previous,
                 std::vector<uint32_t> moved, std::shared_ptr<const EmbreeStillSpheres> still);
    /// Attaches the mesh instances, the user geometry and the world spheres the top level
    /// holds (those in `moved` only, when `still`) to scene_, and commits it.
    void buildTopLevel(const EmbreeEngine* previous, const std::vector<uint32_t>* moved);

    SceneGeometry geometry_;
    FlatSet planes_;         ///< The planes, and the spheres too when flatOnly_.
    bool flatOnly_ = false;  ///< A few world spheres only: no Embree scene is traversed.
    bool hasPlanes_ = false;
    RTCScene scene_ = nullptr;
    unsigned userGeomID_ = RTC_INVALID_GEOMETRY_ID;
    unsigned sphereGeomID_ = RTC_INVALID_GEOMETRY_ID;
    std::vector<uint32_t> spherePrims_;  ///< Primitive index of each sphere primID.
    std::vector<uint32_t> userPrims_;    ///< Primitive index of each user-geometry primID.
    std::shared_ptr<const EmbreeStillSpheres> still_;  ///< Null unless updated() split them.
    unsigned stillInstID_ = RTC_INVALID_GEOMETRY_ID;   ///< still_'s instance in scene_.
    /// What a hit on one mesh instance needs, by geomID (meshes only; slot kNoSlot elsewhere).
    struct MeshInstance {
        uint32_t slot = kNoSlot;  ///< Index into the primitives.
        const MeshAccel* mesh = nullptr;
        const Frame* frame = nullptr;
        bool smooth = false;     ///< Normals interpolated (MeshAccel::normal).
        bool scaleOnly = false;  ///< The frame's linear part is a positive multiple of 1.

        // Both defined inline in embree_engine.cpp, for the hit loop.
        /// Ray i's distance to the plane through `v0` with normal `ng` (object space), for
        /// Embree's hit at `tEmbree` within (0, tmax).
        float distance(const Vec3& ng, const Vec3& v0, const RayBatch& rays, std::size_t i,
                       float tEmbree, float tmax) const;
        /// An object-space normal as the unit world normal.
        Vec3 toWorld(const Vec3& n) const;
    };
    std::vector<MeshInstance> instances_;
    std::vector<std::shared_ptr<const EmbreeMesh>> meshes_;  ///< Per primitive; null if no mesh.
};

}  // namespace rs
