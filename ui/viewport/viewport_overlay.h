// The widget the raster frame view's overlay (light glyphs, gizmo, selection box) is drawn on.
#pragma once

#include <QWidget>
#include <functional>

class QPainter;

namespace rs::ui {

/// Transparent widget over the frame view that paints with a given function; mouse events
/// pass through. (The OpenGL view, a native window that covers widgets, runs the same
/// function itself: FrameView::setOverlayPainter.)
class ViewportOverlay : public QWidget {
    Q_OBJECT
public:
    ViewportOverlay(std::function<void(QPainter&)> painter, QWidget* parent = nullptr);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::function<void(QPainter&)> painter_;
};

}  // namespace rs::ui
