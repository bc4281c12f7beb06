// The camera as the renderer uses it: an orthonormal frame that turns image points into rays.
#pragma once

#include "core/math.h"
#include "scene/document.h"

namespace rs {

/// Generates primary rays. Image x grows right, y grows down; (px, py) are continuous pixel
/// coordinates, so a pixel's centre is (i + 0.5, j + 0.5).
class CameraModel {
public:
    CameraModel() = default;
    CameraModel(const Camera& camera, int width, int height);

    /// The primary ray through image point (px, py), unit direction.
    Ray generateRay(float px, float py) const {
        const Vec3 column = columnTerm(px), row = rowTerm(py);
        return Ray::make(originOf(column, row), directionOf(column, row));
    }
    /// The parts of generateRay that depend on the image x alone and on the image y alone:
    /// a tile works each out once per column and once per row, with the bits of
    /// generateRay (its terms are added in the same order).
    Vec3 columnTerm(float px) const {
        return right_ * ((2.0f * px * invWidth_ - 1.0f) * halfWidth_);
    }
    Vec3 rowTerm(float py) const { return up_ * ((1.0f - 2.0f * py * invHeight_) * halfHeight_); }
    Vec3 originOf(const Vec3& column, const Vec3& row) const {
        return orthographic_ ? origin_ + column + row : origin_;
    }
    Vec3 directionOf(const Vec3& column, const Vec3& row) const {
        return orthographic_ ? forward_ : glm::normalize(forward_ + column + row);
    }
    /// generateRay's origins and directions for the image points of one row, image y py,
    /// whose columnTerm()s are columns[0, count).
    void rowRays(const Vec3* columns, std::size_t count, float py, Vec3* origins, Vec3* dirs) const;
    /// The cone (unit axis, half-angle in radians) holding every perspective ray through the
    /// pixels [x0, x1) x [y0, y1), any point of them; false for an orthographic camera, whose
    /// rays share a direction instead of an origin.
    bool tileCone(int x0, int y0, int x1, int y1, Vec3& axis, float& halfAngle) const;
    /// The image point where world point `p` projects; false when it is behind the camera.
    bool project(const Vec3& p, float& px, float& py) const;

    int width() const { return width_; }
    int height() const { return height_; }
    const Vec3& origin() const { return origin_; }
    const Vec3& forward() const { return forward_; }
    bool orthographic() const { return orthographic_; }
    // The terms of generateRay, for tracers that build many rays at once.
    const Vec3& right() const { return right_; }
    const Vec3& up() const { return up_; }
    float halfWidth() const { return halfWidth_; }
    float halfHeight() const { return halfHeight_; }
    float invWidth() const { return invWidth_; }
    float invHeight() const { return invHeight_; }

private:
    Vec3 origin_{0.0f}, forward_{0.0f, 0.0f, -1.0f}, right_{1.0f, 0.0f, 0.0f},
        up_{0.0f, 1.0f, 0.0f};
    float halfWidth_ = 1.0f, halfHeight_ = 1.0f;
    float invWidth_ = 1.0f, invHeight_ = 1.0f;
    int width_ = 1, height_ = 1;
    bool orthographic_ = false;
};

}  // namespace rs
