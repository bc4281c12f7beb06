// The QPainter frame view: CPU tone mapping and outline, for platforms without OpenGL. The
// shaded image is kept and only the rectangles the frame reports as changed are shaded again.
#pragma once

#include <QElapsedTimer>
#include <QWidget>

#include "display/frame_view.h"

namespace rs::ui {

/// Paints the CPU-shaded frame image scaled into the widget.
class RasterFrameView : public QWidget, public FrameView {
    Q_OBJECT
public:
    explicit RasterFrameView(QWidget* parent = nullptr);
    QWidget* widget() override { return this; }
    void showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                   const std::vector<ObjectId>& selected) override;
    QImage grabImage() override;
    bool usesOpenGL() const override { return false; }
    /// The overlay is a widget of its own over this one; this paints the whole frame again.
    void repaintOverlay() override { update(); }
    /// The shaded frame at frame resolution (what is drawn, before scaling).
    QImage frameImage() const { return image_; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    /// True when image_ can be brought up to date by re-shading `rects` alone.
    bool canShadeRects(const DisplayFrame& frame, ViewMode mode,
                       const std::vector<ObjectId>& selected, std::vector<QRect>& rects) const;
    void shadeRect(const DisplayFrame& frame, const std::vector<ObjectId>& selected,
                   const QRect& rect);
    /// Brings image_ from shadedSelected_ to `selected` where only the outline can differ:
    /// near the objects either selection outlines. Returns the frame rectangle it touched.
    QRect reshadeOutline(const DisplayFrame& frame, const std::vector<ObjectId>& selected);
    /// Widget pixels that show frame pixels `rect`.
    QRect widgetRect(const QRect& rect) const;

    /// Reported once the paint has reached the window system (the backing store flushes
    /// after the paint events): queued, so a paint that covers several widgets reports once.
    void reportPresented();
    bool presentQueued_ = false;
    QElapsedTimer paintEnd_;

    QImage image_;
    PresentedFrame shown_;  ///< The frame image_ comes from.
    /// What image_ was shaded from.
    const DisplayFrame* shadedFrame_ = nullptr;
    uint64_t shadedSerial_ = 0;
    ViewMode shadedMode_ = ViewMode::Color;
    std::vector<ObjectId> shadedSelected_;
    ToneMap shadedTonemap_ = ToneMap::Clamp;
    float shadedExposure_ = 0.0f;
};

}  // namespace rs::ui
