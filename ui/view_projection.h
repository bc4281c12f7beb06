// Widget points to view rays and back, for a frame letterboxed into the viewport.
#pragma once

#include "scene/document.h"
#include "snapshot/camera_model.h"

#include <QPointF>
#include <QRect>

#include <optional>

namespace rs::ui {

/// The view camera as the viewport shows it: a frame of `frameSize` pixels drawn at `imageRect`.
class ViewProjection {
public:
    ViewProjection(const Camera& view, const QSize& frameSize, const QRect& imageRect);

    /// The view ray through a widget point (continuous, not snapped to a pixel).
    Ray rayThrough(const QPointF& widgetPoint) const;
    /// The widget point where world point `p` appears; nullopt behind the camera.
    std::optional<QPointF> project(const Vec3& p) const;
    /// Widget pixels a length of `worldLength` spans at `p`, across the view (0 behind it).
    float projectedLength(const Vec3& p, float worldLength) const;
    const CameraModel& camera() const { return camera_; }
    bool valid() const { return !rect_.isEmpty(); }

private:
    CameraModel camera_;
    QRect rect_;
    QSize frame_;
};

}  // namespace rs::ui
