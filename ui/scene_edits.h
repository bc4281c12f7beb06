// Document edits the designer offers (add, duplicate, remove, move, materials), as pure
// functions on a SceneDocument so commands and tests can use them alike.
#pragma once

#include "scene/document.h"

#include <memory>
#include <string>

namespace rs::ui {

/// Shapes the Add menu creates.
enum class ShapeKind { Sphere, Plane, Rectangle, Box };

/// A name based on `base` that no object, light or material of `doc` uses yet.
std::string uniqueName(const SceneDocument& doc, const std::string& base);
/// Adds a default shape in front of the camera; returns its id.
ObjectId addShape(SceneDocument& doc, ShapeKind kind);
/// Adds a mesh object for already loaded data; returns its id.
ObjectId addMesh(SceneDocument& doc, const std::string& file, std::shared_ptr<const MeshData> data);
/// Adds a point or sphere light above the camera target; returns its id.
ObjectId addLight(SceneDocument& doc, LightType type);
/// Duplicates object or light `id` (slightly offset); returns the copy's id or kNoObject.
ObjectId duplicate(SceneDocument& doc, ObjectId id);
/// Removes object or light `id`; false when there is none.
bool remove(SceneDocument& doc, ObjectId id);
/// Moves object or light `id` by `delta` (translate for shapes, point for planes).
void moveBy(SceneDocument& doc, ObjectId id, const Vec3& delta);
/// Replaces object or light `id` of `doc` with its state in `from` (nothing when either lacks it).
void restoreEntity(SceneDocument& doc, const SceneDocument& from, ObjectId id);
/// Renames object or light `id`; false (unchanged) when the name is empty or taken.
bool rename(SceneDocument& doc, ObjectId id, const std::string& name);
/// Number of objects whose material is `name`.
int materialUsers(const SceneDocument& doc, const std::string& name);
/// Gives object `id` its own copy of its material; returns the new material's name.
std::string makeMaterialUnique(SceneDocument& doc, ObjectId id);
/// Finds a material by name for editing.
Material* findMaterial(SceneDocument& doc, const std::string& name);

}  // namespace rs::ui
