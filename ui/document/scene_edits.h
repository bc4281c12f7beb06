// Document edits the designer offers (add, duplicate, remove, move, materials), as pure
// functions on a SceneDocument so commands and tests can use them alike.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/document.h"

namespace rs::ui {

/// Shapes the Add menu creates.
enum class ShapeKind { Sphere, Plane, Rectangle, Box };

/// A name based on `base` that no object, light or material of `doc` uses yet.
std::string uniqueName(const SceneDocument& doc, const std::string& base);
/// Adds a default shape centred at `at` (a plane through it, facing up); returns its id.
ObjectId addShape(SceneDocument& doc, ShapeKind kind, const Vec3& at);
/// Adds a mesh object for already loaded data, its origin at `at`; returns its id.
ObjectId addMesh(SceneDocument& doc, const std::string& file, std::shared_ptr<const MeshData> data,
                 const Vec3& at);
/// Adds a light of `type` at `at` (a spot aimed straight down from it, a sun slanting
/// down along (-1, -2, -1) with its glyph at `at`); returns its id.
ObjectId addLight(SceneDocument& doc, LightType type, const Vec3& at);
/// Duplicates object or light `id` (slightly offset); returns the copy's id or kNoObject.
ObjectId duplicate(SceneDocument& doc, ObjectId id);
/// Removes object or light `id`; false when there is none.
bool remove(SceneDocument& doc, ObjectId id);
/// Moves object or light `id` by `delta` (translate for shapes, point for planes; a spot's
/// target with its position).
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

// The material list (scenes/FORMAT.md: names are non-empty and unique among the materials).
/// Why `name` cannot be the name of material `current` (empty `current`: a new one); empty
/// when it can.
std::string materialNameError(const SceneDocument& doc, const std::string& current,
                              const std::string& name);
/// Adds a default material with a fresh name; returns the name.
std::string addMaterial(SceneDocument& doc);
/// Adds a copy of material `name` under a fresh name; returns it (empty when there is none).
std::string duplicateMaterial(SceneDocument& doc, const std::string& name);
/// Renames material `from` to `to` and every object that uses it; the error, or empty.
std::string renameMaterial(SceneDocument& doc, const std::string& from, const std::string& to);
/// Why material `name` cannot be deleted (it is used, or there is none); empty when it can.
std::string materialDeleteError(const SceneDocument& doc, const std::string& name);
/// Deletes material `name` when nothing uses it; the error (unchanged document), or empty.
std::string deleteMaterial(SceneDocument& doc, const std::string& name);
/// Gives the objects among `ids` material `name` (empty: the built-in grey), the whole object:
/// a mesh's parts lose their own materials; how many changed.
int assignMaterial(SceneDocument& doc, const std::vector<ObjectId>& ids, const std::string& name);

}  // namespace rs::ui
