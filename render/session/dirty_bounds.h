// The dirty region's second form of the shading path, as conservative bounds: which side of
// a shading point the integrator shades, which lights can add to it, and where the shadow
// rays toward a light can go. Each bound must hold for the integrator's own rule (face_hits,
// light_sampling: the face-forward turn, the horizon and spot listing, the light's disk
// samples); tests/unit/dirty_bounds_test.cpp checks them against it.
#pragma once

#include <cmath>

#include "core/math.h"
#include "session/scene_update.h"
#include "snapshot/compiled_scene.h"

namespace rs {

/// How close to grazing (|n . toEye| over |toEye|) a shading point is taken to face either
/// way: the integrator turns the normal against the ray's own direction, which rounds
/// differently from the direction to the eye used here.
constexpr float kGrazingSlack = 1e-4f;

/// The integrator's face-forward rule (integrator/face_hits.cpp: the normal is turned toward
/// the incoming camera ray) seen from the eye: `ns` = the geometric normal `n` turned toward
/// `toEye` (from the point toward the eye). False when the point is too close to grazing to
/// tell which way the integrator turned it.
inline bool faceViewer(const Vec3& n, const Vec3& toEye, Vec3& ns) {
    const float facing = glm::dot(n, toEye);
    if (std::abs(facing) <= kGrazingSlack * glm::length(toEye)) return false;
    ns = facing > 0.0f ? n : -n;
    return true;
}

/// How far (in cosine) outside a spot light's falloff cone a point must lie to be left alone:
/// the cone test here and the integrator's round differently.
constexpr float kSpotConeSlack = 1e-4f;

/// Whether light `l` can add to the shading point `p` with normal `ns` facing the viewer:
/// false only when the light's sphere lies wholly below the point's horizon (the integrator
/// lists no sample with n . toLight <= 0) by more than `slack`, or the point lies outside a
/// spot light's falloff cone (spotFactor is 0 there).
inline bool lightMayReach(const Vec3& p, const Vec3& ns, const LightSphere& l, float slack) {
    const Vec3 toPoint = p - l.position;
    if (l.spot &&
        glm::dot(l.axis, toPoint) < (l.cosFalloff - kSpotConeSlack) * glm::length(toPoint))
        return false;
    return glm::dot(ns, -toPoint) > -(l.radius + slack);
}

/// How much wider than exact the shadow cone is taken, per unit of a point's distance from
/// the region's centre (and of the sphere's radius): a hundred times float rounding, which
/// the axis toward a light kSunDistance away carries (its position is rounded to 8 units).
constexpr float kConeSlack = 1e-5f;

/// The cone a region's bounding sphere (grown by the light's radius) subtends from a light:
/// a point outside it cannot have a shadow ray to that light crossing the region. No
/// divisions or roots per test, so it pre-filters the exact segment test cheaply.
/// Points are measured from the sphere's centre, never from the light: for a sun, a point
/// kSunDistance (1e8) away, p - light keeps none of the digits that place p (floats are 8
/// apart there), and the cosine of the cone's half-angle (a few units at 1e8) rounds to 1, so
/// the old test from the apex left out most of the points the sun's shadow rays reach the
/// region from. From the centre the same cone is, for a sun, a cylinder a few units wide.
struct ShadowCone {
    Vec3 centre;    ///< Sphere centre.
    Vec3 axis;      ///< Unit, from the light toward the centre.
    float radius;   ///< Grown sphere radius (without the pixel's own hit radius).
    float dist;     ///< Light to sphere centre.
    float invDist;  ///< 1 / dist (0 when the light sits at the centre).
    /// True when a segment from `p` (within `slack` of it) to the light may cross the region.
    bool mayContain(const Vec3& p, float slack) const {
        const Vec3 w = p - centre;
        const float along = glm::dot(w, axis);  // p - light = (dist + along) axis + across
        const Vec3 across = w - along * axis;
        const float across2 = glm::dot(across, across);
        // The rounding allowance grows with |w|, bounded by its 1-norm (no root).
        const float grownBy = std::abs(w.x) + std::abs(w.y) + std::abs(w.z) + radius + slack;
        const float r = radius + slack + kConeSlack * grownBy;
        if (r >= dist) return true;  // The light sits in (or touches) the sphere.
        const float fromLight = dist + along;
        if (fromLight <= 0.0f) return false;  // Behind the light.
        // Closer to the light than the region: |p - light|^2 < (dist - r)^2, written as a
        // product so that no two squares of dist are subtracted.
        if ((along + r) * (fromLight + dist - r) + across2 < 0.0f) return false;
        // Within the half-angle: across2 / |p - light|^2 <= (r / dist)^2, that is
        // across2 (dist^2 - r^2) <= fromLight^2 r^2, here divided by dist^2.
        const float k = r * invDist, f = fromLight * invDist;
        return across2 * (1.0f - k * k) <= f * f * (r * r);
    }
};

inline ShadowCone makeCone(const CompiledLight& l, const Aabb& region) {
    ShadowCone c;
    c.centre = region.center();
    const Vec3 toCenter = c.centre - l.position;
    c.dist = glm::length(toCenter);
    c.axis = c.dist > 0.0f ? toCenter / c.dist : Vec3(0, 0, 1);
    c.invDist = c.dist > 0.0f ? 1.0f / c.dist : 0.0f;
    c.radius = 0.5f * glm::length(region.extent()) + l.radius;
    return c;
}

}  // namespace rs
