// A preview of an image file: read through the renderer's TextureStore check and makeThumbnail.
#include "panels/image_preview.h"

#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>
#include <map>
#include <tuple>

#include "core/input_file.h"
#include "texture/texture_store.h"
#include "texture/thumbnail.h"

namespace rs::ui {

namespace {

/// A preview made, or the reason there is none.
struct Preview {
    QImage image;
    QString error;
};

/// Previews by path, modification time and size read: panels are rebuilt on every selection
/// change, and a file is read once while it stays the same.
Preview previewOf(const std::string& path, const FileStamp& stamp, int readSide) {
    static std::map<std::tuple<std::string, bool, long long, std::uintmax_t, int>, Preview> cache;
    const std::tuple key{path, stamp.exists, stamp.modified, stamp.size, readSide};
    if (auto it = cache.find(key); it != cache.end()) return it->second;
    Preview p;
    std::string error;
    if (!TextureStore::shared().open(path, error)) {
        p.error = QString::fromStdString(error);
    } else {
        const Thumbnail t = makeThumbnail(path, readSide);
        if (!t.ok()) {
            p.error = QString::fromStdString(t.error.empty() ? "cannot read " + path : t.error);
        } else {
            p.image = QImage(t.width, t.height, QImage::Format_RGB888);
            for (int y = 0; y < t.height; ++y)
                std::copy_n(t.rgb.data() + std::size_t(y) * std::size_t(t.width) * 3,
                            std::size_t(t.width) * 3, p.image.scanLine(y));
        }
    }
    if (cache.size() > 64) cache.clear();  // A bound, not an LRU: previews are cheap to redo.
    cache.emplace(key, p);
    return p;
}

}  // namespace

ImagePreview::ImagePreview(QSize box, int readSide, Qt::Alignment alignment,
                           const QString& imageName, const QString& errorName, QWidget* parent)
    : QWidget(parent), box_(box), readSide_(readSide) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    image_ = new QLabel(this);
    image_->setObjectName(imageName);
    image_->setFixedHeight(box.height());
    image_->setAlignment(alignment);
    error_ = new QLabel(this);
    error_->setObjectName(errorName);
    error_->setWordWrap(true);
    error_->setStyleSheet(QStringLiteral("color: #d03030;"));
    error_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(image_);
    layout->addWidget(error_);
    image_->hide();
    error_->hide();
}

void ImagePreview::setImage(const std::string& path) {
    const FileStamp stamp = path.empty() ? FileStamp{} : fileStampOf(path);
    if (path == shown_ && stamp == shownStamp_) return;
    shown_ = path;
    shownStamp_ = stamp;
    Preview p;
    if (!path.empty()) p = previewOf(path, stamp, readSide_);
    QImage shown = p.image;
    if (!shown.isNull() && (shown.width() > box_.width() || shown.height() > box_.height()))
        shown = shown.scaled(box_, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    image_->setPixmap(shown.isNull() ? QPixmap() : QPixmap::fromImage(shown));
    image_->setVisible(!shown.isNull());
    error_->setText(p.error);
    error_->setVisible(!p.error.isEmpty());
}

QString ImagePreview::error() const {
    return error_->isHidden() ? QString() : error_->text();
}

bool ImagePreview::hasImage() const {
    return !image_->isHidden() && !image_->pixmap().isNull();
}

}  // namespace rs::ui
