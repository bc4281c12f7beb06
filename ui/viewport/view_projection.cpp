// ViewProjection: the mapping the viewport's tracing, picking, gestures, light glyphs and
// passepartout share.
#include "viewport/view_projection.h"

#include <algorithm>
#include <cmath>

#include "display/frame_view.h"

namespace rs::ui {

bool validPreviewDivider(int divider) {
    return divider == 1 || divider == 2 || divider == 4;
}

QSize tracedFrameSize(const QSize& devicePixels, int divider) {
    const int d = validPreviewDivider(divider) ? divider : 1;
    return QSize(std::max(1, (devicePixels.width() + d - 1) / d),
                 std::max(1, (devicePixels.height() + d - 1) / d));
}

Camera fitOutputFrame(const Camera& view, const QSize& frameSize, const QSize& outputSize) {
    Camera c = view;
    if (frameSize.isEmpty() || outputSize.isEmpty()) return c;
    const double frameAspect = double(frameSize.width()) / frameSize.height();
    const double outputAspect = double(outputSize.width()) / outputSize.height();
    // The camera's field is the output frame's height. A frame wider than the output shows it
    // at full height; a narrower one at full width, so the traced height grows by this factor.
    const double grow = outputAspect / frameAspect;
    if (grow <= 1.0) return c;
    if (c.projection == Projection::Orthographic) {
        c.orthoHeight = float(c.orthoHeight * grow);
    } else {
        const double half = std::tan(glm::radians(double(c.fovY)) * 0.5) * grow;
        c.fovY = float(glm::degrees(2.0 * std::atan(half)));
    }
    return c;
}

ViewProjection::ViewProjection(const Camera& view, const QSize& outputSize, const QSize& frameSize,
                               const QSize& widget)
    : frame_(frameSize.expandedTo(QSize(1, 1))) {
    const QSize output = outputSize.expandedTo(QSize(1, 1));
    camera_ = CameraModel(fitOutputFrame(view, frame_, output), frame_.width(), frame_.height());
    rect_ = fitRect(widget, frame_);
    outputAspect_ = double(output.width()) / output.height();
}

Ray ViewProjection::rayThrough(const QPointF& w) const {
    const float px = float(w.x() - rect_.x()) * frame_.width() / std::max(1, rect_.width());
    const float py = float(w.y() - rect_.y()) * frame_.height() / std::max(1, rect_.height());
    return camera_.generateRay(px, py);
}

Ray ViewProjection::pixelRay(int x, int y) const {
    return camera_.generateRay(float(x) + 0.5f, float(y) + 0.5f);
}

std::optional<QPoint> ViewProjection::pixelAt(const QPoint& p) const {
    if (!rect_.contains(p)) return std::nullopt;
    const int x = int((p.x() - rect_.x() + 0.5) * frame_.width() / rect_.width());
    const int y = int((p.y() - rect_.y() + 0.5) * frame_.height() / rect_.height());
    return QPoint(std::clamp(x, 0, frame_.width() - 1), std::clamp(y, 0, frame_.height() - 1));
}

QPoint ViewProjection::widgetPointOf(int x, int y) const {
    return QPoint(rect_.x() + int((x + 0.5) * rect_.width() / frame_.width()),
                  rect_.y() + int((y + 0.5) * rect_.height() / frame_.height()));
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

QRectF ViewProjection::outputRect() const {
    // fitOutputFrame centred the output frame in the traced one, at full height or full width.
    const QRectF r(rect_);
    if (r.isEmpty()) return {};
    const double w = std::min(r.width(), r.height() * outputAspect_);
    const double h = std::min(r.height(), r.width() / outputAspect_);
    return QRectF(r.x() + 0.5 * (r.width() - w), r.y() + 0.5 * (r.height() - h), w, h);
}

}  // namespace rs::ui
