// Triangle mesh acceleration: bounds, the normal rule, and the lazily built triangle BVH.
#include "accel/mesh_accel.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rs {

MeshAccel::MeshAccel(std::shared_ptr<const MeshData> data, bool smooth)
    : data_(std::move(data)), smooth_(smooth) {
    if (!data_) return;
    const std::size_t count = data_->triangleCount();
    for (std::size_t i = 0; i < count; ++i) {
        if (!validTriangle(uint32_t(i))) continue;
        for (int k = 0; k < 3; ++k) bounds_.expand(data_->positions[data_->indices[3 * i + k]]);
    }
    // Normals are interpolated only when they can be: one per vertex.
    smooth_ = smooth_ && data_->normals.size() == data_->positions.size();
}

bool MeshAccel::validTriangle(uint32_t tri) const {
    const std::size_t vertexCount = data_->positions.size();
    const uint32_t* idx = &data_->indices[3 * std::size_t(tri)];
    return idx[0] < vertexCount && idx[1] < vertexCount && idx[2] < vertexCount;
}

void MeshAccel::ensureBvh() const {
    std::call_once(bvhOnce_, [this] {
        if (!data_) return;
        const std::size_t count = data_->triangleCount();
        triangles_.reserve(count);
        std::vector<Aabb> boxes;
        boxes.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
            // An out-of-range index leaves a zero triangle, which is never hit; it still takes
            // its slot so triangle i stays triangle i of the indices (normals are looked up by it).
            TriangleShape tri{};
            if (validTriangle(uint32_t(i))) {
                const uint32_t* idx = &data_->indices[3 * i];
                tri = TriangleShape::make(data_->positions[idx[0]], data_->positions[idx[1]],
                                          data_->positions[idx[2]]);
            }
            triangles_.push_back(tri);
            boxes.push_back(rs::bounds(tri));
        }
        bvh_.build(boxes);
    });
}

bool MeshAccel::intersectTriangle(uint32_t tri, const Ray& ray, float& t, float& b1,
                                  float& b2) const {
    if (!validTriangle(tri)) return false;
    const uint32_t* idx = &data_->indices[3 * std::size_t(tri)];
    // The same construction as ensureBvh's triangles, so the same bits.
    const TriangleShape shape = TriangleShape::make(
        data_->positions[idx[0]], data_->positions[idx[1]], data_->positions[idx[2]]);
    return rs::intersect(shape, ray, 0.0f, kInfinity, t, b1, b2);
}

Vec3 MeshAccel::normal(uint32_t tri, float b1, float b2) const {
    const uint32_t* idx = &data_->indices[3 * static_cast<std::size_t>(tri)];
    const Vec3& p0 = data_->positions[idx[0]];
    const Vec3 geometric =
        glm::normalize(glm::cross(data_->positions[idx[1]] - p0, data_->positions[idx[2]] - p0));
    if (!smooth_) return geometric;
    const auto& normals = data_->normals;
    const Vec3 n = (1.0f - b1 - b2) * normals[idx[0]] + b1 * normals[idx[1]] + b2 * normals[idx[2]];
    const float len2 = glm::dot(n, n);
    // Opposing vertex normals can cancel; the geometric normal is then the honest answer.
    return len2 > 0.0f ? n / std::sqrt(len2) : geometric;
}

bool MeshAccel::closestTriangle(const Ray& ray, float tmin, float& tmax, uint32_t& tri, float& b1,
                                float& b2) const {
    ensureBvh();
    // Remember the winner and its barycentrics.
    return bvh_.closestHit(ray, tmin, tmax, [&](uint32_t candidate, float& tFar) {
        float t, c1, c2;
        if (!rs::intersect(triangles_[candidate], ray, tmin, tFar, t, c1, c2)) return false;
        tFar = t;
        tri = candidate;
        b1 = c1;
        b2 = c2;
        return true;
    });
}

bool MeshAccel::intersect(const Ray& ray, float tmin, float& tmax, ShapeHit& hit) const {
    // The normal is worked out once, at the end.
    uint32_t hitTri = 0;
    float hitB1 = 0.0f, hitB2 = 0.0f;
    if (!closestTriangle(ray, tmin, tmax, hitTri, hitB1, hitB2)) return false;
    hit.t = tmax;
    hit.n = normal(hitTri, hitB1, hitB2);
    return true;
}

bool MeshAccel::triangleAt(const Vec3& p, const Vec3& n, uint32_t& tri, float& b1,
                           float& b2) const {
    if (!data_ || bounds_.empty()) return false;
    const float eps = std::max(1e-4f * glm::length(bounds_.max - bounds_.min), 1e-6f);
    // From p + eps n back through p to p - eps n: the surface at p lies halfway.
    float tmax = 2.0f * eps;
    return closestTriangle(Ray::make(p + eps * n, -n), 0.0f, tmax, tri, b1, b2);
}

bool MeshAccel::occluded(const Ray& ray, float tmin, float tmax) const {
    ensureBvh();
    return bvh_.anyHit(ray, tmin, tmax, [&](uint32_t tri) {
        float t, b1, b2;
        return rs::intersect(triangles_[tri], ray, tmin, tmax, t, b1, b2);
    });
}

}  // namespace rs
