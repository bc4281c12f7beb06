// Scene edits: naming, defaults for new objects, and structural changes of the document.
#include "document/scene_edits.h"

#include <algorithm>

namespace rs::ui {

namespace {

bool nameTaken(const SceneDocument& doc, const std::string& name) {
    auto same = [&](const auto& e) { return e.name == name; };
    return std::any_of(doc.objects.begin(), doc.objects.end(), same) ||
           std::any_of(doc.lights.begin(), doc.lights.end(), same) ||
           std::any_of(doc.materials.begin(), doc.materials.end(), same);
}

}  // namespace

std::string uniqueName(const SceneDocument& doc, const std::string& base) {
    if (!nameTaken(doc, base)) return base;
    // "right wall 2" is copy 2 of "right wall": count on from its number instead of
    // appending another ("right wall 2 2"). Only a plain number counts (no sign, no leading 0).
    std::string stem = base;
    long first = 2;
    const std::size_t space = base.find_last_of(' ');
    if (space != std::string::npos && space > 0 && space + 1 < base.size() &&
        base[space + 1] != '0' && base.size() - space - 1 <= 9 &&
        std::all_of(base.begin() + long(space) + 1, base.end(),
                    [](char c) { return c >= '0' && c <= '9'; })) {
        stem = base.substr(0, space);
        first = std::stol(base.substr(space + 1)) + 1;
    }
    for (long i = first;; ++i) {
        std::string n = stem + " " + std::to_string(i);
        if (!nameTaken(doc, n)) return n;
    }
}

ObjectId addShape(SceneDocument& doc, ShapeKind kind, const Vec3& p) {
    Object o;
    switch (kind) {
        case ShapeKind::Sphere:
            o.name = uniqueName(doc, "sphere");
            o.geometry = SphereGeometry{Vec3(0.0f), 0.5f};
            o.transform.translate = p;
            break;
        case ShapeKind::Plane:
            o.name = uniqueName(doc, "plane");
            o.geometry = PlaneGeometry{p, Vec3(0, 1, 0)};
            break;
        case ShapeKind::Rectangle:
            o.name = uniqueName(doc, "rectangle");
            o.geometry = RectangleGeometry{Vec3(0.0f), Vec3(0.5f, 0, 0), Vec3(0, 0.5f, 0)};
            o.transform.translate = p;
            break;
        case ShapeKind::Box:
            o.name = uniqueName(doc, "box");
            o.geometry = BoxGeometry{};
            o.transform.translate = p;
            break;
    }
    return doc.addObject(std::move(o));
}

ObjectId addMesh(SceneDocument& doc, const std::string& file, std::shared_ptr<const MeshData> data,
                 const Vec3& at) {
    Object o;
    std::string base = file.substr(file.find_last_of("/\\") + 1);
    base = base.substr(0, base.find('.'));
    o.name = uniqueName(doc, base.empty() ? "mesh" : base);
    MeshGeometry g;
    g.file = file;
    g.resolvedPath = file;
    g.data = std::move(data);
    o.geometry = std::move(g);
    o.transform.translate = at;
    return doc.addObject(std::move(o));
}

ObjectId addLight(SceneDocument& doc, LightType type, const Vec3& at) {
    Light l;
    l.type = type;
    static const char* const names[] = {"point light", "sphere light", "sun light", "spot light"};
    l.name = uniqueName(doc, names[int(type)]);
    l.position = at;  // A sun has no position: this is where its glyph is drawn.
    l.radius = 0.3f;
    // A sun slanting steeply down (about 55 degrees); a spot aimed straight down.
    if (type == LightType::Directional) l.direction = glm::normalize(Vec3(-1.0f, -2.0f, -1.0f));
    if (type == LightType::Spot) l.target = at - Vec3(0.0f, 1.0f, 0.0f);
    return doc.addLight(std::move(l));
}

ObjectId duplicate(SceneDocument& doc, ObjectId id) {
    const Vec3 offset(0.3f, 0.0f, 0.3f);
    if (const Object* o = doc.findObject(id)) {
        Object copy = *o;
        copy.name = uniqueName(doc, o->name);
        const ObjectId nid = doc.addObject(std::move(copy));
        moveBy(doc, nid, offset);
        return nid;
    }
    if (const Light* l = doc.findLight(id)) {
        Light copy = *l;
        copy.name = uniqueName(doc, l->name);
        copy.position += offset;
        copy.target += offset;  // A spot keeps its aim.
        return doc.addLight(std::move(copy));
    }
    return kNoObject;
}

bool remove(SceneDocument& doc, ObjectId id) {
    auto byId = [id](const auto& e) { return e.id == id; };
    const auto objs = doc.objects.eraseIf(byId);
    const auto lights = std::erase_if(doc.lights, byId);
    return objs + lights > 0;
}

void moveBy(SceneDocument& doc, ObjectId id, const Vec3& delta) {
    if (Object* o = doc.findObject(id)) {
        if (auto* plane = std::get_if<PlaneGeometry>(&o->geometry))
            plane->point += delta;
        else
            o->transform.translate += delta;
    } else if (Light* l = doc.findLight(id)) {
        // A spot moves with its target, keeping its aim (as Blender's does).
        l->position += delta;
        if (l->type == LightType::Spot) l->target += delta;
    }
}

void restoreEntity(SceneDocument& doc, const SceneDocument& from, ObjectId id) {
    if (Object* o = doc.findObject(id)) {
        if (const Object* was = from.findObject(id)) *o = *was;
    } else if (Light* l = doc.findLight(id)) {
        if (const Light* was = from.findLight(id)) *l = *was;
    }
}

bool rename(SceneDocument& doc, ObjectId id, const std::string& name) {
    if (name.empty()) return false;
    std::string* target = nullptr;
    if (Object* o = doc.findObject(id)) target = &o->name;
    if (Light* l = doc.findLight(id)) target = &l->name;
    if (!target) return false;
    if (*target == name) return true;
    if (nameTaken(doc, name)) return false;
    *target = name;
    return true;
}

int materialUsers(const SceneDocument& doc, const std::string& name) {
    return int(std::count_if(doc.objects.begin(), doc.objects.end(),
                             [&](const Object& o) { return usesMaterial(o, name); }));
}

Material* findMaterial(SceneDocument& doc, const std::string& name) {
    for (Material& m : doc.materials)
        if (m.name == name) return &m;
    return nullptr;
}

std::string makeMaterialUnique(SceneDocument& doc, ObjectId id) {
    Object* o = doc.findObject(id);
    if (!o) return {};
    Material copy;
    if (const Material* m = doc.findMaterial(o->material)) copy = *m;
    copy.name = uniqueName(doc, o->name + " material");
    o->material = copy.name;
    doc.materials.push_back(std::move(copy));
    return o->material;
}

std::string materialNameError(const SceneDocument& doc, const std::string& current,
                              const std::string& name) {
    if (name.empty()) return "a material name must not be empty";
    if (name != current && doc.findMaterial(name))
        return "another material is already named \"" + name + "\"";
    return {};
}

std::string addMaterial(SceneDocument& doc) {
    Material m;
    m.name = uniqueName(doc, "material");
    doc.materials.push_back(m);
    return m.name;
}

std::string duplicateMaterial(SceneDocument& doc, const std::string& name) {
    const Material* m = doc.findMaterial(name);
    if (!m) return {};
    Material copy = *m;
    copy.name = uniqueName(doc, name);
    doc.materials.push_back(copy);
    return copy.name;
}

std::string renameMaterial(SceneDocument& doc, const std::string& from, const std::string& to) {
    Material* m = findMaterial(doc, from);
    if (!m) return "there is no material \"" + from + "\"";
    if (std::string error = materialNameError(doc, from, to); !error.empty()) return error;
    m->name = to;
    for (Object& o : doc.objects.editable()) {
        if (o.material == from) o.material = to;
        if (auto* mesh = std::get_if<MeshGeometry>(&o.geometry))
            std::replace(mesh->partMaterials.begin(), mesh->partMaterials.end(), from, to);
    }
    return {};
}

std::string materialDeleteError(const SceneDocument& doc, const std::string& name) {
    if (!doc.findMaterial(name)) return "there is no material \"" + name + "\"";
    // The first few users by name and how many more: a material of 100,000 spheres is
    // counted, not copied name by name.
    constexpr std::size_t kNamed = 3;
    std::vector<const std::string*> named;
    std::size_t users = 0;
    for (const Object& o : doc.objects) {
        if (!usesMaterial(o, name)) continue;
        if (named.size() < kNamed) named.push_back(&o.name);
        ++users;
    }
    if (users == 0) return {};
    std::string list = "\"" + *named[0] + "\"";
    for (std::size_t i = 1; i < named.size(); ++i) list += ", \"" + *named[i] + "\"";
    if (users > kNamed) list += " and " + std::to_string(users - kNamed) + " more";
    return "\"" + name + "\" is used by " + list + "; assign those another material first";
}

std::string deleteMaterial(SceneDocument& doc, const std::string& name) {
    if (std::string error = materialDeleteError(doc, name); !error.empty()) return error;
    std::erase_if(doc.materials, [&](const Material& m) { return m.name == name; });
    return {};
}

int assignMaterial(SceneDocument& doc, const std::vector<ObjectId>& ids, const std::string& name) {
    if (!name.empty() && !doc.findMaterial(name)) return 0;
    int changed = 0;
    for (ObjectId id : ids) {
        Object* o = doc.findObject(id);
        if (!o) continue;
        // An imported asset's parts give up their own materials: the whole object shows it.
        auto* mesh = std::get_if<MeshGeometry>(&o->geometry);
        const bool ownParts =
            mesh && std::any_of(mesh->partMaterials.begin(), mesh->partMaterials.end(),
                                [](const std::string& m) { return !m.empty(); });
        if (o->material == name && !ownParts) continue;
        o->material = name;
        if (ownParts) mesh->partMaterials.clear();
        ++changed;
    }
    return changed;
}

}  // namespace rs::ui
