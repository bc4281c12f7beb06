// The widget the raster frame view's overlay (light glyphs, gizmo, selection box) is drawn on,
// and where it has been drawn.
#pragma once

#include <QRectF>
#include <QRegion>
#include <QWidget>
#include <functional>

class QPainter;

namespace rs::ui {

/// Transparent widget over the frame view that paints with a given function; mouse events
/// pass through. (The OpenGL view, a native window that covers widgets, runs the same
/// function itself: FrameView::setOverlayPainter.) It repaints only where the overlay was or
/// is now drawn, so the frame under the rest stays on screen.
class ViewportOverlay : public QWidget {
    Q_OBJECT
public:
    /// `painter` draws the overlay; `region` says where it draws now (not the passepartout,
    /// which changes only with the output frame).
    ViewportOverlay(std::function<void(QPainter&)> painter, std::function<QRegion()> region,
                    QWidget* parent = nullptr);

    /// The overlay changed: repaints where it was and where it is now, or all of it when the
    /// passepartout's output frame is no longer `output`.
    void repaintChanged(const QRectF& output);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::function<void(QPainter&)> painter_;
    std::function<QRegion()> region_;
    /// Everywhere the overlay may be on screen: region_() at the last repaintChanged() and at
    /// every paint since (a repaint of frame tiles draws the overlay of that moment).
    QRegion shown_;
    QRectF outputShown_;  ///< The passepartout's output frame then.
};

}  // namespace rs::ui
