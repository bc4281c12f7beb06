// Widgets of a material's colour form in the property panel: the Colour / Checker / Image
// selector, the image file dialog and the texture's thumbnail (or why it cannot be read).
#pragma once

#include <QString>
#include <QWidget>
#include <string>

class QComboBox;
class QLabel;

namespace rs::ui {

/// The mode selector, items in ColorMode order (color_pattern_edits.h); object name
/// "colorMode".
QComboBox* makeColorModeCombo(QWidget* parent);

/// The file filter of texture dialogs (the extensions isTextureFileName accepts).
QString textureFileFilter();

/// Asks for an image file (Qt's own dialog, object name "textureFileDialog"), starting in
/// the folder images were last chosen in (dialog_folders.h); the absolute path, or empty
/// when cancelled. `documentPath`: the open scene's file, for the first time.
QString chooseTextureFile(QWidget* parent, const QString& documentPath);

/// A small preview of a texture file: the image scaled to fit kThumbnailSide, or, for a file
/// the renderer cannot read, the error sentence in its place.
class TexturePreview : public QWidget {
    Q_OBJECT
public:
    static constexpr int kThumbnailSide = 96;
    explicit TexturePreview(QWidget* parent = nullptr);
    /// Shows `path` (read once per path and modification time; later calls reuse it).
    void setImage(const std::string& path);
    /// The error shown (empty while a thumbnail is shown).
    QString error() const;
    /// True while a thumbnail (not an error) is shown.
    bool hasThumbnail() const;

private:
    QLabel* image_;
    QLabel* error_;
    std::string shown_;
};

}  // namespace rs::ui
