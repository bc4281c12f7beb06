// ViewportOverlay: a see-through widget that only paints.
#include "viewport/viewport_overlay.h"

#include <QPainter>

namespace rs::ui {

ViewportOverlay::ViewportOverlay(std::function<void(QPainter&)> painter, QWidget* parent)
    : QWidget(parent), painter_(std::move(painter)) {
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
}

void ViewportOverlay::paintEvent(QPaintEvent*) {
    QPainter p(this);
    painter_(p);
}

}  // namespace rs::ui
