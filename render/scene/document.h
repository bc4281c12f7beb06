// The editable scene document: what the designer edits and what scene files hold.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/math.h"
#include "core/shared_list.h"
#include "scene/mesh_data.h"

namespace rs {

/// Stable identity of a light or an object for the lifetime of a document (never reused).
using ObjectId = uint32_t;
inline constexpr ObjectId kNoObject = 0;

/// `x-` keys of one JSON object, kept in file order as (key, serialized JSON value).
using Extras = std::vector<std::pair<std::string, std::string>>;

enum class Projection { Perspective, Orthographic };
enum class ToneMap { Clamp, Linear, Reinhard, Aces };

/// The scene camera (scenes/FORMAT.md, "camera").
struct Camera {
    Projection projection = Projection::Perspective;
    Vec3 position{0.0f, 0.0f, 0.0f};
    Vec3 target{0.0f, 0.0f, -1.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float fovY = 55.0f;        ///< Degrees, vertical, in (0, 180).
    float orthoHeight = 2.0f;  ///< Visible height in scene units for orthographic projection.
    Extras extras;
    bool operator==(const Camera&) const = default;
};

/// A named view the user can go back to (scenes/FORMAT.md, "views"): the designer's view
/// bookmarks, and the cameras an imported asset brings. Never rendered by itself: a render
/// looks through the scene `camera` (or a view named on the command line).
struct ViewBookmark {
    std::string name;  ///< Required, non-empty, unique among the views.
    Camera camera;
    Extras extras;
    bool operator==(const ViewBookmark&) const = default;
};

/// Largest accepted max_depth: recursion deeper than this could overflow a worker's stack.
inline constexpr int kMaxDepthLimit = 1000;
/// Largest accepted shadow_samples and supersampling (per-pixel sample counts are 16-bit).
inline constexpr int kMaxSampleCount = 4096;
/// Largest accepted image width or height, in pixels.
inline constexpr int kMaxImageSide = 16384;
/// Largest accepted image area: the interactive session's deep frame holds about 100 bytes a
/// pixel, so 64 Mpixels is already some 6 GiB. Bounding each side alone would still let
/// 16384 x 16384 (268 Mpixels, 27 GiB) through to fail an allocation deep inside a render.
inline constexpr long long kMaxImagePixels = 64LL * 1024 * 1024;
/// Empty when a width x height image is within kMaxImageSide and kMaxImagePixels, else the
/// message that refuses it (naming the limit).
std::string imageSizeError(int width, int height);

/// Render settings (scenes/FORMAT.md, "render").
struct RenderSettings {
    int width = 1280;
    int height = 720;
    int maxDepth = 3;
    /// Reflected or refracted rays whose accumulated weight is below this are not traced
    /// (scenes/FORMAT.md `min_weight`, POV-Ray's adc_bailout); 0 traces to maxDepth always.
    float minWeight = 1.0f / 255.0f;
    int shadowSamples = 1;
    int supersampling = 1;
    bool adaptiveSupersampling = false;
    ToneMap tonemap = ToneMap::Clamp;
    float exposure = 0.0f;
    Color background{0.0f, 0.0f, 0.0f};
    Color ambient{0.05f, 0.05f, 0.05f};
    /// Version 1's shadows: every surface blocks light, glass too (format version 2 key
    /// `opaque_shadows`). Otherwise a shadow ray passes transparent surfaces, filtered.
    bool opaqueShadows = false;
    Extras extras;
    bool operator==(const RenderSettings&) const = default;
};

/// An image file a scene refers to (a texture or the environment).
struct ImageFile {
    std::string file;          ///< As written in the scene file (relative or absolute).
    std::string resolvedPath;  ///< Absolute path, once the reader or designer resolved it.
    const std::string& source() const { return resolvedPath.empty() ? file : resolvedPath; }
    bool empty() const { return file.empty() && resolvedPath.empty(); }
    bool operator==(const ImageFile& o) const { return source() == o.source(); }
};

/// POV-Ray's solid checker in the object's own space: unit cubes of side `scale` alternate
/// between `even` (the cell holding the origin's positive octant) and `odd`.
struct CheckerPattern {
    Color even{1.0f, 1.0f, 1.0f};
    Color odd{0.0f, 0.0f, 0.0f};
    float scale = 1.0f;
    bool operator==(const CheckerPattern&) const = default;
};

/// An image through the shape's UVs, repeating: uv' = uv * scale + offset.
struct ImageTexture {
    ImageFile image;
    float scaleU = 1.0f, scaleV = 1.0f;
    float offsetU = 0.0f, offsetV = 0.0f;
    bool operator==(const ImageTexture&) const = default;
};

/// What a material's colour is (scenes/FORMAT.md "color"): Material::color alone, a checker,
/// or an image texture. A pattern replaces the flat colour, which is kept for when it goes.
using ColorPattern = std::variant<std::monostate, CheckerPattern, ImageTexture>;

/// The world around the scene (format version 2 `environment`): an equirectangular image,
/// +Y up, its first row straight up, turned `rotation` degrees about +Y. Rays that hit
/// nothing return it times `intensity` instead of the background colour.
struct Environment {
    ImageFile image;  ///< Empty: no environment, the background colour.
    float intensity = 1.0f;
    float rotation = 0.0f;
    Extras extras;
    bool present() const { return !image.empty(); }
    bool operator==(const Environment&) const = default;
};

/// A Whitted material: Phong/Lambert local term plus mirror and glass weights.
struct Material {
    std::string name;
    Color color{0.8f, 0.8f, 0.8f};
    float diffuse = 1.0f;
    float specular = 0.0f;
    float shininess = 32.0f;
    float reflectivity = 0.0f;
    float transparency = 0.0f;
    float ior = 1.5f;
    ColorPattern pattern;  ///< When set, the surface's colour instead of `color`.
    Extras extras;
    bool operator==(const Material&) const = default;
};

enum class LightType { Point, Sphere, Directional, Spot };

/// A point light, a sphere area light sampled for soft shadows, a directional (sun) light
/// travelling along `direction`, or a spot light at `position` aimed at `target` (POV-Ray's
/// spotlight with tightness 0). No distance fall-off.
struct Light {
    ObjectId id = kNoObject;
    std::string name;
    LightType type = LightType::Point;
    Vec3 position{0.0f, 0.0f, 0.0f};
    float radius = 0.5f;                ///< Sphere lights only.
    Vec3 direction{0.0f, -1.0f, 0.0f};  ///< Directional lights only: where the light goes.
    Vec3 target{0.0f, 0.0f, 0.0f};      ///< Spot lights only: the cone's axis points here.
    float coneRadius = 30.0f;   ///< Spot lights only: half-angle of full intensity, degrees.
    float coneFalloff = 45.0f;  ///< Spot lights only: half-angle where it reaches 0, degrees.
    Color color{1.0f, 1.0f, 1.0f};
    float intensity = 1.0f;
    Extras extras;
    bool operator==(const Light&) const = default;
};

struct SphereGeometry {
    Vec3 center{0.0f, 0.0f, 0.0f};
    float radius = 1.0f;
    bool operator==(const SphereGeometry&) const = default;
};
struct PlaneGeometry {
    Vec3 point{0.0f, 0.0f, 0.0f};
    Vec3 normal{0.0f, 1.0f, 0.0f};  ///< Unit length.
    bool operator==(const PlaneGeometry&) const = default;
};
struct RectangleGeometry {
    Vec3 center{0.0f, 0.0f, 0.0f};
    Vec3 u{1.0f, 0.0f, 0.0f};   ///< Half-extent edge vector.
    Vec3 v{0.0f, 0.0f, -1.0f};  ///< Half-extent edge vector, orthogonal to u.
    bool operator==(const RectangleGeometry&) const = default;
};
struct BoxGeometry {
    Vec3 min{-0.5f, -0.5f, -0.5f};
    Vec3 max{0.5f, 0.5f, 0.5f};
    bool operator==(const BoxGeometry&) const = default;
};
struct MeshGeometry {
    std::string file;          ///< As written in the scene file (relative or absolute).
    std::string resolvedPath;  ///< Absolute path the mesh was loaded from.
    bool smoothNormals = true;
    /// The material of each part (MeshData::parts), by the file's material index: a name from
    /// the document's materials, or "" (and any index past the end) for the object's own.
    /// Empty: the whole mesh takes the object's material, as one surface.
    std::vector<std::string> partMaterials;
    std::shared_ptr<const MeshData> data;  ///< Loaded triangles; not part of equality.
    /// Which file the mesh is: its resolved path once known, else the path as written. Two
    /// spellings of one file ("meshes//m.obj", "./meshes/m.obj", an absolute path) are the same
    /// mesh, and saving writes them alike (relative below the scene's folder).
    const std::string& source() const { return resolvedPath.empty() ? file : resolvedPath; }
    bool operator==(const MeshGeometry& o) const {
        return source() == o.source() && smoothNormals == o.smoothNormals &&
               partMaterials == o.partMaterials;
    }
};

/// The closed set of object shapes.
using Geometry =
    std::variant<SphereGeometry, PlaneGeometry, RectangleGeometry, BoxGeometry, MeshGeometry>;

/// Translate, rotate (degrees, X then Y then Z), scale; applied after the shape's own keys.
struct Transform {
    Vec3 translate{0.0f, 0.0f, 0.0f};
    Vec3 rotate{0.0f, 0.0f, 0.0f};
    Vec3 scale{1.0f, 1.0f, 1.0f};
    bool scaleWrittenAsNumber = false;  ///< Round-trips `"scale": 2` as a number.
    bool isIdentity() const {
        return translate == Vec3(0.0f) && rotate == Vec3(0.0f) && scale == Vec3(1.0f);
    }
    /// World-from-object matrix: T * Rz * Ry * Rx * S.
    Mat4 matrix() const;
    bool operator==(const Transform& o) const {
        return translate == o.translate && rotate == o.rotate && scale == o.scale;
    }
};

/// One object of the scene.
struct Object {
    ObjectId id = kNoObject;
    std::string name;
    std::string material;  ///< Material name; empty means the built-in grey diffuse.
    bool visible = true;
    Geometry geometry;
    Transform transform;
    Extras extras;
    bool operator==(const Object&) const = default;
};

/// The material name the triangles of file material `fileMaterial` of `o` use: their part's
/// entry of MeshGeometry::partMaterials when it names one, else the object's material.
inline const std::string& partMaterial(const Object& o, uint32_t fileMaterial) {
    if (const auto* mesh = std::get_if<MeshGeometry>(&o.geometry))
        if (fileMaterial < mesh->partMaterials.size() && !mesh->partMaterials[fileMaterial].empty())
            return mesh->partMaterials[fileMaterial];
    return o.material;
}

/// Calls `f(name)` for every material name `o` shows: its own, then each part's (repeats
/// possible; "" is the built-in grey).
template <class F>
void forEachMaterialOf(const Object& o, F f) {
    f(o.material);
    if (const auto* mesh = std::get_if<MeshGeometry>(&o.geometry))
        for (const std::string& name : mesh->partMaterials)
            if (!name.empty()) f(name);
}

/// True when `o` is a loaded mesh with parts and every part has a material of its own, so
/// the object's own material shows nowhere (an imported asset's usual case).
bool everyPartHasItsOwn(const Object& o);

/// The material that shows on `o` when one does: for a loaded mesh of one part with a material
/// of its own (an imported asset of one material), that part's; else the object's own. What
/// the designer edits when `o` is selected.
const std::string& shownMaterial(const Object& o);

/// True when `o` or one of its parts uses material `name`.
inline bool usesMaterial(const Object& o, const std::string& name) {
    bool used = false;
    forEachMaterialOf(o, [&](const std::string& m) { used = used || m == name; });
    return used;
}

/// The whole editable scene. Ids are assigned by the document and never reused; objects and
/// lights are only appended (addObject, addLight) and erased, so each list is in increasing id
/// order, which findObject and findLight rely on (a binary search).
struct SceneDocument {
    Camera camera;
    RenderSettings render;
    std::vector<Material> materials;
    std::vector<Light> lights;
    /// Copies of a document share the objects an edit did not touch (core/shared_list.h).
    SharedList<Object> objects;
    Environment environment;
    std::vector<ViewBookmark> views;
    Extras extras;
    ObjectId nextId = 1;

    /// Appends an object, giving it a fresh id; returns that id.
    ObjectId addObject(Object o);
    /// Appends a light, giving it a fresh id; returns that id.
    ObjectId addLight(Light l);
    Object* findObject(ObjectId id);
    const Object* findObject(ObjectId id) const;
    Light* findLight(ObjectId id);
    const Light* findLight(ObjectId id) const;
    const Material* findMaterial(const std::string& name) const;
    const ViewBookmark* findView(const std::string& name) const;

    /// Content equality: ids are identity, not content, so they are not compared.
    bool sameContent(const SceneDocument& o) const;
};

/// Name of a geometry kind as the scene format spells it ("sphere", "plane", ...).
const char* geometryTypeName(const Geometry& g);

}  // namespace rs
