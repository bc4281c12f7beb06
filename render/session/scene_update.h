// From one document to the next: what changed, and the snapshot for the new document.
#pragma once

#include <memory>
#include <vector>

#include "scene/document.h"
#include "snapshot/compiled_scene.h"

namespace rs {

/// A light as far as what it can reach goes: centre and radius (0 for a point light).
struct LightSphere {
    Vec3 position;
    float radius;
    /// Spot lights: the cone outside which the light adds nothing (its axis and the cosine
    /// of its falloff half-angle, as compileLight gives them).
    bool spot = false;
    Vec3 axis{0.0f, -1.0f, 0.0f};
    float cosFalloff = -1.0f;
};

/// What an edit changed, in the terms dirty regions need.
struct SceneEdit {
    bool everything = false;         ///< Camera, settings, lights, planes...: re-trace every pixel.
    bool displayOnly = false;        ///< Only tone mapping or exposure: nothing to re-trace.
    bool resized = false;            ///< Image size changed.
    std::vector<Aabb> regions;       ///< Old and new world bounds of changed bounded objects.
    std::vector<ObjectId> retinted;  ///< Objects whose material (or its definition) changed.
    /// Old and new spheres of changed lights (moved, recoloured, added, removed); a pixel
    /// none of them can light at any of its shading points keeps its colour.
    std::vector<LightSphere> lights;
    /// The environment changed (its image, intensity or rotation): pixels with a ray that
    /// escaped the scene re-trace.
    bool environment = false;
    ObjectId focus = kNoObject;  ///< An object the edit is about, for tile priority.
    bool refitted = false;       ///< The snapshot was refitted, not rebuilt.
    /// Anything to re-trace: marking can skip the edit otherwise.
    bool traced() const {
        return everything || environment || !regions.empty() || !retinted.empty() ||
               !lights.empty();
    }
    bool any() const { return displayOnly || traced(); }
};

/// A new snapshot and the edit that leads to it.
struct SceneUpdate {
    std::shared_ptr<const CompiledScene> snapshot;
    SceneEdit edit;
};

/// Compares `before` and `after` (objects and lights matched by id) and builds the snapshot of
/// `after`: a refit of `beforeSnapshot` when only transforms, shapes or object materials
/// changed, a rebuild (reusing mesh BVHs) otherwise. The snapshot traces with `engine`; a
/// snapshot of another engine is rebuilt whole.
SceneUpdate updateScene(const SceneDocument& before,
                        const std::shared_ptr<const CompiledScene>& beforeSnapshot,
                        const SceneDocument& after, EngineKind engine = EngineKind::Embree);

}  // namespace rs
