// RasterFrameView and the choice between the OpenGL and raster views.
#include "raster_frame_view.h"

#include "gl_frame_view.h"
#include "image/tonemap.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QPainter>

namespace rs::ui {

QRect fitRect(const QSize& area, const QSize& frame) {
    if (frame.isEmpty() || area.isEmpty()) return {};
    const QSize s = frame.scaled(area, Qt::KeepAspectRatio);
    // A frame traced at the area's own size (rounded up per preview pixel) fills it: a bar
    // narrower than one frame pixel is rounding, not a different aspect.
    const int slackX = (area.width() + frame.width() - 1) / frame.width();
    const int slackY = (area.height() + frame.height() - 1) / frame.height();
    if (area.width() - s.width() < slackX && area.height() - s.height() < slackY)
        return QRect(QPoint(0, 0), area);
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

bool RasterFrameView::canShadeRects(const DisplayFrame& f, ViewMode mode, const std::vector<ObjectId>& selected,
                                    std::vector<QRect>& rects) const {
    // Debug views normalise over the whole frame; everything else changes only where pixels did.
    return mode == ViewMode::Color && shadedFrame_ == &f && shadedMode_ == mode &&
           shadedSelected_ == selected && shadedTonemap_ == f.tonemap &&
           shadedExposure_ == f.exposure && image_.size() == QSize(f.width, f.height) &&
           f.changedSince(shadedSerial_, rects);
}

void RasterFrameView::shadeRect(const DisplayFrame& f, const std::vector<ObjectId>& selected, const QRect& rect) {
    // The outline of a pixel depends on its neighbours' ids: one pixel of margin.
    const QRect r = rect.adjusted(-1, -1, 1, 1) & QRect(0, 0, f.width, f.height);
    for (int y = r.top(); y <= r.bottom(); ++y) {
        uchar* line = image_.scanLine(y);
        for (int x = r.left(); x <= r.right(); ++x) {
            uchar* p = line + 3 * x;
            if (onOutline(f, x, y, selected))
                std::copy(kOutlineRgb, kOutlineRgb + 3, p);
            else
                toDisplay8(f.color[std::size_t(y) * f.width + x], f.tonemap, f.exposure, p);
        }
    }
}

void RasterFrameView::showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                                const std::vector<ObjectId>& selected) {
    QElapsedTimer timer;
    timer.start();
    if (!frame || frame->empty()) {
        image_ = QImage();
        shadedFrame_ = nullptr;
    } else {
        const DisplayFrame& f = *frame;
        std::vector<QRect> rects;
        if (canShadeRects(f, mode, selected, rects)) {
            for (const QRect& r : rects) shadeRect(f, selected, r);
        } else if (shadedFrame_ != &f || shadedSerial_ != f.serial || shadedMode_ != mode ||
                   shadedSelected_ != selected || shadedTonemap_ != f.tonemap ||
                   shadedExposure_ != f.exposure) {
            image_ = viewportImage(f, mode, selected);
        }
        shadedFrame_ = &f;
        shadedSerial_ = f.serial;
        shadedMode_ = mode;
        shadedSelected_ = selected;
        shadedTonemap_ = f.tonemap;
        shadedExposure_ = f.exposure;
    }
    shown_ = frame ? PresentedFrame{frame->serial, frame->generation, 0.0, 0.0} : PresentedFrame{};
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
