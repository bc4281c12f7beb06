// What a drag must do, worked out from its pixels and the view alone: the closed forms the GUI
// tests hold moves, gestures and orbits to (never the gizmo's or the viewport's own code).
#pragma once

#include <QPointF>
#include <cmath>

#include "scene/document.h"
#include "viewport/view_projection.h"

namespace rs::ui::test {

inline double length(const QPointF& p) {
    return std::hypot(p.x(), p.y());
}

/// The unit widget direction in which `axis` leaves `pivot` on screen.
inline QPointF screenDirection(const ViewProjection& view, const Vec3& pivot, const Vec3& axis) {
    const QPointF d = *view.project(pivot + axis) - *view.project(pivot);
    return d / length(d);
}

/// How far along unit `axis` a drag from widget point `from` to `to`, both on the line the axis
/// through `pivot` makes on screen, carries the point it grabbed. Seen in perspective, the
/// point pivot + s * axis lies at t(s) = a s / (1 + b s) along that line from the pivot's
/// image (a projective map of the line); where s = 1 and s = 2 appear give a and b, and
/// s(t) = t / (a - b t) inverts it. Only the view's projection is used, not the gizmo's code.
inline double alongAxis(const ViewProjection& view, const Vec3& pivot, const Vec3& axis,
                        const QPointF& from, const QPointF& to) {
    const QPointF p0 = *view.project(pivot);
    const QPointF e = screenDirection(view, pivot, axis);
    const auto t = [&](const QPointF& p) { return QPointF::dotProduct(p - p0, e); };
    const double t1 = t(*view.project(pivot + axis)), t2 = t(*view.project(pivot + 2.0f * axis));
    const double b = (2.0 * t1 - t2) / (2.0 * (t2 - t1)), a = t1 * (1.0 + b);
    const auto s = [&](const QPointF& p) { return t(p) / (a - b * t(p)); };
    return s(to) - s(from);
}

/// Where the view ray through widget point `p` meets the horizontal plane at height `y`.
inline Vec3 onHorizontalPlane(const ViewProjection& view, const QPointF& p, float y) {
    const Ray r = view.rayThrough(p);
    return r.at((y - r.origin.y) / r.dir.y);
}

/// The move that carries a point at `at` across a perspective view `camera` by `pixels` (widget
/// x to the right, y down) in the plane through it parallel to the image, for an image that
/// fills a widget `widgetHeight` pixels high: by similar triangles, the pixels over the focal
/// length (half the height over tan(fovY / 2)) times the point's depth along the view.
inline Vec3 acrossView(const Camera& camera, int widgetHeight, const Vec3& at,
                       const QPointF& pixels) {
    const Vec3 forward = glm::normalize(camera.target - camera.position);
    const Vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const Vec3 up = glm::cross(right, forward);
    const double focal = 0.5 * widgetHeight / std::tan(glm::radians(double(camera.fovY)) * 0.5);
    const float perPixel = float(glm::dot(at - camera.position, forward) / focal);
    return perPixel * (float(pixels.x()) * right - float(pixels.y()) * up);
}

}  // namespace rs::ui::test
