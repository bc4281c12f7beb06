// World panel: the environment image, intensity and rotation, and the image's preview strip.
#include "world_panel.h"

#include <QDateTime>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QVBoxLayout>

#include "dialog_folders.h"
#include "parameter_widgets.h"
#include "scene_editor.h"
#include "texture/thumbnail.h"

namespace rs::ui {

namespace {

/// The pixels read for the strip: enough for its width, whatever the file's size.
constexpr int kReadSide = 2 * WorldPanel::kStripWidth;

qint64 stampOf(const std::string& path) {
    const QFileInfo info(QString::fromStdString(path));
    return info.exists() ? info.lastModified().toMSecsSinceEpoch() : -1;
}

}  // namespace

WorldPanel::WorldPanel(SceneEditor* editor, QWidget* parent) : QWidget(parent), editor_(editor) {
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout();
    layout->addLayout(form);

    const ParamDescriptor* fileDesc = findParameter(ParamKind::Environment, "file");
    auto* fileRow = new QWidget(this);
    auto* fileLayout = new QHBoxLayout(fileRow);
    fileLayout->setContentsMargins(0, 0, 0, 0);
    file_ = new QLabel(fileRow);
    file_->setObjectName(QStringLiteral("environmentFile"));
    file_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    file_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    auto* choose = new QPushButton(tr("Choose..."), fileRow);
    choose->setObjectName(QStringLiteral("environmentChoose"));
    choose->setToolTip(tr("An equirectangular image (HDR, EXR, PNG, JPEG, TIFF) around the scene"));
    remove_ = new QPushButton(tr("Remove"), fileRow);
    remove_->setObjectName(QStringLiteral("environmentRemove"));
    remove_->setToolTip(tr("No environment: rays that miss show the background colour"));
    fileLayout->addWidget(file_, 1);
    fileLayout->addWidget(choose);
    fileLayout->addWidget(remove_);
    form->addRow(QString::fromStdString(fileDesc ? fileDesc->label : "Image"), fileRow);
    connect(choose, &QPushButton::clicked, this, [this] { chooseImage(); });
    connect(remove_, &QPushButton::clicked, this, &WorldPanel::removeImage);

    // Intensity and rotation, as the schema describes them (labels, ranges, steps).
    for (const ParamDescriptor& d : parameters(ParamKind::Environment)) {
        if (d.type == ParamType::File) continue;
        const std::string key = d.key;
        ParamEditor pe =
            makeParamEditor(d, this, [this, key](const ParamValue& v) { applyParameter(key, v); });
        form->addRow(QString::fromStdString(d.label), pe.widget);
        numberEditors_.push_back(pe.widget);
        refreshers_.push_back([this, key, set = pe.setValue] {
            if (auto v = getParameter(editor_->document().environment, key)) set(*v);
        });
    }

    strip_ = new QLabel(this);
    strip_->setObjectName(QStringLiteral("environmentStrip"));
    strip_->setFixedHeight(kStripHeight);
    strip_->setAlignment(Qt::AlignCenter);
    error_ = new QLabel(this);
    error_->setObjectName(QStringLiteral("environmentError"));
    error_->setWordWrap(true);
    error_->setStyleSheet(QStringLiteral("color: #d03030;"));
    error_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(strip_);
    layout->addWidget(error_);
    layout->addStretch(1);

    connect(editor_, &SceneEditor::documentChanged, this, &WorldPanel::refresh);
    connect(editor_, &SceneEditor::documentReset, this, &WorldPanel::refresh);
    refresh();
}

bool WorldPanel::chooseImage() {
    QFileDialog dialog(this, tr("Choose Environment Image"),
                       dialogFolder(FileKind::Image, editor_->filePath()),
                       tr("Environment images (*.hdr *.exr *.png *.jpg *.jpeg *.tif *.tiff);;"
                          "All files (*)"));
    dialog.setObjectName(QStringLiteral("environmentFileDialog"));
    dialog.setFileMode(QFileDialog::ExistingFile);
    dialog.setOption(QFileDialog::DontUseNativeDialog);  // The same dialog everywhere (tests).
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return false;
    const QString path = QFileInfo(dialog.selectedFiles().first()).absoluteFilePath();
    rememberDialogFolder(FileKind::Image, path);
    setImageFile(path);
    return true;
}

void WorldPanel::setImageFile(const QString& path) {
    const std::string absolute = QFileInfo(path).absoluteFilePath().toStdString();
    SceneDocument doc = editor_->document();
    if (doc.environment.image.source() == absolute) return;
    doc.environment.image = ImageFile{absolute, absolute};
    editor_->edit(tr("Set environment %1").arg(QFileInfo(path).fileName()), std::move(doc));
}

void WorldPanel::removeImage() {
    SceneDocument doc = editor_->document();
    if (!doc.environment.present()) return;
    doc.environment.image = ImageFile{};
    editor_->edit(tr("Remove environment"), std::move(doc));
}

void WorldPanel::applyParameter(const std::string& key, const ParamValue& value) {
    SceneDocument doc = editor_->document();
    const std::string error = setParameter(doc.environment, key, value);
    if (!error.empty()) {
        error_->setText(QString::fromStdString(error));
        error_->show();
        refresh();  // Put the widget back to the document's value.
        return;
    }
    const ParamDescriptor* d = findParameter(ParamKind::Environment, key);
    // A drag of the slider or the spin box's arrows is one step (MergeKind::Property).
    editor_->edit(tr("Change environment %1").arg(QString::fromStdString(d ? d->label : key)),
                  std::move(doc), MergeKind::Property,
                  QStringLiteral("environment:") + QString::fromStdString(key));
}

void WorldPanel::refresh() {
    const Environment& env = editor_->document().environment;
    const bool present = env.present();
    // The name, which fits; the whole path in the tool tip.
    file_->setText(present ? QFileInfo(QString::fromStdString(env.image.file)).fileName()
                           : tr("None"));
    file_->setToolTip(present ? QString::fromStdString(env.image.source())
                              : tr("No environment: rays that miss show the background colour"));
    remove_->setEnabled(present);
    for (QWidget* w : numberEditors_) w->setEnabled(present);
    for (const auto& r : refreshers_) r();
    showPreview(present ? env.image.source() : std::string());
}

void WorldPanel::showPreview(const std::string& path) {
    const qint64 stamp = path.empty() ? -1 : stampOf(path);
    if (path == shown_ && stamp == shownStamp_) return;
    shown_ = path;
    shownStamp_ = stamp;
    strip_->setPixmap(QPixmap());
    error_->clear();
    if (path.empty()) {
        strip_->hide();
        error_->hide();
        return;
    }
    // OpenImageIO reads every format the renderer does (HDR and EXR clamped, sRGB-encoded).
    const Thumbnail t = makeThumbnail(path, kReadSide);
    if (!t.ok()) {
        strip_->hide();
        error_->setText(QString::fromStdString(t.error.empty() ? "cannot read " + path : t.error));
        error_->show();
        return;
    }
    const QImage image(t.rgb.data(), t.width, t.height, t.width * 3, QImage::Format_RGB888);
    strip_->setPixmap(QPixmap::fromImage(
        image.scaled(kStripWidth, kStripHeight, Qt::KeepAspectRatio, Qt::SmoothTransformation)));
    strip_->show();
    error_->hide();
}

QString WorldPanel::previewError() const {
    return error_->isHidden() ? QString() : error_->text();
}

bool WorldPanel::hasPreview() const {
    return !strip_->isHidden() && !strip_->pixmap().isNull();
}

}  // namespace rs::ui
