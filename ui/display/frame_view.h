// The one interface behind which the viewport draws frames: OpenGL where a context can be
// made, QPainter otherwise (e.g. the offscreen platform).
#pragma once

#include <QImage>
#include <QRect>
#include <cstdint>
#include <functional>
#include <memory>

#include "display/display_frame.h"

class QWidget;

class QPainter;

namespace rs::ui {

/// A frame that has just been put on screen.
struct PresentedFrame {
    uint64_t serial = 0;      ///< DisplayFrame::serial of what was drawn.
    uint64_t generation = 0;  ///< DisplayFrame::generation of what was drawn.
    double paintMs = 0.0;     ///< Time spent drawing it (uploads included).
    double composeMs = 0.0;   ///< From the end of drawing to the swap (window composition).
};

/// Draws the session's frame at fitRect() in the widget, with the selection outline.
class FrameView {
public:
    using PresentedHandler = std::function<void(const PresentedFrame&)>;

    virtual ~FrameView() = default;
    /// The widget that draws (owned by its Qt parent).
    virtual QWidget* widget() = 0;
    /// Shows `frame` in `mode` with the `selected` objects outlined; repaints soon.
    virtual void showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                           const std::vector<ObjectId>& selected) = 0;
    /// What is on screen now, at widget resolution.
    virtual QImage grabImage() = 0;
    /// True for the OpenGL implementation.
    virtual bool usesOpenGL() const = 0;
    /// What to paint over the frame with QPainter, in widget coordinates (light glyphs, the
    /// transform gizmo, the selection box).
    /// A view whose window is native paints it itself: widgets cannot draw over it.
    virtual void setOverlayPainter(std::function<void(QPainter&)> painter) { (void)painter; }
    /// Paints again (the overlay changed).
    virtual void repaintOverlay() {}
    /// Called after each frame reaches the screen (the designer measures latency with it).
    void setPresentedHandler(PresentedHandler handler) { presented_ = std::move(handler); }

protected:
    void notifyPresented(const PresentedFrame& frame) {
        if (presented_) presented_(frame);
    }

private:
    PresentedHandler presented_;
};

/// Where a frame of `frame` pixels is drawn inside a widget of `area`: all of it when the frame
/// has the area's aspect to within a frame pixel (the viewport's own traced size), else
/// letterboxed (aspect kept, centred; e.g. the old frame while a resize is pending).
QRect fitRect(const QSize& area, const QSize& frame);

}  // namespace rs::ui
