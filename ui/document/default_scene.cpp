// Default scene lookup: installed data next to the executable, else the build's source tree.
#include "document/default_scene.h"

#include <QDir>
#include <QFileInfo>

#ifndef RAYSTUDIO_SOURCE_SCENES_DIR
#error "RAYSTUDIO_SOURCE_SCENES_DIR must name the source tree's scenes folder (ui/CMakeLists.txt)"
#endif

namespace rs::ui {

QString defaultScenePath(const QString& executableDir) {
    const QString name = QStringLiteral("reference-room.scene.json");
    const QDir exe(executableDir);
    // Installed first: an installed binary must not open a source tree that happens to remain.
    const QStringList candidates = {
        exe.filePath(QStringLiteral("../share/raystudio/scenes/") + name),
        QDir(QStringLiteral(RAYSTUDIO_SOURCE_SCENES_DIR)).filePath(name),
    };
    for (const QString& c : candidates)
        if (QFileInfo(c).isFile()) return QFileInfo(c).canonicalFilePath();
    return {};
}

}  // namespace rs::ui
