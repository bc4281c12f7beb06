// Passepartout: four dimmed bands around the output frame and a thin line along its edge.
#include "viewport/passepartout.h"

#include <QPainter>

namespace rs::ui {

void paintPassepartout(QPainter& p, const QRect& area, const QRectF& f) {
    if (f.isEmpty()) return;
    const QRectF a(area);
    const QColor dim(0, 0, 0, int(255 * (1.0 - kPassepartoutKeep)));
    // fillRect leaves the painter's pen and brush alone (the OpenGL paint device's painter
    // is shared with the light glyphs); bands without area are skipped.
    const QRectF bands[] = {QRectF(a.left(), a.top(), a.width(), f.top() - a.top()),
                            QRectF(a.left(), f.bottom(), a.width(), a.bottom() - f.bottom()),
                            QRectF(a.left(), f.top(), f.left() - a.left(), f.height()),
                            QRectF(f.right(), f.top(), a.right() - f.right(), f.height())};
    bool any = false;
    for (const QRectF& band : bands)
        if (band.width() >= 0.5 && band.height() >= 0.5) {
            p.fillRect(band, dim);
            any = true;
        }
    // The frame's edge where it meets a band.
    if (any) {
        const QPen old = p.pen();
        p.setPen(QPen(QColor(0, 0, 0, 200), 1.0));
        p.drawLine(f.topLeft(), f.topRight());
        p.drawLine(f.bottomLeft(), f.bottomRight());
        p.drawLine(f.topLeft(), f.bottomLeft());
        p.drawLine(f.topRight(), f.bottomRight());
        p.setPen(old);
    }
}

}  // namespace rs::ui
