// The immutable, render-ready snapshot of a document: world-space shapes, BVH, lights, materials.
#pragma once

#include "accel/bvh.h"
#include "accel/mesh_accel.h"
#include "geometry/shapes.h"
#include "scene/document.h"
#include "snapshot/camera_model.h"
#include "snapshot/light_buffer.h"

#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace rs {

/// Material with its weights resolved for the illumination equation.
struct CompiledMaterial {
    Color color;
    float diffuse, specular, shininess, reflectivity, transparency, ior;
    float localWeight;  ///< 1 - reflectivity - transparency.
    /// R.V below which specular * (R.V)^shininess < 1e-7: far below a float colour's
    /// resolution, so the costly pow is skipped there (the same on every render path).
    float specularCutoff;
};

/// A light as the integrator needs it: position, radius (0 for a point) and intensity * colour.
struct CompiledLight {
    Vec3 position;
    float radius;
    Color power;
    ObjectId id;
};

/// Object-to-world transform of a shape that is tested in its own frame.
struct Frame {
    Mat4 objectFromWorld;
    Mat3 dirToObject;    ///< Linear part of objectFromWorld.
    Mat3 normalToWorld;  ///< Inverse transpose of the world-from-object linear part.
};

/// A mesh instance: the shared triangle BVH plus the instance's frame (always present).
struct MeshShape {
    std::shared_ptr<const MeshAccel> accel;
};

/// The closed set of bounded render shapes.
using BoundedShape = std::variant<SphereShape, RectangleShape, BoxShape, MeshShape>;

/// One bounded object of the snapshot. Without a frame the shape is stored in world space.
struct Primitive {
    BoundedShape shape;
    bool hasFrame = false;
    Frame frame;
    uint32_t material = 0;
    ObjectId id = kNoObject;
    Aabb worldBounds;
};

/// An unbounded plane, tested outside the BVH (thesis 3.1).
struct PlanePrimitive {
    PlaneShape shape;
    uint32_t material;
    ObjectId id;
};

/// What a ray hit: where, the unit outward normal, material and the object's id.
struct SurfaceHit {
    float t;
    Vec3 n;
    uint32_t material;
    ObjectId id;
};

/// Four planes as structure-of-arrays for the ray queries, so one SIMD pass gives four
/// distances (thesis 4.1: planes tested one by one cost 22%). Padding lanes: zero normal.
struct PlaneBlock4 {
    Float4 px, py, pz, nx, ny, nz;
};

/// Four world-space spheres as structure-of-arrays for the ray queries. Padding lanes have a
/// NaN radius2, so their discriminant is NaN and they never hit.
struct SphereBlock4 {
    Float4 cx, cy, cz, radius2;
    float radius[4];
    uint32_t prim[4];  ///< Index into primitives().
};

/// The planes and (when the scene is tested flat) spheres that rays from one origin inside a
/// cone can hit, in scene order: a tile's camera rays test only these (CompiledScene::cull).
/// Invalid when the scene has more than fits; then every ray tests everything.
struct RaySubset {
    static constexpr int kMaxPlaneBlocks = 8;
    static constexpr int kMaxSphereBlocks = 4;
    PlaneBlock4 planes[kMaxPlaneBlocks];
    uint32_t planeIndex[4 * kMaxPlaneBlocks];  ///< Index into planes() of each lane.
    SphereBlock4 spheres[kMaxSphereBlocks];
    int planeBlocks = 0;
    int sphereBlocks = 0;
    bool valid = false;
};

/// Render-ready snapshot. Built by value from a document; holds no reference into it, so the
/// document can be edited while workers trace an older snapshot.
class CompiledScene {
public:
    /// Compiles `doc`. Meshes must already be loaded (MeshGeometry::data); a mesh object
    /// without data is skipped. Mesh BVHs of `previous` are reused when the mesh is the same.
    explicit CompiledScene(const SceneDocument& doc, const CompiledScene* previous = nullptr);

    /// A copy with the listed objects recompiled from `doc` and the BVH refitted bottom-up
    /// instead of rebuilt (thesis 3.2). Material definitions are recompiled too. Only valid
    /// when those objects kept their kind and visibility, and the material list its names and
    /// order; callers fall back to the constructor otherwise.
    CompiledScene refitted(const SceneDocument& doc, const std::vector<ObjectId>& moved) const;
    /// A copy where object `id` is traced as its world bounding box (box proxy while moving).
    CompiledScene withBoxProxy(ObjectId id) const;

    /// Index into primitives() of a bounded object, or -1 (planes, hidden or unknown ids).
    int primitiveIndex(ObjectId id) const;
    /// World bounds of a bounded object; empty for planes, hidden or unknown ids.
    Aabb objectBounds(ObjectId id) const;

    /// Closest hit with t in (tmin, tmax).
    bool intersect(const Ray& ray, float tmin, float tmax, SurfaceHit& hit) const;
    /// The same closest hit for a ray from `subset`'s origin and cone, testing fewer shapes.
    bool intersect(const Ray& ray, float tmin, float tmax, SurfaceHit& hit,
                   const RaySubset* subset) const;
    /// Fills `out` with what rays from `origin` within `halfAngle` of unit `axis` can hit at
    /// t > 0 (conservatively: a shape left out cannot give a hit in any such ray's exact test).
    void cull(const Vec3& origin, const Vec3& axis, float halfAngle, RaySubset& out) const;
    /// True when anything lies on the ray with t in (tmin, tmax) (shadow rays).
    bool occluded(const Ray& ray, float tmin, float tmax) const;
    /// occluded() for a shadow ray toward light `light` cast as WhittedIntegrator does: from
    /// a shading point p offset by epsilon() along the unit normal, toward a point of the light
    /// (unit `dir`), stopping epsilon() short of it; tmin >= 0. Same answer, but only the
    /// objects in the light buffer cell of the ray's origin are tested.
    bool occludedToLight(std::size_t light, const Vec3& origin, const Vec3& dir, float tmin,
                         float tmax) const;

    const CameraModel& camera() const { return camera_; }
    const RenderSettings& settings() const { return settings_; }
    const std::vector<CompiledMaterial>& materials() const { return materials_; }
    const std::vector<CompiledLight>& lights() const { return lights_; }
    const std::vector<Primitive>& primitives() const { return primitives_; }
    const std::vector<PlanePrimitive>& planes() const { return planes_; }
    const Bvh& bvh() const { return bvh_; }
    /// Ray offset that avoids self-intersection, scaled to the scene's size and rounded to a
    /// power of two, so small edits keep it (and so every unchanged pixel) bit-identical.
    float epsilon() const { return epsilon_; }
    /// Bounds of everything bounded, lights included.
    const Aabb& sceneBounds() const { return sceneBounds_; }

    // The query layout, for tracers that test many rays at once (PacketTracer).
    /// True when the bounded objects are a few world spheres, tested without the BVH.
    bool testsFlat() const { return flat_; }
    /// planes() four at a time.
    const std::vector<PlaneBlock4>& planeBlocks() const { return planeBlocks_; }
    /// primitives() four at a time, only when testsFlat().
    const std::vector<SphereBlock4>& sphereBlocks() const { return sphereBlocks_; }
    /// The sphere of each primitive, only when testsFlat().
    const std::vector<SphereShape>& flatSpheres() const { return flatSpheres_; }
    /// The shadow-ray candidates around light `light` (index into lights()), or null.
    const LightBuffer* lightBuffer(std::size_t light) const {
        return light < lightBuffers_.size() ? &lightBuffers_[light] : nullptr;
    }

private:
    bool intersectPrimitive(const Primitive& p, const Ray& ray, float tmin, float tmax,
                            ShapeHit& hit) const;
    bool intersectFlat(const Ray& ray, float tmin, float tmax, SurfaceHit& hit, bool found,
                       const SphereBlock4* blocks, std::size_t count) const;
    bool occludedFlat(const Ray& ray, float tmin, float tmax) const;
    bool occludedByPlanes(const Ray& ray, float tmin, float tmax) const;
    /// Fills the query-only arrays below from planes_ and primitives_; call after changing them.
    void prepareQueries();
    void computeEpsilon();

    CameraModel camera_;
    RenderSettings settings_;
    std::vector<CompiledMaterial> materials_;
    std::vector<CompiledLight> lights_;
    std::vector<Primitive> primitives_;
    std::vector<PlanePrimitive> planes_;
    Bvh bvh_;
    // Query-only copies (prepareQueries). When the bounded primitives are a few world spheres,
    // testing them all four at a time beats the BVH walk (flat_).
    std::vector<PlaneBlock4> planeBlocks_;
    bool flat_ = false;
    std::vector<SphereBlock4> sphereBlocks_;  ///< Only when flat_.
    std::vector<SphereShape> flatSpheres_;    ///< primitives_'s spheres, only when flat_.
    /// One per light when there are few enough bounded objects (kLightBufferLimit), else none.
    std::vector<LightBuffer> lightBuffers_;
    float epsilon_ = 1e-4f;
    Aabb sceneBounds_;
};

}  // namespace rs
