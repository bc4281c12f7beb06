// Texture coordinates of the shapes and their gradients, in each shape's own space.
#pragma once

#include <cmath>

#include "core/fast_angles.h"
#include "core/math.h"

namespace rs {

/// Texture coordinates at a surface point and their gradients in object space: for a small
/// step dp in the tangent plane, du = dot(dudp, dp) and dv = dot(dvdp, dp) (object units).
/// The gradients are those of the functions below extended off the surface, so only their
/// tangent components matter.
struct ShapeUV {
    float u = 0.0f, v = 0.0f;
    Vec3 dudp{0.0f}, dvdp{0.0f};
};

/// POV-Ray's spherical map (map_type 1) about `center`, with d = (p - c) / |p - c|:
///   u = phi / (2 pi), phi = acos(d.x / sqrt(d.x^2 + d.z^2)), phi = 2 pi - phi when d.z < 0,
///     so u runs from 0 at +X through 0.25 at +Z, 0.5 at -X and 0.75 at -Z back to 1 (the
///     seam is the half-plane z = 0, x > 0); u = 0 on the axis (d.x^2 + d.z^2 = 0);
///   v = 0.5 + asin(d.y) / pi: 0 at the south pole (-Y), 0.5 on the equator, 1 at the north.
/// Gradients: du/dp = (-dz, 0, dx) / (2 pi (dx^2 + dz^2)) with (dx, dy, dz) = p - c, which
/// grows without bound toward the poles (where u is singular; zero on the axis itself), and
/// dv/dp = (-dy dx / rho, rho, -dy dz / rho) / (pi |p - c|^2), rho = sqrt(dx^2 + dz^2) (zero
/// on the axis). `radius` is used only when p is the centre (u = 0, v = 0.5, zero gradients).
[[gnu::always_inline]] inline ShapeUV sphereUV(const Vec3& p, const Vec3& center, float radius) {
    (void)radius;
    ShapeUV uv;
    const Vec3 d = p - center;
    const float rhoSquared = d.x * d.x + d.z * d.z;
    const float lengthSquared = rhoSquared + d.y * d.y;
    if (!(lengthSquared > 0.0f)) {  // the centre itself: no direction
        uv.v = 0.5f;
        return uv;
    }
    const float rho = std::sqrt(rhoSquared);
    if (rhoSquared > 0.0f) {
        // acos(x / rho), mirrored for z < 0: atan2 gives the same angle without the acos's
        // loss of precision near +-X.
        float phi = atan2Polynomial(d.z, d.x);
        if (phi < 0.0f) phi += kTwoPi;
        float u = phi / kTwoPi;
        if (u >= 1.0f) u = 0.0f;  // -0 and rounding just below the seam
        uv.u = u;
        uv.dudp = Vec3(-d.z, 0.0f, d.x) / (kTwoPi * rhoSquared);
        uv.dvdp = Vec3(-d.y * d.x / rho, rho, -d.y * d.z / rho) / (kPi * lengthSquared);
    }
    // asin(dy / |d|) is atan2(dy, rho).
    uv.v = 0.5f + atan2Polynomial(d.y, rho) / kPi;
    return uv;
}

/// A plane's planar projection, unit cells in scene units. With n = normalize(`normal`):
///   T1 = normalize(X - n (n.X)), or normalize(Z - n (n.Z)) when |n.x| > 0.9;  T2 = n x T1;
///   u = (p - point) . T1,  v = (p - point) . T2;  dudp = T1, dvdp = T2.
/// For the floor n = +Y: T1 = +X, T2 = -Z, so u = x - point.x and v = point.z - z.
ShapeUV planeUV(const Vec3& p, const Vec3& point, const Vec3& normal);

/// planeUV's axes T1, T2 for a plane's normal, computed once per plane.
struct PlaneAxes {
    Vec3 t1{0.0f}, t2{0.0f};
};
PlaneAxes planeAxes(const Vec3& normal);
/// planeUV with its axes at hand: the same values.
inline ShapeUV planeUV(const Vec3& p, const Vec3& point, const PlaneAxes& axes) {
    const Vec3 d = p - point;
    return {glm::dot(d, axes.t1), glm::dot(d, axes.t2), axes.t1, axes.t2};
}

/// The rectangle c + a u + b v, a, b in [-1, 1] (u, v its half-extent edges, not necessarily
/// orthogonal): texture u = (a + 1) / 2, v = (b + 1) / 2, so [0, 1]^2 spans it from corner
/// c - u - v. (a, b) come from the in-plane dual basis of (u, v), as RectangleShape's test
/// does, so sheared rectangles map exactly; dudp = uDual / 2, dvdp = vDual / 2.
ShapeUV rectangleUV(const Vec3& p, const Vec3& center, const Vec3& u, const Vec3& v);

/// [0, 1]^2 on each face of the axis-aligned box [min, max], the face chosen by the dominant
/// axis of the outward object-space normal `n` (ties go to X, then Y). Every face is upright
/// as seen from outside: u grows to the viewer's right and v upward, where "up" is +Y on the
/// four side faces, -Z on the top face (seen from above) and +Z on the bottom face (seen from
/// below). With ext = max - min:
///   +X face: u = (max.z - z) / ext.z,  v = (y - min.y) / ext.y
///   -X face: u = (z - min.z) / ext.z,  v = (y - min.y) / ext.y
///   +Y face: u = (x - min.x) / ext.x,  v = (max.z - z) / ext.z
///   -Y face: u = (x - min.x) / ext.x,  v = (z - min.z) / ext.z
///   +Z face: u = (x - min.x) / ext.x,  v = (y - min.y) / ext.y
///   -Z face: u = (max.x - x) / ext.x,  v = (y - min.y) / ext.y
/// The gradients are the constant coefficients of x, y, z above. A zero extent on an axis
/// gives 0 for that coordinate and its gradient.
ShapeUV boxUV(const Vec3& p, const Vec3& n, const Vec3& min, const Vec3& max);

/// A mesh triangle (p0, p1, p2) with vertex texture coordinates (t0, t1, t2), at barycentrics
/// (b1, b2) (weights 1 - b1 - b2, b1, b2 of the three vertices):
///   (u, v) = (1 - b1 - b2) t0 + b1 t1 + b2 t2.
/// The gradients are the in-plane vectors g with g . (p1 - p0) = du1 and g . (p2 - p0) = du2
/// (du_k the change of u, resp. v, from vertex 0 to vertex k), so the footprint maps into
/// texture space through the triangle's own linear map; a degenerate triangle or UV-less
/// data gives zero gradients.
ShapeUV triangleUV(const Vec3& p0, const Vec3& p1, const Vec3& p2, const glm::vec2& t0,
                   const glm::vec2& t1, const glm::vec2& t2, float b1, float b2);

}  // namespace rs
