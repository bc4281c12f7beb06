// Writing a scene file the way every designer save does it: QSaveFile, so a crash or a kill
// mid-write leaves the previous file whole.
#pragma once

#include <QString>

#include "scene/document.h"

namespace rs::ui {

/// Serialises `doc` (mesh paths relative to the file's folder where they lie below it) and
/// commits it to `path` atomically; false with `error` set when any step fails.
bool writeSceneFile(const QString& path, const SceneDocument& doc, QString& error);

}  // namespace rs::ui
