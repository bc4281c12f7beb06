// Triangle mesh acceleration: triangles built from indexed MeshData, a BVH over them, queries.
#include "accel/mesh_accel.h"

#include <cmath>
#include <utility>

namespace rs {

MeshAccel::MeshAccel(std::shared_ptr<const MeshData> data, bool smooth)
    : data_(std::move(data)), smooth_(smooth) {
    if (!data_) return;
    const std::size_t count = data_->triangleCount();
    const std::size_t vertexCount = data_->positions.size();
    triangles_.reserve(count);
    std::vector<Aabb> boxes;
    boxes.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const uint32_t* idx = &data_->indices[3 * i];
        // An out-of-range index leaves a zero triangle, which is never hit; it still takes its
        // slot so triangle i stays triangle i of the indices (normals are looked up by it).
        TriangleShape tri{};
        if (idx[0] < vertexCount && idx[1] < vertexCount && idx[2] < vertexCount)
            tri = TriangleShape::make(data_->positions[idx[0]], data_->positions[idx[1]],
                                      data_->positions[idx[2]]);
        triangles_.push_back(tri);
        boxes.push_back(rs::bounds(tri));
    }
    bvh_.build(boxes);
    // Normals are interpolated only when they can be: one per vertex.
    smooth_ = smooth_ && data_->normals.size() == vertexCount;
}

bool MeshAccel::intersect(const Ray& ray, float tmin, float& tmax, ShapeHit& hit) const {
    // Remember the winner and its barycentrics; the normal is worked out once, at the end.
    uint32_t hitTri = 0;
    float hitB1 = 0.0f, hitB2 = 0.0f;
    const bool found = bvh_.closestHit(ray, tmin, tmax, [&](uint32_t tri, float& tFar) {
        float t, b1, b2;
        if (!rs::intersect(triangles_[tri], ray, tmin, tFar, t, b1, b2)) return false;
        tFar = t;
        hitTri = tri;
        hitB1 = b1;
        hitB2 = b2;
        return true;
    });
    if (!found) return false;
    const TriangleShape& tri = triangles_[hitTri];
    hit.t = tmax;
    const Vec3 geometric = glm::normalize(glm::cross(tri.e1, tri.e2));
    hit.n = geometric;
    if (smooth_) {
        const uint32_t* idx = &data_->indices[3 * static_cast<std::size_t>(hitTri)];
        const auto& normals = data_->normals;
        const Vec3 n = (1.0f - hitB1 - hitB2) * normals[idx[0]] + hitB1 * normals[idx[1]] +
                       hitB2 * normals[idx[2]];
        const float len2 = glm::dot(n, n);
        // Opposing vertex normals can cancel; the geometric normal is then the honest answer.
        if (len2 > 0.0f) hit.n = n / std::sqrt(len2);
    }
    return true;
}

bool MeshAccel::occluded(const Ray& ray, float tmin, float tmax) const {
    return bvh_.anyHit(ray, tmin, tmax, [&](uint32_t tri) {
        float t, b1, b2;
        return rs::intersect(triangles_[tri], ray, tmin, tmax, t, b1, b2);
    });
}

}  // namespace rs
