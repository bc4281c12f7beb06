// Where a patterned material's colour comes from at a hit: the object's own space and shape
// (for the checker and for texture coordinates), kept per engine slot of the snapshot.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "accel/mesh_accel.h"
#include "accel/ray_engine.h"
#include "core/lanes.h"
#include "core/math.h"
#include "core/scratch_arena.h"
#include "scene/document.h"
#include "snapshot/footprint.h"
#include "texture/shape_uv.h"
#include "texture/texture_store.h"

namespace rs {

/// A material's colour as the integrator evaluates it (scenes/FORMAT.md "color").
struct MaterialPattern {
    enum class Kind : uint8_t { None, Checker, Image };
    Kind kind = Kind::None;
    Color even{0.0f}, odd{0.0f};  ///< Checker colours.
    float checkerScale = 1.0f;
    TextureHandle texture;  ///< Image: empty when the file could not be opened ("missing").
    float scaleU = 1.0f, scaleV = 1.0f, offsetU = 0.0f, offsetV = 0.0f;
};

/// One bounded object or plane whose material has a pattern: its shape in its own space and
/// the map from world space to it.
struct PatternSurface {
    enum class Shape : uint8_t { Sphere, Plane, Rectangle, Box, Mesh };
    Shape shape = Shape::Sphere;
    Mat4 objectFromWorld{1.0f};
    Mat3 dirToObject{1.0f};     ///< Linear part of objectFromWorld.
    Mat3 normalToObject{1.0f};  ///< Inverse transpose of dirToObject.
    /// Sphere: centre a, radius r. Plane: point a, unit normal b. Rectangle: centre a, half
    /// edges b, c. Box: min a, max b.
    Vec3 a{0.0f}, b{0.0f}, c{0.0f};
    float r = 0.0f;
    PlaneAxes planeAxes;  ///< Plane: planeUV's axes for normal b.
    /// Mesh with texture coordinates: its triangles, to find the one under a hit (shared by
    /// every snapshot showing that mesh data); null for a mesh without them, whose texture
    /// coordinates are (0, 0) everywhere.
    std::shared_ptr<const MeshAccel> mesh;
};

/// The pattern surfaces of a snapshot, by engine slot (primitive index, or plane index with
/// kPlaneSlot). Empty, and never consulted, when no material has a pattern.
class SurfacePatterns {
public:
    /// The surface of `o` (its geometry and transform); for a mesh, texture coordinates come
    /// from `meshData` (the part a primitive traces) when given, else from the whole mesh.
    static PatternSurface surfaceOf(const Object& o,
                                    const std::shared_ptr<const MeshData>& meshData);

    void resize(std::size_t primitives, std::size_t planes);
    void setPrimitive(std::size_t index, const PatternSurface& s) { primitives_[index] = s; }
    void setPlane(std::size_t index, const PatternSurface& s) { planes_[index] = s; }
    const PatternSurface& at(uint32_t slot) const {
        return (slot & kPlaneSlot) ? planes_[slot & ~kPlaneSlot] : primitives_[slot];
    }
    bool empty() const { return primitives_.empty() && planes_.empty(); }

private:
    std::vector<PatternSurface> primitives_, planes_;
};

/// The colour of `pattern` at world point p with unit world normal n on `surface`, reached
/// along unit direction `dir` by a cone `width` wide there, filtered over that cone's
/// footprint (footprintAt): the checker by its analytic box filter, an image by the
/// TextureStore's mip-mapped lookup. A missing image shows the loud "missing" pattern. The
/// arguments come in registers (a footprint built by the caller went through the stack in
/// pieces the callee read back across, a store-forwarding stall every call).
Color patternColor(const MaterialPattern& pattern, const PatternSurface& surface, Vec3 p, Vec3 n,
                   Vec3 dir, float width);

/// A hit point and its footprint's half-axes in the surface's own space.
struct InObject {
    Vec3 p, a1, a2;
};
[[gnu::always_inline]] inline InObject inObject(const PatternSurface& surface, const Vec3& p,
                                                const Footprint& footprint) {
    if (surface.shape == PatternSurface::Shape::Plane) return {p, footprint.a1, footprint.a2};
    return {Vec3(surface.objectFromWorld * glm::vec4(p, 1.0f)), surface.dirToObject * footprint.a1,
            surface.dirToObject * footprint.a2};
}

/// The half-width along one axis of the axis-aligned box that holds an ellipse whose
/// half-axes have components a1 and a2 on that axis (one, or a lane of them).
template <class F>
[[gnu::always_inline]] inline F boxHalfWidth(F a1, F a2) {
    return sqrtLanes(a1 * a1 + a2 * a2);
}

/// What the checker filters at a hit: the point in the object's own space and the half-widths
/// (object units) of the axis-aligned box that holds the footprint's ellipse there.
struct CheckerBox {
    Vec3 p, halfWidth;
};
[[gnu::always_inline]] inline CheckerBox checkerBoxAt(const PatternSurface& surface, const Vec3& p,
                                                      const Footprint& footprint) {
    const InObject o = inObject(surface, p, footprint);
    return {o.p, Vec3(boxHalfWidth(o.a1.x, o.a2.x), boxHalfWidth(o.a1.y, o.a2.y),
                      boxHalfWidth(o.a1.z, o.a2.z))};
}

/// A checker's colour where a fraction `odd` of the box lies on odd cells.
inline Color checkerColor(const MaterialPattern& pattern, float odd) {
    return pattern.even + (pattern.odd - pattern.even) * odd;
}

/// A level's checkered points gathered so that their footprints and box filters run several
/// at a time (footprintAxes on lanes, then checkerOddFractions): each point's colour is the
/// one patternColor gives it alone. Per-thread scratch (ScratchVector): keep it in the
/// thread's workspace.
class CheckerBatch {
public:
    /// Empty, with room for `capacity` points.
    void reset(std::size_t capacity);
    /// Adds shading point `point`: world point p on `surface`, reached along unit direction
    /// `dir` by a cone `width` wide there, with unit world normal n; cells of side `scale`.
    /// `surface` must outlive evaluate().
    [[gnu::always_inline]] void add(uint32_t point, const PatternSurface& surface, const Vec3& p,
                                    const Vec3& dir, const Vec3& n, float width, float scale) {
        // One record a point: a few stores through one pointer (parallel arrays cost a
        // reload of each array's address after every store, which might have changed it).
        // Planes are in world space already (inObject): no transform to look up.
        entries_[count_++] = {p,
                              dir,
                              n,
                              width,
                              scale,
                              point,
                              surface.shape == PatternSurface::Shape::Plane ? nullptr : &surface};
    }
    std::size_t size() const { return count_; }
    uint32_t point(std::size_t k) const { return entries_[k].point; }
    /// The odd fraction of each point added, in the order added.
    const float* evaluate();

private:
    struct Entry {
        Vec3 p, dir, n;
        float width, scale;
        uint32_t point;
        const PatternSurface* surface;  ///< Null for a plane.
    };
    std::size_t count_ = 0;
    ScratchVector<Entry> entries_;
    /// What the box filter reads (checkerOddFractions): points in their object's space, the
    /// box's half-widths, the cells' sides; and its answers.
    ScratchVector<float> px_, py_, pz_, hx_, hy_, hz_, scale_, odd_;
};

}  // namespace rs
