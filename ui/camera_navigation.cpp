// Camera navigation math (turntable orbit around the target, keeping the up vector).
#include "camera_navigation.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace rs::ui {

void orbit(Camera& c, float yawDeg, float pitchDeg) {
    const Vec3 up = glm::normalize(c.up);
    Vec3 offset = c.position - c.target;
    offset = Vec3(glm::rotate(Mat4(1.0f), glm::radians(-yawDeg), up) * glm::vec4(offset, 0.0f));
    const Vec3 right = glm::cross(glm::normalize(-offset), up);
    if (glm::length(right) > 1e-6f) {
        const Vec3 pitched =
            Vec3(glm::rotate(Mat4(1.0f), glm::radians(-pitchDeg), glm::normalize(right)) *
                 glm::vec4(offset, 0.0f));
        // Stop short of the poles so the view never flips over the up vector.
        if (std::abs(glm::dot(glm::normalize(pitched), up)) < 0.99f) offset = pitched;
    }
    c.position = c.target + offset;
}

void pan(Camera& c, float dx, float dy) {
    const Vec3 forward = c.target - c.position;
    const float dist = glm::length(forward);
    const Vec3 right = glm::normalize(glm::cross(forward, c.up));
    const Vec3 up = glm::normalize(glm::cross(right, forward));
    const float height = c.projection == Projection::Orthographic
                             ? c.orthoHeight
                             : 2.0f * dist * std::tan(glm::radians(c.fovY) * 0.5f);
    const Vec3 move = (-right * dx + up * dy) * height;
    c.position += move;
    c.target += move;
}

void dolly(Camera& c, float factor) {
    if (c.projection == Projection::Orthographic) {
        c.orthoHeight = std::max(1e-3f, c.orthoHeight * (1.0f - factor));
        return;
    }
    const Vec3 forward = c.target - c.position;
    const float dist = glm::length(forward);
    const float step = std::clamp(factor, -1.0f, 0.9f) * dist;
    if (dist - step < 1e-3f) return;
    c.position += forward / dist * step;
}

void frame(Camera& c, const Vec3& center, float radius) {
    const Vec3 dir = glm::normalize(c.position - c.target);
    const float half = glm::radians(c.fovY) * 0.5f;
    const float dist = std::max(radius, 1e-3f) / std::sin(half) * 1.2f;
    c.target = center;
    c.position = center + dir * dist;
    if (c.projection == Projection::Orthographic) c.orthoHeight = 2.4f * radius;
}

}  // namespace rs::ui
