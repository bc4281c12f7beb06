// Reading the objects of a scene file: per-type geometry, transforms, material references
// and the meshes they load.
#include <cmath>
#include <filesystem>
#include <map>

#include "io/mesh_io.h"
#include "io/scene_reader_sections.h"

namespace rs {

namespace {
// Relative: u and v of a rectangle rotated in the designer are orthogonal only to rounding.
constexpr double kOrthogonalTolerance = 1e-4;
// A normal this close to unit length is kept bit for bit, so save/load is exact.
constexpr double kUnitTolerance = 1e-6;

glm::dvec3 toDouble(const Vec3& v) {
    return glm::dvec3(v.x, v.y, v.z);
}

/// Meshes loaded during one parse, so objects sharing a file share its triangles.
using MeshCache = std::map<std::pair<std::string, bool>, std::shared_ptr<const MeshData>>;

struct ObjectContext {
    SceneErrorSink& sink;
    const std::string& baseDir;
    const SceneDocument& doc;
    MeshCache& meshes;
};

// Geometry keys without a default in the format are required: sphere center and radius,
// plane point and normal, rectangle center, u and v, box min and max, mesh file.
void readSphere(EntryReader& r, SphereGeometry& g) {
    r.vector("center", g.center, VectorRule::Any, Need::Required);
    r.number("radius", g.radius, NumberRange::positive(), Need::Required);
}

void readPlane(EntryReader& r, PlaneGeometry& g) {
    r.vector("point", g.point, VectorRule::Any, Need::Required);
    if (r.vector("normal", g.normal, VectorRule::NonZero, Need::Required)) {
        glm::dvec3 n = toDouble(g.normal);
        double length = glm::length(n);
        if (std::abs(length - 1.0) > kUnitTolerance) {
            n /= length;
            g.normal =
                Vec3(static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z));
        }
    }
    for (const char* key : {"translate", "rotate", "scale"})
        r.forbid(key, std::string("a plane takes no transform (") + key +
                          "); place it with point and normal");
}

void readRectangle(EntryReader& r, RectangleGeometry& g) {
    r.vector("center", g.center, VectorRule::Any, Need::Required);
    bool edges = r.vector("u", g.u, VectorRule::NonZero, Need::Required);
    edges = r.vector("v", g.v, VectorRule::NonZero, Need::Required) && edges;
    if (!edges) return;
    glm::dvec3 u = toDouble(g.u), v = toDouble(g.v);
    double cosine = glm::dot(u, v) / (glm::length(u) * glm::length(v));
    if (std::abs(cosine) > kOrthogonalTolerance) {
        double degrees = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / 3.14159265358979;
        r.sink().atValue(r.pointerTo("v"), "u and v must be orthogonal, they are " +
                                               describeJson(Json(std::round(degrees * 100) / 100)) +
                                               " degrees apart");
    }
}

void readBox(EntryReader& r, BoxGeometry& g) {
    bool corners = r.vector("min", g.min, VectorRule::Any, Need::Required);
    corners = r.vector("max", g.max, VectorRule::Any, Need::Required) && corners;
    if (!corners) return;
    static const char* const axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
        if (g.min[a] < g.max[a]) continue;
        r.sink().atValue(appendPointer(r.pointerTo("max"), static_cast<std::size_t>(a)),
                         std::string("box max must be greater than min in every component (") +
                             axes[a] + ": min " + describeJson(Json(jsonNumberForFloat(g.min[a]))) +
                             ", max " + describeJson(Json(jsonNumberForFloat(g.max[a]))) + ")");
        return;
    }
}

void readMesh(EntryReader& r, ObjectContext& ctx, MeshGeometry& g) {
    r.boolean("smooth_normals", g.smoothNormals);
    if (!r.string("file", g.file, Need::Required)) return;
    const std::string at = r.pointerTo("file");
    if (g.file.empty()) {
        ctx.sink.atValue(at, "file must not be empty");
        return;
    }
    namespace fs = std::filesystem;
    fs::path path(g.file);
    if (path.is_relative()) path = fs::path(ctx.baseDir) / path;
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    g.resolvedPath = (ec ? path : absolute).lexically_normal().string();

    auto [it, fresh] = ctx.meshes.try_emplace({g.resolvedPath, g.smoothNormals});
    if (fresh) {
        MeshLoadResult loaded = loadMesh(g.resolvedPath, g.smoothNormals);
        if (!loaded.ok()) {
            ctx.meshes.erase(it);
            ctx.sink.atValue(at, loaded.error);
            return;
        }
        it->second = loaded.mesh;
    }
    g.data = it->second;
}

void readTransform(EntryReader& r, Transform& t) {
    r.vector("translate", t.translate, VectorRule::Any);
    r.vector("rotate", t.rotate, VectorRule::Any);
    const Json* scale = r.get("scale");
    if (scale && scale->is_number()) {
        float s = 1.0f;
        if (!r.number("scale", s, NumberRange::any())) return;
        if (s == 0.0f) {
            r.sink().atValue(r.pointerTo("scale"), "scale must be non-zero");
            return;
        }
        t.scale = Vec3(s);
        t.scaleWrittenAsNumber = true;
    } else if (scale) {
        r.vector("scale", t.scale, VectorRule::NonZeroComponents);
    }
}

void readObject(EntryReader& r, ObjectContext& ctx, Object& o) {
    r.name(o.name);
    r.boolean("visible", o.visible);
    if (r.string("material", o.material)) {
        if (r.has("material") && o.material.empty())
            ctx.sink.atValue(r.pointerTo("material"),
                             "material must not be empty (leave it out for the default grey)");
        else if (!o.material.empty() && !ctx.doc.findMaterial(o.material))
            ctx.sink.atValue(r.pointerTo("material"),
                             "material \"" + o.material + "\" is not defined in /materials");
    }
    enum class Kind { Sphere, Plane, Rectangle, Box, Mesh } kind = Kind::Sphere;
    if (!r.enumeration("type", kind,
                       {{"sphere", Kind::Sphere},
                        {"plane", Kind::Plane},
                        {"rectangle", Kind::Rectangle},
                        {"box", Kind::Box},
                        {"mesh", Kind::Mesh}},
                       Need::Required))
        return;
    switch (kind) {
        case Kind::Sphere:
            readSphere(r, o.geometry.emplace<SphereGeometry>());
            break;
        case Kind::Plane:
            readPlane(r, o.geometry.emplace<PlaneGeometry>());
            break;
        case Kind::Rectangle:
            readRectangle(r, o.geometry.emplace<RectangleGeometry>());
            break;
        case Kind::Box:
            readBox(r, o.geometry.emplace<BoxGeometry>());
            break;
        case Kind::Mesh:
            readMesh(r, ctx, o.geometry.emplace<MeshGeometry>());
            break;
    }
    if (kind != Kind::Plane) readTransform(r, o.transform);
    o.extras = r.finish();
}
}  // namespace

void readObjects(SceneErrorSink& sink, const Json& json, const std::string& baseDir,
                 SceneDocument& doc) {
    if (!expectArray(sink, json, "/objects")) return;
    MeshCache meshes;
    ObjectContext ctx{sink, baseDir, doc, meshes};
    UniqueNames names("object");
    for (std::size_t i = 0; i < json.size(); ++i) {
        const std::string at = appendPointer("/objects", i);
        if (!expectObject(sink, json[i], at)) continue;
        EntryReader r(sink, json[i], at);
        Object o;
        readObject(r, ctx, o);
        if (!o.name.empty()) names.add(sink, o.name, at);
        doc.addObject(std::move(o));
    }
}

}  // namespace rs
