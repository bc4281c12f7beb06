// Tiles arrive already tone-mapped (background_jobs.cpp), so painting is a blit and a scale.
#include "jobs/render_window.h"

#include <QFileInfo>
#include <QPainter>
#include <QScreen>
#include <algorithm>

namespace rs::ui {

RenderWindow::RenderWindow(QWidget* parent) : QWidget(parent, Qt::Window) {
    setObjectName(QStringLiteral("renderWindow"));
    setWindowTitle(tr("Render"));
    setAttribute(Qt::WA_OpaquePaintEvent);
    // A queued render that starts must not take the keyboard from a field being edited.
    setAttribute(Qt::WA_ShowWithoutActivating);
}

void RenderWindow::begin(const QString& path, int width, int height) {
    path_ = path;
    image_ = QImage(width, height, QImage::Format_RGB888);
    image_.fill(Qt::black);
    setWindowTitle(tr("Render - %1 (rendering)").arg(QFileInfo(path).fileName()));
    update();
}

void RenderWindow::putTile(const QImage& tile, const QRect& where) {
    if (!image_.rect().contains(where)) return;  // A tile of an image this window no longer shows.
    QPainter p(&image_);
    p.drawImage(where.topLeft(), tile);
    p.end();
    // Only the tile's part of the window: a 4K render sends thousands of tiles.
    const QRect target = imageRect();
    const double sx = double(target.width()) / image_.width();
    const double sy = double(target.height()) / image_.height();
    update(QRectF(target.x() + where.x() * sx, target.y() + where.y() * sy, where.width() * sx,
                  where.height() * sy)
               .toAlignedRect()
               .adjusted(-1, -1, 1, 1));
}

void RenderWindow::end(const QString& outcome) {
    setWindowTitle(tr("Render - %1 (%2)").arg(QFileInfo(path_).fileName(), outcome));
}

void RenderWindow::showOver(QWidget* owner) {
    QScreen* screen = owner->screen();
    const QRect area = screen ? screen->availableGeometry() : QRect(0, 0, 1280, 800);
    resize(sizeHint().boundedTo(area.size() * 0.8));
    // The title bar and borders the window manager adds (known once shown; a guess before).
    const QMargins frame = isVisible() ? QMargins(frameGeometry().left() - geometry().left(),
                                                  frameGeometry().top() - geometry().top(),
                                                  frameGeometry().right() - geometry().right(),
                                                  frameGeometry().bottom() - geometry().bottom())
                                       : QMargins(4, 30, 4, 4);
    QRect outer = QRect(QPoint(0, 0), size()).marginsAdded(frame);
    outer.moveCenter(owner->frameGeometry().center());
    outer.moveLeft(std::clamp(outer.left(), area.left(),
                              std::max(area.left(), area.right() - outer.width() + 1)));
    outer.moveTop(std::clamp(outer.top(), area.top(),
                             std::max(area.top(), area.bottom() - outer.height() + 1)));
    move(outer.topLeft());  // A top-level widget's position is its frame's corner.
    show();
    raise();
}

QSize RenderWindow::sizeHint() const {
    if (image_.isNull()) return {640, 360};
    return image_.size().scaled(QSize(960, 600), Qt::KeepAspectRatio);
}

QRect RenderWindow::imageRect() const {
    if (image_.isNull()) return {};
    QRect r({}, image_.size().scaled(size(), Qt::KeepAspectRatio));
    r.moveCenter(rect().center());
    return r;
}

void RenderWindow::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().window());
    if (image_.isNull()) return;
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.drawImage(imageRect(), image_);
}

}  // namespace rs::ui
