// Atomic scene saves through QSaveFile (temporary file in the same folder, renamed on commit).
#include "document/scene_file_writer.h"

#include <QFileInfo>
#include <QSaveFile>

#include "io/scene_io.h"

namespace rs::ui {

bool writeSceneFile(const QString& path, const SceneDocument& doc, QString& error) {
    const std::string text = serializeScene(doc, QFileInfo(path).absolutePath().toStdString());
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(text.data(), qint64(text.size())) != qint64(text.size()) || !file.commit()) {
        error = file.errorString();
        return false;
    }
    return true;
}

}  // namespace rs::ui
