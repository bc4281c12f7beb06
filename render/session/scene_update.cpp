// Document diffing for incremental rendering: everything, regions, or material changes.
#include "session/scene_update.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/input_file.h"
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

/// Whether `image`, shown through `opened` by the applied snapshot, was saved again since it
/// was opened (from a paint program, say): the document is the same, the picture is not.
/// One stat().
bool resavedSince(const ImageFile& image, const TextureHandle& opened) {
    return !image.source().empty() && !(fileStampOf(image.source()) == opened.file);
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

/// Document-wide changes: the image's sides, the camera and traced settings (everything),
/// the environment (its file saved again included), lights and display-only settings. True
/// when the environment changed.
bool diffDocumentWide(const SceneDocument& before, const CompiledScene& beforeSnapshot,
                      const SceneDocument& after, SceneEdit& edit) {
    edit.resized =
        before.render.width != after.render.width || before.render.height != after.render.height;
    if (!(before.camera == after.camera) || !sameTracedSettings(before.render, after.render))
        edit.everything = true;
    // The environment is seen only by rays that leave the scene (it lights nothing).
    const bool environmentChanged =
        !(before.environment == after.environment) ||
        (after.environment.present() &&
         resavedSince(after.environment.image, beforeSnapshot.environment().texture));
    edit.environment = environmentChanged && !edit.everything;
    edit.lights = changedLights(before.lights, after.lights);
    edit.displayOnly = !edit.everything && (before.render.tonemap != after.render.tonemap ||
                                            before.render.exposure != after.render.exposure);
    return environmentChanged;
}

/// Materials: by name; a changed, added or removed definition retints its users, and so
/// does a texture file saved again since the applied snapshot opened it.
struct MaterialDiff {
    std::set<std::string> changed;  ///< Names whose definition changed, appeared or went.
    bool listChanged = false;       ///< Materials added, removed or reordered.
};

MaterialDiff diffMaterials(const SceneDocument& before, const CompiledScene& beforeSnapshot,
                           const SceneDocument& after) {
    MaterialDiff d;
    d.listChanged = before.materials.size() != after.materials.size();
    const auto& compiled = beforeSnapshot.materials();  // the built-in grey first
    for (std::size_t i = 0; i < after.materials.size(); ++i) {
        const Material* old = before.findMaterial(after.materials[i].name);
        const auto* image = std::get_if<ImageTexture>(&after.materials[i].pattern);
        const std::size_t slot = old ? std::size_t(old - before.materials.data()) + 1 : 0;
        if (!old || !sameMaterialData(*old, after.materials[i]) ||
            (image && slot < compiled.size() &&
             resavedSince(image->image, compiled[slot].pattern.texture)))
            d.changed.insert(after.materials[i].name);
        if (i >= before.materials.size() || before.materials[i].name != after.materials[i].name)
            d.listChanged = true;
    }
    for (const Material& m : before.materials)
        if (!after.findMaterial(m.name)) d.changed.insert(m.name);
    return d;
}

/// Whether any material of `o` passes `test`.
template <class Test>
bool anyMaterial(const Object& o, Test test) {
    bool any = false;
    forEachMaterialOf(o, [&](const std::string& name) { any = any || test(name); });
    return any;
}

/// Objects: which moved, appeared or went (their old and new bounds are the edit's regions).
class ObjectDiff {
public:
    ObjectDiff(const SceneDocument& before, const SceneDocument& after,
               const MaterialDiff& materials, SceneEdit& edit)
        : before_(before), after_(after), materials_(materials), edit_(edit) {}

    /// Compares every object of `before` with its namesake in `after`.
    void run() {
        // Objects kept in place: the document diff names the changed ones without visiting
        // the rest, unless a material definition changed (then its users are found by
        // walking).
        const DocumentChange change = describeChange(before_, after_);
        if (!change.objectsRestructured && materials_.changed.empty()) {
            for (const DocumentChange::ObjectEdit& e : change.objects)
                compare(before_.objects[e.index], after_.objects[e.index]);
            return;
        }
        std::map<ObjectId, const Object*> old;
        for (const Object& o : before_.objects) old[o.id] = &o;
        for (const Object& o : after_.objects) {
            auto it = old.find(o.id);
            if (it == old.end()) {
                added.push_back(o.id);
                structural = true;
                if (isPlane(o) && o.visible) edit_.everything = true;
                continue;
            }
            const Object& prev = *it->second;
            old.erase(it);
            compare(prev, o);
        }
        for (const auto& [id, o] : old) {
            structural = true;
            removed.push_back(id);
            if (isPlane(*o) && o->visible) edit_.everything = true;
        }
    }

    std::vector<ObjectId> moved, added, removed;
    std::set<ObjectId> reshadowed;  ///< Retinted objects whose filtered shadows changed.
    bool structural = false;        ///< Objects added, removed, shown, hidden or retyped.

private:
    /// Glass filters the shadows it casts (scenes/FORMAT.md "Shadows"): a material change of
    /// an object that is or was transparent reaches every pixel whose shadow rays cross it.
    bool filters(const SceneDocument& doc, const std::string& name) const {
        const Material* m = doc.findMaterial(name);
        return !doc.render.opaqueShadows && m && m->transparency > 0.0f;
    }
    bool castsFilteredShadow(const Object& prev, const Object& o) const {
        return anyMaterial(prev, [&](const std::string& m) { return filters(before_, m); }) ||
               anyMaterial(o, [&](const std::string& m) { return filters(after_, m); });
    }

    void compare(const Object& prev, const Object& o) {
        const bool shapeChanged =
            !(prev.geometry == o.geometry) || !(prev.transform == o.transform);
        const bool kindChanged = prev.geometry.index() != o.geometry.index();
        const bool materialChanged =
            prev.material != o.material ||
            anyMaterial(o, [&](const std::string& m) { return materials_.changed.count(m) > 0; });
        if (isPlane(o) || isPlane(prev)) {
            if (shapeChanged || kindChanged || prev.visible != o.visible)
                edit_.everything = true;
            else if (materialChanged && o.visible && castsFilteredShadow(prev, o))
                edit_.everything = true;
            else if (materialChanged && o.visible)
                edit_.retinted.push_back(o.id);
            structural |= kindChanged || prev.visible != o.visible;
            return;
        }
        if (kindChanged || prev.visible != o.visible || meshChanged(prev, o)) {
            structural = true;
            added.push_back(o.id);
            removed.push_back(o.id);
            edit_.focus = o.id;
        } else if (shapeChanged && o.visible) {
            moved.push_back(o.id);
            edit_.focus = o.id;
        } else if (materialChanged && o.visible) {
            moved.push_back(o.id);  // Recompiled for its material index; bounds unchanged.
            edit_.retinted.push_back(o.id);
            if (castsFilteredShadow(prev, o)) reshadowed.insert(o.id);
        }
    }

    const SceneDocument& before_;
    const SceneDocument& after_;
    const MaterialDiff& materials_;
    SceneEdit& edit_;
};

/// The snapshot of `after`: rebuilt (reusing mesh BVHs), refitted, or the same.
std::shared_ptr<const CompiledScene> snapshotAfter(
    const SceneDocument& after, const std::shared_ptr<const CompiledScene>& beforeSnapshot,
    EngineKind engine, bool rebuild, const std::vector<ObjectId>& moved, SceneEdit& edit) {
    if (rebuild) return std::make_shared<const CompiledScene>(after, beforeSnapshot.get(), engine);
    if (!moved.empty() || !edit.retinted.empty()) {
        edit.refitted = true;
        return std::make_shared<const CompiledScene>(beforeSnapshot->refitted(after, moved));
    }
    return beforeSnapshot;
}

/// The edit's regions: the old bounds of what went, the new of what came, both of what moved
/// (a material change alone re-shapes nothing: its pixels are retinted).
void addRegions(const ObjectDiff& objects, const CompiledScene& b, const CompiledScene& a,
                SceneEdit& edit) {
    auto addRegion = [&](const Aabb& box) {
        if (!box.empty()) edit.regions.push_back(box);
    };
    for (ObjectId id : objects.removed) addRegion(b.objectBounds(id));
    for (ObjectId id : objects.added) addRegion(a.objectBounds(id));
    for (ObjectId id : objects.moved) {
        const Aabb ob = b.objectBounds(id), nb = a.objectBounds(id);
        if (ob.min == nb.min && ob.max == nb.max && !objects.reshadowed.count(id) &&
            std::find(edit.retinted.begin(), edit.retinted.end(), id) != edit.retinted.end())
            continue;  // A material change only: its pixels are retinted, not re-shaped.
        addRegion(ob);
        addRegion(nb);
    }
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
    const bool environmentChanged = diffDocumentWide(before, *beforeSnapshot, after, edit);
    const MaterialDiff materials = diffMaterials(before, *beforeSnapshot, after);
    ObjectDiff objects(before, after, materials, edit);
    objects.run();
    const bool rebuild = edit.everything || objects.structural || materials.listChanged ||
                         !edit.lights.empty() || environmentChanged;
    update.snapshot = snapshotAfter(after, beforeSnapshot, engine, rebuild, objects.moved, edit);
    if (update.snapshot->epsilon() != beforeSnapshot->epsilon()) edit.everything = true;
    addRegions(objects, *beforeSnapshot, *update.snapshot, edit);
    return update;
}

}  // namespace rs
