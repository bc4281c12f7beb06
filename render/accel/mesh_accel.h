// A triangle mesh ready for tracing: triangles plus their own BVH, in object space.
#pragma once

#include "accel/bvh.h"
#include "geometry/shapes.h"
#include "scene/mesh_data.h"

#include <memory>
#include <vector>

namespace rs {

/// Immutable once built; shared by every snapshot that shows the mesh (moving the object only
/// changes its instance transform, so the triangle BVH is never rebuilt on a move).
class MeshAccel {
public:
    /// Builds triangles and the BVH. `smooth` interpolates vertex normals when the data has them.
    MeshAccel(std::shared_ptr<const MeshData> data, bool smooth);

    /// Closest hit in (tmin, tmax); on a hit shrinks tmax and fills `hit` (object space normal).
    bool intersect(const Ray& ray, float tmin, float& tmax, ShapeHit& hit) const;
    /// Any hit in (tmin, tmax).
    bool occluded(const Ray& ray, float tmin, float tmax) const;

    const Aabb& bounds() const { return bvh_.bounds(); }
    /// The mesh data this was built from (snapshots reuse an accel for the same data).
    const std::shared_ptr<const MeshData>& data() const { return data_; }
    bool smooth() const { return smooth_; }
    std::size_t triangleCount() const { return triangles_.size(); }

private:
    std::shared_ptr<const MeshData> data_;
    std::vector<TriangleShape> triangles_;  ///< In BVH leaf order is not required; indexed.
    bool smooth_;
    Bvh bvh_;
};

}  // namespace rs
