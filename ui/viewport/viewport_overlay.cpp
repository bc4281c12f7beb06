// ViewportOverlay: a see-through widget that only paints, and only where it must.
#include "viewport/viewport_overlay.h"

#include <QPainter>

namespace rs::ui {

ViewportOverlay::ViewportOverlay(std::function<void(QPainter&)> painter,
                                 std::function<QRegion()> region, QWidget* parent)
    : QWidget(parent), painter_(std::move(painter)), region_(std::move(region)) {
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
}

void ViewportOverlay::repaintChanged(const QRectF& output) {
    const QRegion now = region_();
    if (output != outputShown_)
        update();
    else
        update(now | shown_);
    shown_ = now;
    outputShown_ = output;
}

void ViewportOverlay::paintEvent(QPaintEvent*) {
    // Any paint, a tile's too, draws the overlay as it is at that moment.
    shown_ += region_();
    QPainter p(this);
    painter_(p);
}

}  // namespace rs::ui
