// A triangle mesh ready for tracing: its data, bounds and normal rule, and (built on first
// use) the thesis's triangle BVH, all in object space.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "accel/bvh.h"
#include "geometry/shapes.h"
#include "scene/mesh_data.h"

namespace rs {

/// Immutable once built; shared by every snapshot that shows the mesh (moving the object only
/// changes its instance transform, so the triangles are never rebuilt on a move). The
/// triangle BVH is only built for the built-in engine (ensureBvh), so a scene traced with
/// Embree never pays for it.
class MeshAccel {
public:
    /// Computes the bounds. `smooth` interpolates vertex normals when the data has them.
    MeshAccel(std::shared_ptr<const MeshData> data, bool smooth);

    /// Builds the triangle list and BVH once; safe to call from several threads.
    void ensureBvh() const;

    /// Closest hit in (tmin, tmax); on a hit shrinks tmax and fills `hit` (object space normal).
    bool intersect(const Ray& ray, float tmin, float& tmax, ShapeHit& hit) const;
    /// Closest hit in (tmin, tmax) through the triangle BVH: on a hit shrinks tmax and gives
    /// the triangle's index and barycentrics (b1 weighs its second vertex, b2 its third).
    bool closestTriangle(const Ray& ray, float tmin, float& tmax, uint32_t& tri, float& b1,
                         float& b2) const;
    /// The triangle under object-space point `p` on the surface, with unit normal `n` there:
    /// the closest along the short segment p + n s, s in (-eps, eps), eps = 1e-4 of the
    /// bounds' diagonal (at least 1e-6). Every engine reports a hit as its point and normal,
    /// so texture coordinates found this way agree between engines. Builds the BVH (ensureBvh).
    bool triangleAt(const Vec3& p, const Vec3& n, uint32_t& tri, float& b1, float& b2) const;
    /// Any hit in (tmin, tmax).
    bool occluded(const Ray& ray, float tmin, float tmax) const;

    /// The unit object-space normal at barycentrics (b1, b2) of triangle `tri`: the
    /// interpolated vertex normal when smooth, else the geometric one, cross(p1 - p0, p2 - p0)
    /// normalised. Every engine's smooth mesh hits get their normal here; Embree's flat hits
    /// take the same cross product from Embree (its Ng), which it has already computed.
    Vec3 normal(uint32_t tri, float b1, float b2) const;
    /// The project's triangle test (Moeller-Trumbore) of triangle `tri` alone, over (0, inf):
    /// distance and barycentrics, for engines that found the triangle by other means.
    bool intersectTriangle(uint32_t tri, const Ray& ray, float& t, float& b1, float& b2) const;
    /// Triangle `tri`'s first vertex (a point on its plane); `tri` must be valid.
    const Vec3& firstVertex(uint32_t tri) const {
        return data_->positions[data_->indices[3 * std::size_t(tri)]];
    }
    /// True when triangle `tri` has three valid vertex indices (others are never hit).
    bool validTriangle(uint32_t tri) const;

    const Aabb& bounds() const { return bounds_; }
    /// The mesh data this was built from (snapshots reuse an accel for the same data).
    const std::shared_ptr<const MeshData>& data() const { return data_; }
    bool smooth() const { return smooth_; }
    std::size_t triangleCount() const { return data_ ? data_->triangleCount() : 0; }

private:
    std::shared_ptr<const MeshData> data_;
    bool smooth_;
    Aabb bounds_;
    mutable std::once_flag bvhOnce_;
    mutable std::vector<TriangleShape> triangles_;  ///< Triangle i of the indices (ensureBvh).
    mutable Bvh bvh_;
};

}  // namespace rs
