// Camera frame set-up and projection of world points to the image (for dirty regions, picking).
#include "snapshot/camera_model.h"

#include <algorithm>
#include <cmath>

namespace rs {

CameraModel::CameraModel(const Camera& camera, int width, int height)
    : width_(width), height_(height), orthographic_(camera.projection == Projection::Orthographic) {
    origin_ = camera.position;
    forward_ = glm::normalize(camera.target - camera.position);
    right_ = glm::normalize(glm::cross(forward_, camera.up));
    up_ = glm::cross(right_, forward_);
    float aspect = float(width) / float(height);
    halfHeight_ =
        orthographic_ ? 0.5f * camera.orthoHeight : std::tan(glm::radians(camera.fovY) * 0.5f);
    halfWidth_ = halfHeight_ * aspect;
    invWidth_ = 1.0f / float(width);
    invHeight_ = 1.0f / float(height);
}

void CameraModel::rowRays(const Vec3* columns, std::size_t count, float py, Vec3* origins,
                          Vec3* dirs) const {
    const Vec3 row = rowTerm(py);
    if (orthographic_) {
        for (std::size_t i = 0; i < count; ++i)
            origins[i] = originOf(columns[i], row), dirs[i] = forward_;
        return;
    }
    for (std::size_t i = 0; i < count; ++i)
        origins[i] = origin_, dirs[i] = directionOf(columns[i], row);
}

bool CameraModel::tileCone(int x0, int y0, int x1, int y1, Vec3& axis, float& halfAngle) const {
    if (orthographic_) return false;
    // The directions through the tile's image rectangle are the convex combinations of its
    // corners' directions, so a cone around the corners holds them all.
    Vec3 corners[4];
    int k = 0;
    for (int y : {y0, y1})
        for (int x : {x0, x1}) corners[k++] = generateRay(float(x), float(y)).dir;
    axis = glm::normalize(corners[0] + corners[1] + corners[2] + corners[3]);
    float cosMin = 1.0f;
    for (const Vec3& c : corners) cosMin = std::min(cosMin, glm::dot(axis, c));
    halfAngle = std::acos(std::clamp(cosMin, -1.0f, 1.0f));
    return true;
}

bool CameraModel::project(const Vec3& p, float& px, float& py) const {
    Vec3 d = p - origin_;
    float z = glm::dot(d, forward_);
    float u, v;
    if (orthographic_) {
        u = glm::dot(d, right_);
        v = glm::dot(d, up_);
    } else {
        if (z <= 0.0f) return false;
        u = glm::dot(d, right_) / z;
        v = glm::dot(d, up_) / z;
    }
    px = (u / halfWidth_ + 1.0f) * 0.5f * float(width_);
    py = (1.0f - v / halfHeight_) * 0.5f * float(height_);
    return true;
}

}  // namespace rs
