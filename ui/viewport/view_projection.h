// The viewport's one mapping: widget points to frame pixels and view rays and back, for a frame
// traced at the viewport's own size (times the preview scale) with the output frame fitted in.
#pragma once

#include <QPoint>
#include <QPointF>
#include <QRect>
#include <QRectF>
#include <QSize>
#include <optional>

#include "scene/document.h"
#include "snapshot/camera_model.h"

namespace rs::ui {

/// Preview scales the viewport offers (Blender's "pixel size"): 1, 1/2 or 1/4 of a device pixel.
bool validPreviewDivider(int divider);
/// The frame the viewport traces for a widget of `devicePixels` at a preview scale of
/// 1 / `divider`: each side divided, rounded up, at least one pixel.
QSize tracedFrameSize(const QSize& devicePixels, int divider);
/// `view` with its field of view widened where needed so that the output frame (the aspect of
/// `outputSize`, spanning `view`'s own field) fits centred inside a frame of `frameSize`.
Camera fitOutputFrame(const Camera& view, const QSize& frameSize, const QSize& outputSize);

/// The view camera as the viewport shows it: a frame of `frameSize` pixels, traced through
/// fitOutputFrame(view, frameSize, outputSize) and drawn at fitRect(widget, frameSize).
class ViewProjection {
public:
    ViewProjection(const Camera& view, const QSize& outputSize, const QSize& frameSize,
                   const QSize& widget);

    /// The view ray through a widget point (continuous, not snapped to a pixel).
    Ray rayThrough(const QPointF& widgetPoint) const;
    /// The ray through the centre of frame pixel (x, y), as the session traced it.
    Ray pixelRay(int x, int y) const;
    /// Frame pixel under widget point `p`, or nullopt outside the drawn image.
    std::optional<QPoint> pixelAt(const QPoint& p) const;
    /// Widget point at the centre of frame pixel (x, y).
    QPoint widgetPointOf(int x, int y) const;
    /// The widget point where world point `p` appears; nullopt behind the camera.
    std::optional<QPointF> project(const Vec3& p) const;
    /// Widget pixels a length of `worldLength` spans at `p`, across the view (0 behind it).
    float projectedLength(const Vec3& p, float worldLength) const;
    /// Where the frame is drawn in the widget.
    QRect imageRect() const { return rect_; }
    /// Where the document's output frame lies in the widget (inside imageRect()).
    QRectF outputRect() const;
    const CameraModel& camera() const { return camera_; }
    bool valid() const { return !rect_.isEmpty(); }

private:
    CameraModel camera_;
    QRect rect_;
    QSize frame_;
    double outputAspect_ = 1.0;
};

}  // namespace rs::ui
