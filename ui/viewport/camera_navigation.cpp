// Camera navigation math (turntable orbit, keeping the view upright).
#include "viewport/camera_navigation.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace rs::ui {

namespace {

/// The camera moved rigidly by `m` about `pivot`: the image turns with it.
Camera rotated(const Camera& c, const Mat4& m, const Vec3& pivot) {
    Camera r = c;
    r.position = pivot + Vec3(m * glm::vec4(c.position - pivot, 0.0f));
    r.target = pivot + Vec3(m * glm::vec4(c.target - pivot, 0.0f));
    r.up = Vec3(m * glm::vec4(c.up, 0.0f));
    return r;
}

/// The up vector the renderer makes of the hint: orthogonal to the view direction.
Vec3 trueUp(const Camera& c) {
    const Vec3 forward = glm::normalize(c.target - c.position);
    const Vec3 right = glm::cross(forward, c.up);
    if (glm::length(right) < 1e-6f) return glm::normalize(c.up);
    return glm::normalize(glm::cross(glm::normalize(right), forward));
}

}  // namespace

void orbitAround(Camera& c, const Vec3& pivot, const Vec3& worldUp, float yawDeg, float pitchDeg) {
    const Vec3 up = glm::normalize(worldUp);
    Camera r = rotated(c, glm::rotate(Mat4(1.0f), glm::radians(-yawDeg), up), pivot);
    const Vec3 right = glm::cross(r.target - r.position, r.up);
    if (glm::length(right) > 1e-6f) {
        const Mat4 pitch = glm::rotate(Mat4(1.0f), glm::radians(-pitchDeg), glm::normalize(right));
        const Camera p = rotated(r, pitch, pivot);
        // The up hint turns with the view, so a top view (looking along -up) can pitch out of
        // it; a pitch that would turn the image upside down is refused.
        if (glm::dot(trueUp(p), up) > -1e-3f) r = p;
    }
    // Away from the poles the world up gives the same image and keeps the hint clean for
    // "Scene Camera from View".
    const Vec3 forward = glm::normalize(r.target - r.position);
    if (std::abs(glm::dot(forward, up)) < 0.999f) r.up = up;
    c.position = r.position;
    c.target = r.target;
    c.up = r.up;
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

void frame(Camera& c, const Vec3& center, float radius, float maxDistance) {
    const Vec3 dir = glm::normalize(c.position - c.target);
    const float half = glm::radians(c.fovY) * 0.5f;
    const float dist =
        std::min(std::max(radius, 1e-3f) / std::sin(half) * 1.2f, std::max(maxDistance, 1e-3f));
    c.target = center;
    c.position = center + dir * dist;
    if (c.projection == Projection::Orthographic) c.orthoHeight = 2.4f * radius;
}

void alignView(Camera& c, const Vec3& viewDir, const Vec3& up) {
    const float dist = std::max(glm::length(c.target - c.position), 1e-3f);
    c.position = c.target - glm::normalize(viewDir) * dist;
    c.up = up;
}

}  // namespace rs::ui
