// A ray's footprint on a surface: what a texture lookup filters over.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace rs {

/// The half-axes of the ellipse one pixel's cone of rays covers on a surface, in world units
/// (ray cones: Ray Tracing Gems, "Texture Level of Detail Strategies for Real-Time Ray
/// Tracing"). Zero axes point-sample.
struct Footprint {
    Vec3 a1{0.0f}, a2{0.0f};
};

/// The footprint of a cone of full width `width` (world units) arriving along unit `dir` at
/// a surface with unit normal `n`: stretched by 1 / |cos| along the direction's projection on
/// the surface, at most 100 times (grazing angles).
[[gnu::always_inline]] inline Footprint footprintAt(const Vec3& dir, const Vec3& n, float width) {
    if (!(width > 0.0f)) return {};
    const float half = 0.5f * width;
    const float cosine = std::abs(glm::dot(dir, n));
    Vec3 along = dir - n * glm::dot(dir, n);
    const float len = glm::length(along);
    if (len > 1e-6f) {
        along /= len;
    } else {  // Head-on: any direction in the surface.
        along = glm::normalize(std::abs(n.x) > 0.9f ? glm::cross(n, Vec3(0.0f, 1.0f, 0.0f))
                                                    : glm::cross(n, Vec3(1.0f, 0.0f, 0.0f)));
    }
    const Vec3 across = glm::cross(n, along);
    return {along * (half / std::max(cosine, 0.01f)), across * half};
}

}  // namespace rs
