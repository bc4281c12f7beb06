// The colour-form widgets: selector, texture dialog, and the thumbnail through makeThumbnail.
#include "color_pattern_editor.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>
#include <filesystem>
#include <map>

#include "dialog_folders.h"
#include "texture/texture_store.h"
#include "texture/thumbnail.h"

namespace rs::ui {

namespace {

/// A preview made, or the reason there is none.
struct Preview {
    QImage image;
    QString error;
};

/// Previews by path and modification time: the panel is rebuilt on every selection change.
Preview previewOf(const std::string& path) {
    static std::map<std::pair<std::string, long long>, Preview> cache;
    std::error_code ec;
    const auto modified = std::filesystem::last_write_time(path, ec);
    const std::pair key{path, ec ? -1LL : (long long)modified.time_since_epoch().count()};
    if (auto it = cache.find(key); it != cache.end()) return it->second;
    Preview p;
    // The renderer's own check first: its error is the one a render would report.
    std::string error;
    if (!TextureStore::shared().open(path, error)) {
        p.error = QString::fromStdString(error);
    } else {
        const Thumbnail t = makeThumbnail(path, TexturePreview::kThumbnailSide);
        if (!t.ok()) {
            p.error = QString::fromStdString(t.error);
        } else {
            p.image = QImage(t.width, t.height, QImage::Format_RGB888);
            for (int y = 0; y < t.height; ++y)
                std::copy_n(t.rgb.data() + std::size_t(y) * t.width * 3, t.width * 3,
                            p.image.scanLine(y));
        }
    }
    if (cache.size() > 64) cache.clear();  // A bound, not an LRU: previews are cheap to redo.
    cache.emplace(key, p);
    return p;
}

}  // namespace

QComboBox* makeColorModeCombo(QWidget* parent) {
    auto* combo = new QComboBox(parent);
    combo->setObjectName(QStringLiteral("colorMode"));
    combo->addItems({QObject::tr("Colour"), QObject::tr("Checker"), QObject::tr("Image")});
    combo->setToolTip(
        QObject::tr("The surface's colour: one colour, a 3D checker of two, or "
                    "an image through the shape's texture coordinates"));
    return combo;
}

QString textureFileFilter() {
    return QObject::tr("Images (*.png *.jpg *.jpeg *.tif *.tiff *.exr *.hdr *.tga *.bmp)");
}

QString chooseTextureFile(QWidget* parent, const QString& documentPath) {
    QFileDialog dialog(parent, QObject::tr("Choose Texture Image"),
                       dialogFolder(FileKind::Image, documentPath), textureFileFilter());
    dialog.setObjectName(QStringLiteral("textureFileDialog"));
    dialog.setFileMode(QFileDialog::ExistingFile);
    dialog.setOption(QFileDialog::DontUseNativeDialog);  // The same dialog everywhere (tests).
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return {};
    const QString path = QFileInfo(dialog.selectedFiles().first()).absoluteFilePath();
    rememberDialogFolder(FileKind::Image, path);
    return path;
}

TexturePreview::TexturePreview(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    image_ = new QLabel(this);
    image_->setObjectName(QStringLiteral("textureThumbnail"));
    image_->setFixedHeight(kThumbnailSide);
    image_->setAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    error_ = new QLabel(this);
    error_->setObjectName(QStringLiteral("textureError"));
    error_->setWordWrap(true);
    error_->setStyleSheet(QStringLiteral("color: #d03030;"));
    error_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(image_);
    layout->addWidget(error_);
    error_->hide();
}

void TexturePreview::setImage(const std::string& path) {
    if (path == shown_) return;
    shown_ = path;
    const Preview p = previewOf(path);
    image_->setPixmap(p.image.isNull() ? QPixmap() : QPixmap::fromImage(p.image));
    image_->setVisible(!p.image.isNull());
    error_->setText(p.error);
    error_->setVisible(!p.error.isEmpty());
}

QString TexturePreview::error() const {
    return error_->text();
}

bool TexturePreview::hasThumbnail() const {
    return image_->pixmap().isNull() == false;
}

}  // namespace rs::ui
