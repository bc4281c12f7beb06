// The colour-form widgets: selector, texture dialog, and the texture's preview.
#include "panels/color_pattern_editor.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>

#include "panels/dialog_folders.h"
#include "panels/image_preview.h"

namespace rs::ui {

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

ImagePreview* makeTexturePreview(QWidget* parent) {
    return new ImagePreview(QSize(kTextureThumbnailSide, kTextureThumbnailSide),
                            kTextureThumbnailSide, Qt::AlignLeft | Qt::AlignVCenter,
                            QStringLiteral("textureThumbnail"), QStringLiteral("textureError"),
                            parent);
}

}  // namespace rs::ui
