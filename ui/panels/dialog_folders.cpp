// Remembered dialog folders, one QSettings key per kind of file.
#include "panels/dialog_folders.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace rs::ui {

namespace {
QString settingsKey(FileKind kind) {
    switch (kind) {
        case FileKind::Scene:
            return QStringLiteral("dialogs/sceneFolder");
        case FileKind::Mesh:
            return QStringLiteral("dialogs/meshFolder");
        case FileKind::Image:
            return QStringLiteral("dialogs/imageFolder");
    }
    return {};
}
}  // namespace

QString dialogFolder(FileKind kind, const QString& documentPath) {
    const QString remembered = QSettings().value(settingsKey(kind)).toString();
    if (!remembered.isEmpty() && QFileInfo(remembered).isDir()) return remembered;
    if (!documentPath.isEmpty()) {
        const QString folder = QFileInfo(documentPath).absolutePath();
        if (QFileInfo(folder).isDir()) return folder;
    }
    return QDir::homePath();
}

void rememberDialogFolder(FileKind kind, const QString& chosenPath) {
    if (chosenPath.isEmpty()) return;
    QSettings().setValue(settingsKey(kind), QFileInfo(chosenPath).absolutePath());
}

}  // namespace rs::ui
