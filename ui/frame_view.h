// The one interface behind which the viewport draws frames: OpenGL where a context can be
// made, QPainter otherwise (e.g. the offscreen platform).
#pragma once

#include "display_frame.h"

#include <QImage>
#include <QRect>

#include <memory>

class QWidget;

namespace rs::ui {

/// Draws the session's frame, letterboxed to the widget, with the selection outline.
class FrameView {
public:
    virtual ~FrameView() = default;
    /// The widget that draws (owned by its Qt parent).
    virtual QWidget* widget() = 0;
    /// Shows `frame` in `mode` with `selected` outlined; repaints soon.
    virtual void showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                           ObjectId selected) = 0;
    /// What is on screen now, at widget resolution.
    virtual QImage grabImage() = 0;
    /// True for the OpenGL implementation.
    virtual bool usesOpenGL() const = 0;
};

/// Where a frame of `frame` pixels is drawn inside a widget of `area` (aspect kept, centred).
QRect fitRect(const QSize& area, const QSize& frame);

/// True when OpenGL views can work on this platform (not offscreen, and a context can be made).
bool openGLAvailable();

/// Makes the OpenGL view when available, else the raster view, as a child of `parent`.
FrameView* createFrameView(QWidget* parent);

}  // namespace rs::ui
