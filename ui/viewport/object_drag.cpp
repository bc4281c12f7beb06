// ObjectDrag: the drag plane or locked axis, and the document each step shows.
#include "viewport/object_drag.h"

#include <cmath>

#include "document/scene_edits.h"

namespace rs::ui {

namespace {
/// The point of line (a + s * axis) closest to the ray (o + t * d).
Vec3 closestOnAxis(const Vec3& a, const Vec3& axis, const Vec3& o, const Vec3& d) {
    const Vec3 w = a - o;
    const float b = glm::dot(axis, d), dd = glm::dot(d, d), aa = glm::dot(axis, axis);
    const float denom = aa * dd - b * b;
    if (std::abs(denom) < 1e-8f) return a;
    const float s = (b * glm::dot(d, w) - dd * glm::dot(axis, w)) / denom;
    return a + axis * s;
}
}  // namespace

ObjectDrag::ObjectDrag(ObjectId pressed, std::vector<ObjectId> ids, SceneDocument start,
                       const Vec3& anchor, const ViewProjection& view, const QPoint& press)
    : pressed_(pressed), ids_(std::move(ids)), start_(std::move(start)), anchor_(anchor) {
    grabOffset_ = grabbedAt(view, press) - anchor_;
}

Vec3 ObjectDrag::grabbedAt(const ViewProjection& view, const QPoint& pos) const {
    const Ray ray = view.rayThrough(QPointF(pos));
    if (axisLock_ >= 0) {
        Vec3 axis(0.0f);
        axis[axisLock_] = 1.0f;
        return closestOnAxis(anchor_, axis, ray.origin, ray.dir) + grabOffset_;
    }
    // Plane parallel to the image through the anchor.
    const Vec3 n = view.camera().forward();
    const float denom = glm::dot(ray.dir, n);
    if (std::abs(denom) < 1e-6f) return anchor_ + grabOffset_;
    const float t = glm::dot(anchor_ + grabOffset_ - ray.origin, n) / denom;
    return ray.at(t);
}

SceneDocument ObjectDrag::moved(SceneDocument current, const ViewProjection& view,
                                const QPoint& pos) const {
    Vec3 delta = grabbedAt(view, pos) - grabOffset_ - anchor_;
    if (axisLock_ >= 0) {
        const float d = delta[axisLock_];
        delta = Vec3(0.0f);
        delta[axisLock_] = d;
    }
    for (ObjectId id : ids_) {
        restoreEntity(current, start_, id);
        moveBy(current, id, delta);
    }
    return current;
}

SceneDocument ObjectDrag::restored(SceneDocument current) const {
    for (ObjectId id : ids_) restoreEntity(current, start_, id);
    return current;
}

}  // namespace rs::ui
