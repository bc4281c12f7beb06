// The QPainter frame view: CPU tone mapping and outline, for platforms without OpenGL.
#pragma once

#include "frame_view.h"

#include <QWidget>

namespace rs::ui {

/// Paints the CPU-shaded frame image scaled into the widget.
class RasterFrameView : public QWidget, public FrameView {
    Q_OBJECT
public:
    explicit RasterFrameView(QWidget* parent = nullptr);
    QWidget* widget() override { return this; }
    void showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                   ObjectId selected) override;
    QImage grabImage() override;
    bool usesOpenGL() const override { return false; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QImage image_;
    PresentedFrame shown_;  ///< The frame image_ comes from.
};

}  // namespace rs::ui
