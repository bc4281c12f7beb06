// dropTexture: one edit through the scene editor and a sentence saying what it did.
#include "document/texture_drop.h"

#include <QFileInfo>
#include <QObject>

#include "document/color_pattern_edits.h"
#include "document/scene_editor.h"

namespace rs::ui {

QString dropTexture(SceneEditor& editor, ObjectId id, const QString& absolutePath) {
    const QString file = QFileInfo(absolutePath).fileName();
    const Object* target = editor.document().findObject(id);
    if (!target)
        return QObject::tr("Drop the image %1 on an object to give its material that texture")
            .arg(file);
    const QString object = QString::fromStdString(target->name);
    SceneDocument doc = editor.document();
    const TextureDrop drop = giveObjectTexture(doc, id, absolutePath.toStdString());
    if (!drop.error.empty())
        return QObject::tr("Image %1 not applied: %2")
            .arg(file, QString::fromStdString(drop.error));
    const QString material = QString::fromStdString(drop.material);
    if (!drop.changed) return QObject::tr("%1 already has the texture %2").arg(object, file);
    editor.edit(QObject::tr("Texture %1 on %2").arg(file, object), std::move(doc));
    editor.setSelection(id);
    return drop.created ? QObject::tr(
                              "%1 now has its own material \"%2\" with the texture %3 "
                              "(its old material is unchanged for the other objects)")
                              .arg(object, material, file)
                        : QObject::tr("Material \"%1\" of %2 now has the texture %3")
                              .arg(material, object, file);
}

}  // namespace rs::ui
