// RasterFrameView and the choice between the OpenGL and raster views.
#include "raster_frame_view.h"

#include "gl_frame_view.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QPainter>

namespace rs::ui {

QRect fitRect(const QSize& area, const QSize& frame) {
    if (frame.isEmpty() || area.isEmpty()) return {};
    const QSize s = frame.scaled(area, Qt::KeepAspectRatio);
    return QRect((area.width() - s.width()) / 2, (area.height() - s.height()) / 2, s.width(),
                 s.height());
}

bool openGLAvailable() {
    if (QGuiApplication::platformName() == QLatin1String("offscreen") ||
        QGuiApplication::platformName() == QLatin1String("minimal"))
        return false;
    if (qEnvironmentVariableIsSet("RAYSTUDIO_NO_OPENGL")) return false;
    QOpenGLContext context;
    return context.create();
}

FrameView* createFrameView(QWidget* parent) {
    if (openGLAvailable()) return new GlFrameView(parent);
    return new RasterFrameView(parent);
}

RasterFrameView::RasterFrameView(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void RasterFrameView::showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                                ObjectId selected) {
    QElapsedTimer timer;
    timer.start();
    image_ = frame ? viewportImage(*frame, mode, selected) : QImage();
    shown_ = frame ? PresentedFrame{frame->serial, frame->generation, 0.0} : PresentedFrame{};
    shown_.paintMs = timer.nsecsElapsed() / 1e6;  // The CPU shading is this view's upload.
    update();
}

QImage RasterFrameView::grabImage() {
    return grab().toImage();
}

void RasterFrameView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(48, 48, 48));
    if (!image_.isNull()) p.drawImage(fitRect(size(), image_.size()), image_);
    notifyPresented(shown_);
}

}  // namespace rs::ui
