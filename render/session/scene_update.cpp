// Document diffing for incremental rendering: everything, regions, or material changes.
#include "session/scene_update.h"

#include <algorithm>
#include <map>
#include <set>

#include "scene/document_change.h"

namespace rs {

namespace {

/// Settings that change traced radiance (tone mapping and exposure only change display).
bool sameTracedSettings(RenderSettings a, RenderSettings b) {
    a.tonemap = b.tonemap;
    a.exposure = b.exposure;
    a.extras = b.extras;
    return a == b;
}

bool sameLight(const Light& a, const Light& b) {
    if (a.id != b.id || a.type != b.type || a.color != b.color || a.intensity != b.intensity)
        return false;
    switch (a.type) {
        case LightType::Point:
            return a.position == b.position;
        case LightType::Sphere:
            return a.position == b.position && a.radius == b.radius;
        case LightType::Directional:
            return a.direction == b.direction;
        case LightType::Spot:
            return a.position == b.position && a.target == b.target &&
                   a.coneRadius == b.coneRadius && a.coneFalloff == b.coneFalloff;
    }
    return false;
}

/// Where the light's rays come from, as the integrator sees it (a directional light's point
/// is kSunDistance away), and a spot light's cone.
LightSphere sphereOf(const Light& l) {
    const CompiledLight c = compileLight(l);
    return {c.position, c.radius, c.spot, c.axis, c.cosFalloff};
}

/// The spheres of every light whose contribution may differ: changed lights (old and new), and
/// from the first added, removed or reordered light on, all of them, because a light's index
/// seeds its samples.
std::vector<LightSphere> changedLights(const std::vector<Light>& before,
                                       const std::vector<Light>& after) {
    std::vector<LightSphere> out;
    const std::size_t common = std::min(before.size(), after.size());
    std::size_t i = 0;
    for (; i < common && before[i].id == after[i].id; ++i) {
        if (sameLight(before[i], after[i])) continue;
        out.push_back(sphereOf(before[i]));
        out.push_back(sphereOf(after[i]));
    }
    for (std::size_t k = i; k < before.size(); ++k) out.push_back(sphereOf(before[k]));
    for (std::size_t k = i; k < after.size(); ++k) out.push_back(sphereOf(after[k]));
    return out;
}

bool sameMaterialData(Material a, const Material& b) {
    a.extras = b.extras;
    return a == b;
}

bool isPlane(const Object& o) {
    return std::holds_alternative<PlaneGeometry>(o.geometry);
}

/// A mesh whose triangles or normals differ (smooth normals toggled, another file or reloaded
/// data): a refit would keep the old mesh BVH, so the object must be compiled afresh.
bool meshChanged(const Object& before, const Object& after) {
    const auto* a = std::get_if<MeshGeometry>(&before.geometry);
    const auto* b = std::get_if<MeshGeometry>(&after.geometry);
    return a && b && (!(*a == *b) || a->data != b->data);
}

}  // namespace

SceneUpdate updateScene(const SceneDocument& before,
                        const std::shared_ptr<const CompiledScene>& beforeSnapshot,
                        const SceneDocument& after, EngineKind engine) {
    SceneUpdate update;
    SceneEdit& edit = update.edit;
    if (!beforeSnapshot || beforeSnapshot->engineKind() != engine) {
        update.snapshot =
            std::make_shared<const CompiledScene>(after, beforeSnapshot.get(), engine);
        edit.everything = edit.resized = true;
        return update;
    }
    edit.resized =
        before.render.width != after.render.width || before.render.height != after.render.height;
    if (!(before.camera == after.camera) || !sameTracedSettings(before.render, after.render))
        edit.everything = true;
    // The environment is seen only by rays that leave the scene (it lights nothing).
    const bool environmentChanged = !(before.environment == after.environment);
    edit.environment = environmentChanged && !edit.everything;
    edit.lights = changedLights(before.lights, after.lights);
    edit.displayOnly = !edit.everything && (before.render.tonemap != after.render.tonemap ||
                                            before.render.exposure != after.render.exposure);

    // Materials: by name; a changed, added or removed definition retints its users.
    std::set<std::string> changedMaterials;
    bool materialListChanged = before.materials.size() != after.materials.size();
    for (std::size_t i = 0; i < after.materials.size(); ++i) {
        const Material* old = before.findMaterial(after.materials[i].name);
        if (!old || !sameMaterialData(*old, after.materials[i]))
            changedMaterials.insert(after.materials[i].name);
        if (i >= before.materials.size() || before.materials[i].name != after.materials[i].name)
            materialListChanged = true;
    }
    for (const Material& m : before.materials)
        if (!after.findMaterial(m.name)) changedMaterials.insert(m.name);

    // Glass filters the shadows it casts (scenes/FORMAT.md "Shadows"): a material change of
    // an object that is or was transparent reaches every pixel whose shadow rays cross it.
    auto filters = [](const SceneDocument& doc, const std::string& name) {
        const Material* m = doc.findMaterial(name);
        return !doc.render.opaqueShadows && m && m->transparency > 0.0f;
    };
    auto anyMaterial = [](const Object& o, auto test) {
        bool any = false;
        forEachMaterialOf(o, [&](const std::string& name) { any = any || test(name); });
        return any;
    };
    auto castsFilteredShadow = [&](const Object& prev, const Object& o) {
        return anyMaterial(prev, [&](const std::string& m) { return filters(before, m); }) ||
               anyMaterial(o, [&](const std::string& m) { return filters(after, m); });
    };
    std::set<ObjectId> reshadowed;

    std::vector<ObjectId> moved, added, removed;
    bool structural = false;
    auto compare = [&](const Object& prev, const Object& o) {
        const bool shapeChanged =
            !(prev.geometry == o.geometry) || !(prev.transform == o.transform);
        const bool kindChanged = prev.geometry.index() != o.geometry.index();
        const bool materialChanged =
            prev.material != o.material ||
            anyMaterial(o, [&](const std::string& m) { return changedMaterials.count(m) > 0; });
        if (isPlane(o) || isPlane(prev)) {
            if (shapeChanged || kindChanged || prev.visible != o.visible)
                edit.everything = true;
            else if (materialChanged && o.visible && castsFilteredShadow(prev, o))
                edit.everything = true;
            else if (materialChanged && o.visible)
                edit.retinted.push_back(o.id);
            structural |= kindChanged || prev.visible != o.visible;
            return;
        }
        if (kindChanged || prev.visible != o.visible || meshChanged(prev, o)) {
            structural = true;
            added.push_back(o.id);
            removed.push_back(o.id);
            edit.focus = o.id;
        } else if (shapeChanged && o.visible) {
            moved.push_back(o.id);
            edit.focus = o.id;
        } else if (materialChanged && o.visible) {
            moved.push_back(o.id);  // Recompiled for its material index; bounds unchanged.
            edit.retinted.push_back(o.id);
            if (castsFilteredShadow(prev, o)) reshadowed.insert(o.id);
        }
    };

    // Objects kept in place: the document diff names the changed ones without visiting the
    // rest, unless a material definition changed (then its users are found by walking).
    const DocumentChange change = describeChange(before, after);
    std::map<ObjectId, const Object*> old;
    if (!change.objectsRestructured && changedMaterials.empty()) {
        for (const DocumentChange::ObjectEdit& e : change.objects)
            compare(before.objects[e.index], after.objects[e.index]);
    } else {
        for (const Object& o : before.objects) old[o.id] = &o;
        for (const Object& o : after.objects) {
            auto it = old.find(o.id);
            if (it == old.end()) {
                added.push_back(o.id);
                structural = true;
                if (isPlane(o) && o.visible) edit.everything = true;
                continue;
            }
            const Object& prev = *it->second;
            old.erase(it);
            compare(prev, o);
        }
    }
    for (const auto& [id, o] : old) {
        structural = true;
        removed.push_back(id);
        if (isPlane(*o) && o->visible) edit.everything = true;
    }

    if (edit.everything || structural || materialListChanged || !edit.lights.empty() ||
        environmentChanged) {
        update.snapshot =
            std::make_shared<const CompiledScene>(after, beforeSnapshot.get(), engine);
    } else if (!moved.empty() || !edit.retinted.empty()) {
        update.snapshot =
            std::make_shared<const CompiledScene>(beforeSnapshot->refitted(after, moved));
        edit.refitted = true;
    } else {
        update.snapshot = beforeSnapshot;
    }
    const CompiledScene& b = *beforeSnapshot;
    const CompiledScene& a = *update.snapshot;
    if (a.epsilon() != b.epsilon()) edit.everything = true;

    auto addRegion = [&](const Aabb& box) {
        if (!box.empty()) edit.regions.push_back(box);
    };
    for (ObjectId id : removed) addRegion(b.objectBounds(id));
    for (ObjectId id : added) addRegion(a.objectBounds(id));
    for (ObjectId id : moved) {
        const Aabb ob = b.objectBounds(id), nb = a.objectBounds(id);
        if (ob.min == nb.min && ob.max == nb.max && !reshadowed.count(id) &&
            std::find(edit.retinted.begin(), edit.retinted.end(), id) != edit.retinted.end())
            continue;  // A material change only: its pixels are retinted, not re-shaped.
        addRegion(ob);
        addRegion(nb);
    }
    return update;
}

}  // namespace rs
