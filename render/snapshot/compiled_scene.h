// The immutable, render-ready snapshot of a document: world-space shapes, BVH, lights, materials.
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "accel/primitive.h"
#include "accel/ray_engine.h"
#include "geometry/shapes.h"
#include "scene/document.h"
#include "snapshot/camera_model.h"
#include "snapshot/surface_patterns.h"

namespace rs {

/// Material with its weights resolved for the illumination equation.
struct CompiledMaterial {
    Color color;
    float diffuse, specular, shininess, reflectivity, transparency, ior;
    float localWeight;  ///< 1 - reflectivity - transparency.
    /// R.V below which specular * (R.V)^shininess is negligible (highlightCutoff,
    /// scene/shading_rules.h): the costly pow is skipped there.
    float specularCutoff;
    MaterialPattern pattern;  ///< A checker or an image in place of `color`.
};

/// The environment as the integrator looks it up (scenes/FORMAT.md "environment").
struct CompiledEnvironment {
    bool present = false;
    TextureHandle texture;  ///< Empty when the file could not be opened: "missing" shows.
    float intensity = 1.0f;
    float rotation = 0.0f;  ///< Degrees about +Y.
};

/// How far a directional light's point is placed along its reverse direction: far enough
/// that its rays are parallel to within 1e-4 radians over a scene ten thousand units wide,
/// near enough that a float direction to it is exact to about 1e-7 (scenes/FORMAT.md).
inline constexpr float kSunDistance = 1e8f;

/// A light as the integrator needs it: position, radius (0 for a point) and intensity * colour.
/// A directional light is a point light kSunDistance away (so every shadow ray, dirty-region
/// cone and sample is a point light's); a spot light is a point light whose power falls off
/// outside its cone.
struct CompiledLight {
    Vec3 position;
    float radius;
    Color power;
    ObjectId id;
    bool spot = false;             ///< Power times spotFactor (integrator/light_sampling.h).
    bool sun = false;              ///< A directional light: not part of the scene's bounds.
    Vec3 axis{0.0f, -1.0f, 0.0f};  ///< Spot lights: unit direction from the light to its target.
    float cosFalloff = 0.0f;       ///< Spot lights: cos of the half-angle where power reaches 0.
    float cosRadius = 1.0f;        ///< Spot lights: cos of the half-angle of full power.
};

/// A light as the integrator sees it: a sun becomes a point kSunDistance away, a spot light
/// gets its axis and the cosines of its cone (clamped to [0, 90] degrees, falloff at least
/// the radius). Dirty marking asks the same question of a light's old and new cones.
CompiledLight compileLight(const Light& l);

/// What a ray hit: where, the unit outward normal, material and the object's id.
struct SurfaceHit {
    float t;
    Vec3 n;
    uint32_t material;
    ObjectId id;
};

/// Render-ready snapshot. Built by value from a document; holds no reference into it, so the
/// document can be edited while workers trace an older snapshot.
class CompiledScene {
public:
    /// Compiles `doc` and builds a ray engine of `engine` over it. Meshes must already be
    /// loaded (MeshGeometry::data); a mesh object without data is skipped. Meshes of
    /// `previous` (and its engine's per-mesh structures) are reused when the mesh is the same.
    explicit CompiledScene(const SceneDocument& doc, const CompiledScene* previous = nullptr,
                           EngineKind engine = EngineKind::Embree);

    /// A copy with the listed objects recompiled from `doc` and the engine refitted or
    /// re-committed instead of rebuilt (thesis 3.2). Material definitions are recompiled too.
    /// Only valid when those objects kept their kind, visibility and mesh, and the material
    /// list its names and order; callers fall back to the constructor otherwise.
    CompiledScene refitted(const SceneDocument& doc, const std::vector<ObjectId>& moved) const;
    /// A copy where object `id` is traced as its world bounding box (box proxy while moving).
    CompiledScene withBoxProxy(ObjectId id) const;

    /// Index into primitives() of a bounded object's first primitive, or -1 (planes, hidden
    /// or unknown ids). A mesh with part materials is one primitive per part, adjacent.
    int primitiveIndex(ObjectId id) const;
    /// [first, end) of the object's primitives in primitives(); empty when it has none.
    std::pair<std::size_t, std::size_t> primitiveRange(ObjectId id) const;
    /// World bounds of a bounded object; empty for planes, hidden or unknown ids.
    Aabb objectBounds(ObjectId id) const;

    /// Closest hit with t in (0, tmax), through the engine (picking, tests, single rays).
    bool intersect(const Ray& ray, float tmax, SurfaceHit& hit) const;
    /// True when anything lies on the ray with t in (0, tmax).
    bool occluded(const Ray& ray, float tmax) const;
    /// Material and object id of an engine hit slot (a primitive or a plane).
    void describe(uint32_t slot, uint32_t& material, ObjectId& id) const {
        if (slot & kPlaneSlot) {
            const PlanePrimitive& p = (*planes_)[slot & ~kPlaneSlot];
            material = p.material, id = p.id;
        } else {
            const Primitive& p = (*primitives_)[slot];
            material = p.material, id = p.id;
        }
    }

    const CameraModel& camera() const { return camera_; }
    const RenderSettings& settings() const { return settings_; }
    const std::vector<CompiledMaterial>& materials() const { return materials_; }
    const std::vector<CompiledLight>& lights() const { return lights_; }
    const std::vector<Primitive>& primitives() const { return *primitives_; }
    const std::vector<PlanePrimitive>& planes() const { return *planes_; }
    /// The engine that answers this snapshot's ray queries.
    const RayEngine& engine() const { return *engine_; }
    EngineKind engineKind() const { return engine_->kind(); }
    /// Ray offset that avoids self-intersection, scaled to the scene's size and rounded to a
    /// power of two, so small edits keep it (and so every unchanged pixel) bit-identical.
    float epsilon() const { return epsilon_; }
    /// Bounds of everything bounded, lights included.
    const Aabb& sceneBounds() const { return sceneBounds_; }

    /// What an escaped ray along unit `dir` returns: the environment (filtered over a cone of
    /// full angle `spread`) times its intensity, else the background colour.
    Color environmentColor(const Vec3& dir, float spread) const;
    /// environmentColor of `count` escaped rays at once (directions axis by axis) into
    /// out[0, count), the environment's map for four at a time; `spots`: room for `count`.
    /// Each colour is bit for bit the one environmentColor gives.
    void environmentColors(std::size_t count, const Directions& dirs, float spread,
                           EnvironmentSpot* spots, Color* out) const;
    const CompiledEnvironment& environment() const { return environment_; }
    /// True when some material has a checker or an image: only then does shading look
    /// patterns up (flat-colour scenes take the tables' colours, as before patterns).
    bool hasPatterns() const { return !patterns_->empty(); }
    /// Where patterned materials are looked up, by engine slot (empty without patterns).
    const SurfacePatterns& patterns() const { return *patterns_; }
    /// Images that could not be opened (textures, the environment), one message each naming
    /// its scene key and the file; they render as the "missing" pattern.
    const std::vector<std::string>& problems() const { return problems_; }

private:
    CompiledScene() = default;
    void computeEpsilon();
    SceneGeometry geometry() const;
    /// Material table (built-in grey first) and environment of `doc`, images opened.
    void compileLooks(const SceneDocument& doc);
    /// patterns_ for every primitive and plane whose material has a pattern.
    void compilePatterns(const SceneDocument& doc);

    CameraModel camera_;
    RenderSettings settings_;
    std::vector<CompiledMaterial> materials_;
    std::vector<CompiledLight> lights_;
    std::shared_ptr<const std::vector<Primitive>> primitives_;
    std::shared_ptr<const std::vector<PlanePrimitive>> planes_;
    std::shared_ptr<const RayEngine> engine_;
    float epsilon_ = 1e-4f;
    Aabb sceneBounds_;
    CompiledEnvironment environment_;
    std::shared_ptr<const SurfacePatterns> patterns_ = std::make_shared<SurfacePatterns>();
    std::vector<std::string> problems_;
};

}  // namespace rs
