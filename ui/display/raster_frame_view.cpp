// RasterFrameView, and fitRect, which both views use.
#include "display/raster_frame_view.h"

#include <QElapsedTimer>
#include <QPaintEvent>
#include <QPainter>
#include <QRegion>
#include <algorithm>
#include <cmath>

#include "image/tonemap.h"

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

RasterFrameView::RasterFrameView(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_OpaquePaintEvent);
}

bool RasterFrameView::canShadeRects(const DisplayFrame& f, ViewMode mode,
                                    const std::vector<ObjectId>& selected,
                                    std::vector<QRect>& rects) const {
    // Debug views normalise over the whole frame; everything else changes only where pixels did.
    return mode == ViewMode::Color && shadedFrame_ == &f && shadedMode_ == mode &&
           shadedSelected_ == selected && shadedTonemap_ == f.tonemap &&
           shadedExposure_ == f.exposure && image_.size() == QSize(f.width, f.height) &&
           f.changedSince(shadedSerial_, rects);
}

void RasterFrameView::shadeRect(const DisplayFrame& f, const std::vector<ObjectId>& selected,
                                const QRect& rect) {
    // The outline of a pixel depends on its neighbours' ids: one pixel of margin.
    const QRect r = rect.adjusted(-1, -1, 1, 1) & QRect(0, 0, f.width, f.height);
    // All rows before any outline: toneMapRect copies a row's bytes to the next.
    toneMapRect(f, r, image_);
    if (selected.empty()) return;
    for (int y = r.top(); y <= r.bottom(); ++y)
        drawOutlineRow(f, y, r.left(), r.right(), selected, image_.scanLine(y));
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
            // Only what changed is shaded, repainted and flushed to the window system.
            QRegion dirty;
            for (const QRect& r : rects) {
                shadeRect(f, selected, r);
                dirty += widgetRect(r.adjusted(-1, -1, 1, 1));
            }
            update(dirty);
            shown_.serial = f.serial;
            shown_.generation = f.generation;
            shown_.paintMs += timer.nsecsElapsed() / 1e6;  // The shading is this view's upload.
            shadedSerial_ = f.serial;
            return;
        } else if (mode == ViewMode::Color && shadedFrame_ == &f && shadedSerial_ == f.serial &&
                   shadedMode_ == mode && shadedTonemap_ == f.tonemap &&
                   shadedExposure_ == f.exposure && image_.size() == QSize(f.width, f.height) &&
                   shadedSelected_ != selected) {
            // A click that selects: the outline moves, the rest of the picture stays.
            update(widgetRect(reshadeOutline(f, selected)));
            shadedSelected_ = selected;
            shown_.paintMs += timer.nsecsElapsed() / 1e6;
            return;
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
    shown_.serial = frame ? frame->serial : 0;
    shown_.generation = frame ? frame->generation : 0;
    shown_.paintMs += timer.nsecsElapsed() / 1e6;
    update();
}

QRect RasterFrameView::reshadeOutline(const DisplayFrame& f,
                                      const std::vector<ObjectId>& selected) {
    // Only pixels of an object outlined before or now, or next to one, can change, and of
    // those only the ones at an id edge (the press that selects: this is on its clock).
    const QRect bounds = outlinedBounds(f, selected, shadedSelected_);
    if (bounds.isEmpty()) return {};
    const QRect r = bounds.adjusted(-1, -1, 1, 1) & QRect(0, 0, f.width, f.height);
    for (int y = r.top(); y <= r.bottom(); ++y) {
        uchar* line = image_.scanLine(y);
        for (int x = r.left(); x <= r.right(); ++x) {
            if (!atIdEdge(f, x, y)) continue;
            const bool now = onOutline(f, x, y, selected);
            if (now == onOutline(f, x, y, shadedSelected_)) continue;
            if (now)
                std::copy(kOutlineRgb, kOutlineRgb + 3, line + 3 * x);
            else
                toDisplay8(f.color[std::size_t(y) * f.width + x], f.tonemap, f.exposure,
                           line + 3 * x);
        }
    }
    return r;
}

QImage RasterFrameView::grabImage() {
    return grab().toImage();
}

QRect RasterFrameView::widgetRect(const QRect& r) const {
    const QRect fit = fitRect(size(), image_.size());
    if (fit.isEmpty()) return {};
    const double sx = double(fit.width()) / image_.width();
    const double sy = double(fit.height()) / image_.height();
    const int x0 = fit.x() + int(std::floor(r.left() * sx));
    const int y0 = fit.y() + int(std::floor(r.top() * sy));
    const int x1 = fit.x() + int(std::ceil((r.right() + 1) * sx));
    const int y1 = fit.y() + int(std::ceil((r.bottom() + 1) * sy));
    return QRect(QPoint(x0, y0), QPoint(x1 - 1, y1 - 1)) & rect();
}

void RasterFrameView::paintEvent(QPaintEvent* event) {
    QElapsedTimer timer;
    timer.start();
    QPainter p(this);
    const QRect fit = image_.isNull() ? QRect() : fitRect(size(), image_.size());
    // The letterbox bars only; the image covers the rest (clipped to what changed).
    for (const QRect& r : QRegion(event->rect()) - QRegion(fit)) p.fillRect(r, QColor(48, 48, 48));
    if (!image_.isNull()) p.drawImage(fit, image_);
    shown_.paintMs += timer.nsecsElapsed() / 1e6;
    paintEnd_.start();
    reportPresented();
}

void RasterFrameView::reportPresented() {
    if (presentQueued_) return;
    presentQueued_ = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            presentQueued_ = false;
            PresentedFrame f = shown_;
            f.composeMs = paintEnd_.nsecsElapsed() / 1e6;
            shown_.paintMs = 0.0;  // Later paints of the same frame report their own drawing.
            notifyPresented(f);
        },
        Qt::QueuedConnection);
}

}  // namespace rs::ui
