// Undo command that stores the document before and after a change and applies by replacing.
#pragma once

#include <QUndoCommand>

#include "document/scene_editor.h"
#include "scene/document.h"

namespace rs::ui {

/// One undoable edit; mergeWith() folds consecutive edits of the same kind and key.
class DocumentCommand : public QUndoCommand {
public:
    DocumentCommand(SceneEditor* editor, const QString& text, SceneDocument before,
                    SceneDocument after, MergeKind merge, QString mergeKey, int serial);
    void undo() override;
    void redo() override;
    int id() const override { return int(merge_); }
    bool mergeWith(const QUndoCommand* other) override;

private:
    SceneEditor* editor_;
    SceneDocument before_, after_;
    MergeKind merge_;
    QString mergeKey_;
    int serial_;
};

}  // namespace rs::ui
