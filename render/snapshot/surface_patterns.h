// Where a patterned material's colour comes from at a hit: the object's own space and shape
// (for the checker and for texture coordinates), kept per engine slot of the snapshot.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "accel/mesh_accel.h"
#include "accel/ray_engine.h"
#include "core/math.h"
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
    const PatternSurface& at(uint32_t slot) const;
    bool empty() const { return primitives_.empty() && planes_.empty(); }

private:
    std::vector<PatternSurface> primitives_, planes_;
};

/// The colour of `pattern` at world point p with unit world normal n on `surface`, filtered
/// over `footprint`: the checker by its analytic box filter, an image by the TextureStore's
/// mip-mapped lookup. A missing image shows the loud "missing" pattern.
Color patternColor(const MaterialPattern& pattern, const PatternSurface& surface, const Vec3& p,
                   const Vec3& n, const Footprint& footprint);

}  // namespace rs
