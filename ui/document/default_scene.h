// Where the designer finds the bundled reference room when it is started without a scene.
#pragma once

#include <QString>

namespace rs::ui {

/// scenes/reference-room.scene.json for an executable in `executableDir`: the installed copy
/// (../share/raystudio/scenes/) first, else the source tree the build was configured from.
/// Empty when neither exists. Never relative to the working folder: a desktop launcher or a
/// shell anywhere must open the same scene.
QString defaultScenePath(const QString& executableDir);

}  // namespace rs::ui
