// Where the designer keeps the images embedded in imported assets: next to the scene once it
// has a file, else in the designer's data folder until the scene is saved.
#pragma once

#include <QString>
#include <QStringList>

#include "scene/document.h"

namespace rs::ui {

/// The folder an import writes embedded images into for the scene at `scenePath`: the
/// scene's folder, or the data folder's "imported-images" for a scene never saved.
QString importedImageFolder(const QString& scenePath);

/// What moving the images of a saved scene did.
struct MovedImages {
    QStringList copied;  ///< The new files.
    QStringList notes;   ///< Images that could not be copied (they keep their old path).
};

/// Copies every texture of `doc` that lies in `fromFolder` (the data folder of an unsaved
/// scene's imports) into `toFolder` (the scene's), keeping its file name unless another file
/// has it there ("name-2.png", ...), and points the materials at the copies; so a scene
/// saved after an import carries its images with it.
MovedImages moveImportedImages(SceneDocument& doc, const QString& fromFolder,
                               const QString& toFolder);

}  // namespace rs::ui
