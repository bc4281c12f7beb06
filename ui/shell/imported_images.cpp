// Embedded images of imported assets: their folder, and their move next to a saved scene.
#include "shell/imported_images.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <map>

namespace rs::ui {

QString importedImageFolder(const QString& scenePath) {
    if (!scenePath.isEmpty()) return QFileInfo(scenePath).absolutePath();
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
           QStringLiteral("/imported-images");
}

namespace {
/// `name` in `folder`, or "base-2.ext", ... when another file has that name.
QString freeFileName(const QDir& folder, const QString& name) {
    const QFileInfo info(name);
    QString candidate = name;
    for (int n = 2; folder.exists(candidate); ++n)
        candidate = info.completeBaseName() + QLatin1Char('-') + QString::number(n) +
                    (info.suffix().isEmpty() ? QString() : QLatin1Char('.') + info.suffix());
    return folder.filePath(candidate);
}
}  // namespace

MovedImages moveImportedImages(SceneDocument& doc, const QString& fromFolder,
                               const QString& toFolder) {
    MovedImages moved;
    const QDir from(fromFolder), to(toFolder);
    if (QFileInfo(fromFolder).canonicalFilePath() == QFileInfo(toFolder).canonicalFilePath())
        return moved;
    std::map<QString, QString> copies;  // old path -> new path, one copy per image
    for (Material& m : doc.materials) {
        auto* texture = std::get_if<ImageTexture>(&m.pattern);
        if (!texture) continue;
        const QString source = QString::fromStdString(texture->image.source());
        const QFileInfo info(source);
        if (!info.isAbsolute() || info.absolutePath() != from.absolutePath()) continue;
        auto [it, fresh] = copies.try_emplace(source);
        if (fresh) {
            const QString target = freeFileName(to, info.fileName());
            if (QFile::copy(source, target)) {
                it->second = target;
                moved.copied << target;
            } else {
                moved.notes << QObject::tr(
                                   "image \"%1\" of material \"%2\" could not be copied "
                                   "to %3; the scene refers to it where it is")
                                   .arg(source, QString::fromStdString(m.name), toFolder);
            }
        }
        if (it->second.isEmpty()) continue;
        texture->image.file = it->second.toStdString();
        texture->image.resolvedPath = it->second.toStdString();
    }
    return moved;
}

}  // namespace rs::ui
