// World panel: the environment image, intensity and rotation, and the image's preview strip.
#include "panels/world_panel.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "document/scene_editor.h"
#include "panels/dialog_folders.h"
#include "panels/image_preview.h"
#include "panels/parameter_widgets.h"

namespace rs::ui {

namespace {

/// The pixels read for the strip: enough for its width, whatever the file's size.
constexpr int kReadSide = 2 * WorldPanel::kStripWidth;

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

    preview_ = new ImagePreview(QSize(kStripWidth, kStripHeight), kReadSide, Qt::AlignCenter,
                                QStringLiteral("environmentStrip"),
                                QStringLiteral("environmentError"), this);
    layout->addWidget(preview_);
    valueError_ = new QLabel(this);
    valueError_->setObjectName(QStringLiteral("environmentValueError"));
    valueError_->setWordWrap(true);
    valueError_->setStyleSheet(QStringLiteral("color: #d03030;"));
    valueError_->hide();
    layout->addWidget(valueError_);
    layout->addStretch(1);

    connect(editor_, &SceneEditor::documentChanged, this, &WorldPanel::refresh);
    connect(editor_, &SceneEditor::imagesReloaded, this, &WorldPanel::refresh);
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
        valueError_->setText(QString::fromStdString(error));
        valueError_->show();
        refresh();  // Put the widget back to the document's value.
        return;
    }
    valueError_->hide();
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
    preview_->setImage(present ? env.image.source() : std::string());
}

QString WorldPanel::previewError() const {
    return preview_->error();
}

bool WorldPanel::hasPreview() const {
    return preview_->hasImage();
}

}  // namespace rs::ui
