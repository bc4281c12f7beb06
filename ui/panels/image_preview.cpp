// A preview of an image file: asked of the PreviewReader, shown when it arrives.
#include "panels/image_preview.h"

#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>

#include "panels/preview_reader.h"

namespace rs::ui {

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
    note_ = new QLabel(this);
    note_->setObjectName(imageName + QStringLiteral("Reading"));
    note_->setFixedHeight(box.height());  // In the image's place: nothing below moves.
    note_->setAlignment(alignment);
    note_->setStyleSheet(QStringLiteral("color: palette(mid);"));
    layout->addWidget(image_);
    layout->addWidget(error_);
    layout->addWidget(note_);
    image_->hide();
    error_->hide();
    note_->hide();
}

void ImagePreview::setImage(const std::string& path) {
    const FileStamp stamp = path.empty() ? FileStamp{} : fileStampOf(path);
    if (path == shown_ && stamp == shownStamp_) return;
    shown_ = path;
    shownStamp_ = stamp;
    if (path.empty()) return display(nullptr);
    PreviewReader& reader = PreviewReader::shared();
    if (const auto made = reader.find(path, stamp, readSide_)) return display(&*made);
    // What was shown stays hidden meanwhile: it is another file's.
    image_->hide();
    error_->hide();
    note_->setText(tr("Reading %1...").arg(QFileInfo(QString::fromStdString(path)).fileName()));
    note_->show();
    reading_ = true;
    reader.request(path, stamp, readSide_, mailbox_,
                   [this, path, stamp](const PreviewPixels& preview) {
                       // Only if it is still the file (as it was) to show.
                       if (path == shown_ && stamp == shownStamp_) display(&preview);
                   });
}

void ImagePreview::display(const PreviewPixels* preview) {
    reading_ = false;
    note_->hide();
    QImage shown = preview ? preview->image : QImage();
    if (!shown.isNull() && (shown.width() > box_.width() || shown.height() > box_.height()))
        shown = shown.scaled(box_, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    image_->setPixmap(shown.isNull() ? QPixmap() : QPixmap::fromImage(shown));
    image_->setVisible(!shown.isNull());
    const QString error = preview ? QString::fromStdString(preview->error) : QString();
    error_->setText(error);
    error_->setVisible(!error.isEmpty());
}

QString ImagePreview::error() const {
    return error_->isHidden() ? QString() : error_->text();
}

bool ImagePreview::hasImage() const {
    return !image_->isHidden() && !image_->pixmap().isNull();
}

}  // namespace rs::ui
