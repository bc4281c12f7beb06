// Move, rotate and scale of objects and lights about a pivot: the document side of G, R, S.
#pragma once

#include <optional>
#include <vector>

#include "scene/document.h"

namespace rs::ui {

/// World centre of an object (its shape's centre through its transform; a plane's point) or
/// a light's position; nullopt when `id` is neither.
std::optional<Vec3> entityCentre(const SceneDocument& doc, ObjectId id);
/// World bounds of object `id` (empty for planes, unknown ids and meshes without data).
Aabb worldBounds(const SceneDocument& doc, ObjectId id);
/// World bounds of `o` (empty for planes and meshes without data): loops over every object
/// use this, not a lookup by id each.
Aabb worldBounds(const Object& o);
/// The point gestures act about: the mean of the entities' centres.
Vec3 pivotOf(const SceneDocument& doc, const std::vector<ObjectId>& ids);
/// Moves every entity by `delta`.
void translateAll(SceneDocument& doc, const std::vector<ObjectId>& ids, const Vec3& delta);
/// Rotates every entity by `degrees` about the line through `pivot` along unit `axis` (a
/// spot's target with it, a sun's direction).
void rotateAll(SceneDocument& doc, const std::vector<ObjectId>& ids, const Vec3& pivot,
               const Vec3& axis, float degrees);
/// Scales every entity about `pivot` by `factors` along the columns of the orthonormal
/// `axes` (the world's, or the gizmo's local ones); sphere lights scale their radius by the
/// largest factor; planes only move; a spot moves with its target (its cone unchanged).
void scaleAll(SceneDocument& doc, const std::vector<ObjectId>& ids, const Vec3& pivot,
              const Vec3& factors, const Mat3& axes = Mat3(1.0f));
/// Euler angles in degrees (X, then Y, then Z, as Transform::rotate) of rotation matrix `r`.
Vec3 eulerDegreesOf(const Mat4& r);

}  // namespace rs::ui
