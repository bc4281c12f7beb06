// Widgets of a material's colour form in the property panel: the Colour / Checker / Image
// selector, the image file dialog and the texture's thumbnail (or why it cannot be read).
#pragma once

#include <QString>
#include <QWidget>

class QComboBox;

namespace rs::ui {

class ImagePreview;

/// The mode selector, items in ColorMode order (color_pattern_edits.h); object name
/// "colorMode".
QComboBox* makeColorModeCombo(QWidget* parent);

/// The file filter of texture dialogs (the extensions isTextureFileName accepts).
QString textureFileFilter();

/// Asks for an image file (Qt's own dialog, object name "textureFileDialog"), starting in
/// the folder images were last chosen in (dialog_folders.h); the absolute path, or empty
/// when cancelled. `documentPath`: the open scene's file, for the first time.
QString chooseTextureFile(QWidget* parent, const QString& documentPath);

/// The side of a texture's thumbnail in the property panel.
inline constexpr int kTextureThumbnailSide = 96;

/// A texture's preview (image_preview.h): the image scaled to fit kTextureThumbnailSide, or,
/// for a file the renderer cannot read, the error sentence in its place (labels
/// "textureThumbnail" and "textureError").
ImagePreview* makeTexturePreview(QWidget* parent);

}  // namespace rs::ui
