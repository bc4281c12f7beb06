// The geometry a ray engine is built from: bounded primitives (in world space or in a frame
// of their own), the unbounded planes kept outside the tree, and the one test of a primitive.
#pragma once

#include <memory>
#include <variant>
#include <vector>

#include "accel/mesh_accel.h"
#include "geometry/shapes.h"
#include "scene/document.h"

namespace rs {

/// Object-to-world transform of a shape that is tested in its own frame.
struct Frame {
    Mat4 worldFromObject;
    Mat4 objectFromWorld;
    Mat3 dirToObject;    ///< Linear part of objectFromWorld.
    Mat3 normalToWorld;  ///< Inverse transpose of the world-from-object linear part.

    /// A world point and direction in the object's frame: the one transform every engine
    /// tests a ray with, so that their distances agree bit for bit.
    Vec3 pointToObject(const Vec3& p) const { return Vec3(objectFromWorld * glm::vec4(p, 1.0f)); }
    Vec3 directionToObject(const Vec3& d) const { return dirToObject * d; }
};

/// A mesh instance: the shared triangle mesh plus the instance's frame (always present).
struct MeshShape {
    std::shared_ptr<const MeshAccel> accel;
};

/// The closed set of bounded render shapes.
using BoundedShape = std::variant<SphereShape, RectangleShape, BoxShape, MeshShape>;

/// One bounded object of the snapshot. Without a frame the shape is stored in world space.
struct Primitive {
    BoundedShape shape;
    bool hasFrame = false;
    Frame frame;
    uint32_t material = 0;
    ObjectId id = kNoObject;
    Aabb worldBounds;
};

/// An unbounded plane, tested outside the tree (thesis 3.1).
struct PlanePrimitive {
    PlaneShape shape;
    uint32_t material;
    ObjectId id;
};

/// Closest hit of `ray` (world space) with `p` in (tmin, tmax): t and the unit outward world
/// normal. Every engine tests spheres, boxes and rectangles with this, so their answers agree.
/// Meshes go through their own BVH (MeshAccel) here; an engine may trace them its own way.
bool intersectPrimitive(const Primitive& p, const Ray& ray, float tmin, float tmax, ShapeHit& hit);

/// A light as the engine sees it: a sphere shadow rays end at (for candidate lists).
struct LightBounds {
    Vec3 center;
    float radius;
};

/// Everything an engine is built from. Shared, immutable: the snapshot holds the same vectors.
struct SceneGeometry {
    std::shared_ptr<const std::vector<Primitive>> primitives;
    std::shared_ptr<const std::vector<PlanePrimitive>> planes;
    std::vector<LightBounds> lights;
    float epsilon = 1e-4f;  ///< The snapshot's ray offset.
};

}  // namespace rs
