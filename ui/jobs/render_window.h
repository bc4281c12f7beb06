// The Render window: the image of the running (or last) Render Image as it fills in.
#pragma once

#include <QImage>
#include <QWidget>

namespace rs::ui {

/// A top-level window showing one render's image, scaled to fit; tiles not yet traced are black.
class RenderWindow : public QWidget {
    Q_OBJECT
public:
    explicit RenderWindow(QWidget* parent = nullptr);

    /// Starts showing a new render of width x height into `path` (all black).
    void begin(const QString& path, int width, int height);
    /// Draws a finished tile at `where` in the image.
    void putTile(const QImage& tile, const QRect& where);
    /// Notes in the title how the render ended; the image stays.
    void end(const QString& outcome);
    /// Shows the window at its size hint (at most 80 % of the screen), centred over `owner`
    /// and moved wholly onto `owner`'s screen; on top, without taking the focus.
    void showOver(QWidget* owner);
    /// What the window shows, at the render's size.
    const QImage& image() const { return image_; }

    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QRect imageRect() const;

    QImage image_;
    QString path_;
};

}  // namespace rs::ui
