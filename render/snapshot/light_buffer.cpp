// Light buffer construction: which objects each direction cell around a light can see.
#include "snapshot/light_buffer.h"

#include <algorithm>
#include <array>

namespace rs {

// The bound in light_buffer.h: a shadow ray from shading point p leaves o = p + eps n toward a
// light sample q (|q - L| <= R) with unit direction w = (q - p) / |q - p| and stops at
// t = |q - p| - eps, where it is at q + eps (n - w). Its point at t = s (|q - p| - eps), s in
// [0, 1], is o + s (q + eps (n - w) - o); the point of [o, L] with the same s is o + s (L - o).
// They differ by s (q - L + eps (n - w)), at most R + 2 eps.

namespace {

constexpr int kRes = LightBuffer::kResolution;
constexpr int kCells = 6 * kRes * kRes;
/// Angular slack for rounding in the cell lookup and the cone test (radians).
constexpr float kAngleMargin = 1e-3f;

/// The direction through face coordinates (a, b) in [-1, 1] of cube face `face`, laid out as
/// LightBuffer::candidates reads it.
Vec3 faceDirection(int face, float a, float b) {
    const int axis = face / 2;
    Vec3 d(0.0f);
    d[axis] = (face & 1) ? -1.0f : 1.0f;
    d[(axis + 1) % 3] = a;
    d[(axis + 2) % 3] = b;
    return d;
}

/// Each cell's centre direction and the cosine and sine of its angular radius plus margin.
struct CellCone {
    Vec3 axis;
    float cosRadius, sinRadius;
};

const std::array<CellCone, kCells>& cellCones() {
    static const std::array<CellCone, kCells> cones = [] {
        std::array<CellCone, kCells> out{};
        auto coord = [](int i) { return 2.0f * float(i) / float(kRes) - 1.0f; };
        for (int face = 0; face < 6; ++face) {
            for (int j = 0; j < kRes; ++j) {
                for (int i = 0; i < kRes; ++i) {
                    const float a0 = coord(i), a1 = coord(i + 1), b0 = coord(j), b1 = coord(j + 1);
                    const Vec3 c = glm::normalize(faceDirection(face, 0.5f * (a0 + a1), 0.5f * (b0 + b1)));
                    // A cell is a convex spherical quadrilateral: its farthest point from the
                    // centre is a corner.
                    float cosMin = 1.0f;
                    for (float a : {a0, a1})
                        for (float b : {b0, b1})
                            cosMin = std::min(cosMin, glm::dot(c, glm::normalize(faceDirection(face, a, b))));
                    const float radius = std::acos(std::clamp(cosMin, -1.0f, 1.0f)) + kAngleMargin;
                    out[std::size_t((face * kRes + j) * kRes + i)] = {c, std::cos(radius), std::sin(radius)};
                }
            }
        }
        return out;
    }();
    return cones;
}

}  // namespace

LightBuffer::LightBuffer(const Vec3& light, float reach, std::span<const BoundingSphere> objects,
                         std::span<const BufferPlane> planes)
    : light_(light) {
    // Each object as the cone it fills seen from the light, and the nearest distance of its
    // grown sphere (a shadow segment reaches at most |o - L| + reach from the light).
    struct ObjectCone {
        Vec3 axis;
        float cosAngle, sinAngle;
        float minDistance;
        bool everywhere;
    };
    std::vector<ObjectCone> cones;
    cones.reserve(objects.size());
    for (const BoundingSphere& s : objects) {
        const Vec3 d = s.center - light;
        const float dist = glm::length(d);
        // Grown by the reach and by a relative slack far above the exact tests' rounding.
        const float r = s.radius + reach + 1e-5f * (dist + s.radius);
        if (!(dist > r)) {  // The light is inside (or the sphere is not finite): every cell.
            cones.push_back({Vec3(0.0f), -1.0f, 0.0f, 0.0f, true});
            continue;
        }
        const float sinAngle = r / dist;
        cones.push_back({d / dist, std::sqrt(1.0f - sinAngle * sinAngle), sinAngle,
                         (dist - r) * (1.0f - 1e-5f), false});
    }

    // A ray from the light in direction d meets plane k at t > 0 when d . toward < 0, with
    // `toward` the normal flipped to point at the light's side, at t = height / -(d . toward).
    // Within the slack of the plane the shadow segments may cross it in any direction.
    struct PlaneSide {
        Vec3 toward;
        float height;  ///< The light's distance from the plane, less the slack.
        bool everywhere;
    };
    std::vector<PlaneSide> sides;
    sides.reserve(planes.size());
    for (const BufferPlane& p : planes) {
        const float side = glm::dot(light - p.point, p.normal);
        const float slack = reach + 1e-5f * (std::abs(side) + glm::length(light - p.point));
        const float height = std::abs(side) - slack;
        sides.push_back({side > 0.0f ? p.normal : -p.normal, height, !(height > 0.0f)});
    }

    const auto& cells = cellCones();
    start_.resize(kCells + 1);
    for (std::size_t c = 0; c < cells.size(); ++c) {
        start_[c] = uint32_t(entries_.size());
        const CellCone& cell = cells[c];
        for (std::size_t k = 0; k < cones.size(); ++k) {
            const ObjectCone& o = cones[k];
            if (o.everywhere) {
                entries_.push_back({uint32_t(k), 0.0f});
                continue;
            }
            // Overlap when the angle between the axes is at most the sum of the half-angles,
            // which stays below 180 degrees, where the cosine falls monotonically.
            const float cosSum = o.cosAngle * cell.cosRadius - o.sinAngle * cell.sinRadius;
            if (glm::dot(o.axis, cell.axis) >= cosSum)
                entries_.push_back({uint32_t(k), o.minDistance * o.minDistance});
        }
        for (std::size_t k = 0; k < sides.size(); ++k) {
            const PlaneSide& p = sides[k];
            if (p.everywhere) {
                entries_.push_back({kPlaneBit | uint32_t(k), 0.0f});
                continue;
            }
            // The steepest descent toward the plane over the cell: cos of the angle between
            // the axis and -toward, less the cell radius (1 when the cell contains -toward).
            const float cosAxis = -glm::dot(p.toward, cell.axis);
            const float sinAxis = std::sqrt(std::max(0.0f, 1.0f - cosAxis * cosAxis));
            const float steepest = cosAxis >= cell.cosRadius
                                       ? 1.0f
                                       : cosAxis * cell.cosRadius + sinAxis * cell.sinRadius;
            if (!(steepest > 0.0f)) continue;  // Every direction of the cell leaves the plane.
            // A segment from the light must run height / steepest to come within the slack.
            const float minDistance = std::min(p.height / steepest, p.height * 1e6f) * (1.0f - 1e-5f);
            entries_.push_back({kPlaneBit | uint32_t(k), minDistance * minDistance});
        }
    }
    start_[kCells] = uint32_t(entries_.size());
}

float LightBuffer::averageCandidates() const {
    return start_.empty() ? 0.0f : float(entries_.size()) / float(kCells);
}

}  // namespace rs
