// Texture coordinates of planes, rectangles, boxes and mesh triangles, with their gradients
// (spheres': in the header, inlined where image lookups take them per point).
#include "texture/shape_uv.h"

#include <cmath>

namespace rs {

PlaneAxes planeAxes(const Vec3& normal) {
    const Vec3 n = glm::normalize(normal);
    const Vec3 axis = std::abs(n.x) > 0.9f ? Vec3(0.0f, 0.0f, 1.0f) : Vec3(1.0f, 0.0f, 0.0f);
    const Vec3 t1 = glm::normalize(axis - n * glm::dot(n, axis));
    return {t1, glm::cross(n, t1)};
}

ShapeUV planeUV(const Vec3& p, const Vec3& point, const Vec3& normal) {
    return planeUV(p, point, planeAxes(normal));
}

ShapeUV rectangleUV(const Vec3& p, const Vec3& center, const Vec3& u, const Vec3& v) {
    // The dual basis inside the plane, as RectangleShape::make builds it.
    const Vec3 normal = glm::normalize(glm::cross(u, v));
    const Vec3 vPerp = glm::cross(v, normal);
    const Vec3 uPerp = glm::cross(normal, u);
    const Vec3 uDual = vPerp / glm::dot(u, vPerp);
    const Vec3 vDual = uPerp / glm::dot(v, uPerp);
    const Vec3 d = p - center;
    ShapeUV uv;
    uv.u = 0.5f * (glm::dot(d, uDual) + 1.0f);
    uv.v = 0.5f * (glm::dot(d, vDual) + 1.0f);
    uv.dudp = 0.5f * uDual;
    uv.dvdp = 0.5f * vDual;
    return uv;
}

namespace {

/// One box-face coordinate: (p[axis] - min[axis]) / ext when `rising`, else
/// (max[axis] - p[axis]) / ext; its gradient lies along that axis.
void faceCoordinate(const Vec3& p, const Vec3& min, const Vec3& max, int axis, bool rising,
                    float& value, Vec3& gradient) {
    const float ext = max[axis] - min[axis];
    gradient = Vec3(0.0f);
    if (!(ext > 0.0f)) {
        value = 0.0f;
        return;
    }
    const float inv = 1.0f / ext;
    value = rising ? (p[axis] - min[axis]) * inv : (max[axis] - p[axis]) * inv;
    gradient[axis] = rising ? inv : -inv;
}

}  // namespace

ShapeUV boxUV(const Vec3& p, const Vec3& n, const Vec3& min, const Vec3& max) {
    const Vec3 a = glm::abs(n);
    const int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
    const bool positive = n[axis] >= 0.0f;
    // (axis of u, u rising?, axis of v, v rising?) per face, as the header lists them.
    int uAxis = 0, vAxis = 1;
    bool uRising = true, vRising = true;
    switch (axis) {
        case 0:  // +X: u = (max.z - z); -X: u = (z - min.z); v = (y - min.y)
            uAxis = 2;
            uRising = !positive;
            break;
        case 1:  // u = (x - min.x); +Y: v = (max.z - z); -Y: v = (z - min.z)
            vAxis = 2;
            vRising = !positive;
            break;
        default:  // +Z: u = (x - min.x); -Z: u = (max.x - x); v = (y - min.y)
            uRising = positive;
            break;
    }
    ShapeUV uv;
    faceCoordinate(p, min, max, uAxis, uRising, uv.u, uv.dudp);
    faceCoordinate(p, min, max, vAxis, vRising, uv.v, uv.dvdp);
    return uv;
}

ShapeUV triangleUV(const Vec3& p0, const Vec3& p1, const Vec3& p2, const glm::vec2& t0,
                   const glm::vec2& t1, const glm::vec2& t2, float b1, float b2) {
    ShapeUV uv;
    const glm::vec2 t = (1.0f - b1 - b2) * t0 + b1 * t1 + b2 * t2;
    uv.u = t.x;
    uv.v = t.y;
    // g = a e1 + b e2 with the Gram system [e1.e1 e1.e2; e1.e2 e2.e2] (a, b) = (d1, d2).
    const Vec3 e1 = p1 - p0, e2 = p2 - p0;
    const float g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const float det = g11 * g22 - g12 * g12;
    if (!(det > 0.0f) || !std::isfinite(det)) return uv;
    const glm::vec2 d1 = t1 - t0, d2 = t2 - t0;
    auto gradient = [&](float c1, float c2) {
        const float a = (g22 * c1 - g12 * c2) / det;
        const float b = (g11 * c2 - g12 * c1) / det;
        return a * e1 + b * e2;
    };
    uv.dudp = gradient(d1.x, d2.x);
    uv.dvdp = gradient(d1.y, d2.y);
    return uv;
}

}  // namespace rs
