// Reading the objects of a scene file: per-type geometry, transforms, material references
// and the meshes they load.
#include <cmath>
#include <filesystem>
#include <map>

#include "io/mesh_io.h"
#include "io/scene_reader_sections.h"
#include "scene/field_rules.h"

namespace rs {

namespace {
/// Meshes loaded during one parse, so objects sharing a file share its triangles.
using MeshCache = std::map<std::pair<std::string, bool>, std::shared_ptr<const MeshData>>;

struct ObjectContext {
    SceneErrorSink& sink;
    const std::string& baseDir;
    const SceneDocument& doc;
    MeshCache& meshes;
};

// Geometry keys without a default in the format are required (the descriptors say which);
// the rules that relate them come from scene/field_rules.h.
void readSphere(EntryReader& r, SphereGeometry& g) {
    readFields(r, ParamKind::Sphere, g);
}

void readPlane(EntryReader& r, PlaneGeometry& g) {
    const auto invalid = readFields(r, ParamKind::Plane, g);
    if (noneInvalid(invalid, {"normal"}) && g.normal != Vec3(0.0f))
        g.normal = planeNormal(g.normal);
    for (const char* key : {"translate", "rotate", "scale"})
        r.forbid(key, std::string("a plane takes no transform (") + key +
                          "); place it with point and normal");
}

void readRectangle(EntryReader& r, RectangleGeometry& g) {
    const auto invalid = readFields(r, ParamKind::Rectangle, g);
    if (!noneInvalid(invalid, {"u", "v"})) return;
    if (auto e = rectangleEdgesError(g)) r.sink().atValue(r.pointerTo(e.key), e.message);
}

void readBox(EntryReader& r, BoxGeometry& g) {
    const auto invalid = readFields(r, ParamKind::Box, g);
    if (!noneInvalid(invalid, {"min", "max"})) return;
    int axis = 0;
    if (auto e = boxCornersError(g, &axis))
        r.sink().atValue(appendPointer(r.pointerTo(e.key), static_cast<std::size_t>(axis)),
                         e.message);
}

void readPartMaterials(EntryReader& r, ObjectContext& ctx, MeshGeometry& g);

void readMesh(EntryReader& r, ObjectContext& ctx, MeshGeometry& g) {
    // The file is read last: loading it needs smooth_normals.
    readFields(r, ParamKind::Mesh, g, {"file"});
    readPartMaterials(r, ctx, g);
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

/// `part_materials`: for each of the mesh file's materials, by index, the name of one of
/// ours, or null for the object's own.
void readPartMaterials(EntryReader& r, ObjectContext& ctx, MeshGeometry& g) {
    constexpr std::size_t kMost = 65536;
    const Json* parts = r.get("part_materials");
    if (!parts) return;
    const std::string at = r.pointerTo("part_materials");
    if (!parts->is_array()) {
        ctx.sink.atValue(at, "part_materials must be an array of material names or nulls");
        return;
    }
    if (parts->size() > kMost) {
        ctx.sink.atValue(at, "part_materials has " + std::to_string(parts->size()) +
                                 " entries; at most " + std::to_string(kMost));
        return;
    }
    std::vector<std::string> names;
    for (std::size_t i = 0; i < parts->size(); ++i) {
        const Json& entry = (*parts)[i];
        const std::string pointer = appendPointer(at, i);
        if (entry.is_null()) {
            names.emplace_back();
        } else if (!entry.is_string() || entry.get<std::string>().empty()) {
            ctx.sink.atValue(pointer, "a part's material must be a material name or null");
            return;
        } else if (!ctx.doc.findMaterial(entry.get<std::string>())) {
            ctx.sink.atValue(pointer, "material \"" + entry.get<std::string>() +
                                          "\" is not defined in /materials");
            return;
        } else {
            names.push_back(entry.get<std::string>());
        }
    }
    g.partMaterials = std::move(names);
}

void readTransform(EntryReader& r, Transform& t) {
    // Scale may also be one number (uniform), which the writer keeps as written.
    readFields(r, ParamKind::Transform, t, {"scale"});
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
