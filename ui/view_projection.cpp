// ViewProjection: the mapping the viewport's picking, gestures and light glyphs share.
#include "view_projection.h"

#include <algorithm>
#include <cmath>

namespace rs::ui {

ViewProjection::ViewProjection(const Camera& view, const QSize& frameSize, const QRect& imageRect)
    : camera_(view, std::max(1, frameSize.width()), std::max(1, frameSize.height())),
      rect_(imageRect),
      frame_(frameSize.expandedTo(QSize(1, 1))) {}

Ray ViewProjection::rayThrough(const QPointF& w) const {
    const float px = float(w.x() - rect_.x()) * frame_.width() / std::max(1, rect_.width());
    const float py = float(w.y() - rect_.y()) * frame_.height() / std::max(1, rect_.height());
    return camera_.generateRay(px, py);
}

std::optional<QPointF> ViewProjection::project(const Vec3& p) const {
    float px = 0.0f, py = 0.0f;
    if (!camera_.project(p, px, py)) return std::nullopt;
    return QPointF(rect_.x() + double(px) * rect_.width() / frame_.width(),
                   rect_.y() + double(py) * rect_.height() / frame_.height());
}

float ViewProjection::projectedLength(const Vec3& p, float worldLength) const {
    const auto a = project(p);
    const auto b = project(p + camera_.up() * worldLength);
    if (!a || !b) return 0.0f;
    return float(std::hypot(b->x() - a->x(), b->y() - a->y()));
}

}  // namespace rs::ui
