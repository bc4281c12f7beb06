// The World panel: the environment around the scene (its equirectangular image, intensity and
// rotation) with a preview strip of the image, every change one undoable edit.
#pragma once

#include <QString>
#include <QWidget>
#include <functional>
#include <string>
#include <vector>

#include "scene/parameters.h"

class QLabel;
class QPushButton;

namespace rs::ui {

class ImagePreview;
class SceneEditor;

/// Edits SceneDocument::environment. Without an image the background colour shows, and
/// Intensity and Rotation (from ParamKind::Environment's descriptors) are disabled.
class WorldPanel : public QWidget {
    Q_OBJECT
public:
    /// Size of the preview strip's box; the image keeps its aspect inside it.
    static constexpr int kStripWidth = 280;
    static constexpr int kStripHeight = 90;

    explicit WorldPanel(SceneEditor* editor, QWidget* parent = nullptr);

    /// Choose...: asks for an image (object name "environmentFileDialog"), starting in the
    /// folder images were last chosen in, and sets it; false when cancelled.
    bool chooseImage();
    /// Sets the environment's image to `path` (made absolute) in one undoable edit.
    void setImageFile(const QString& path);
    /// Remove: no environment image (the background colour shows), one undoable edit.
    void removeImage();

    /// The error shown instead of the strip (empty while the strip or nothing is shown).
    QString previewError() const;
    /// True while the strip shows an image.
    bool hasPreview() const;

private:
    void applyParameter(const std::string& key, const ParamValue& value);
    void refresh();

    SceneEditor* editor_;
    QLabel* file_;
    QPushButton* remove_;
    ImagePreview* preview_;
    QLabel* valueError_;  ///< A value the format refuses (the editors' ranges keep it rare).
    std::vector<QWidget*> numberEditors_;
    std::vector<std::function<void()>> refreshers_;
};

}  // namespace rs::ui
