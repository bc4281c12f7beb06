// An image file dropped on an object in the viewport becomes its material's texture.
#pragma once

#include <QString>

#include "scene/document.h"

namespace rs::ui {

class SceneEditor;

/// Gives object `id` (kNoObject: the drop missed every object) the image at `absolutePath`
/// as its material's texture, in one undo step (giveObjectTexture says when a new material is
/// made), and selects it. Returns the sentence for the status bar: what happened, or, for
/// empty space or a light, to drop the image on an object.
QString dropTexture(SceneEditor& editor, ObjectId id, const QString& absolutePath);

}  // namespace rs::ui
