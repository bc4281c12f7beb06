// SceneEditor: document ownership, undoable edits and selection bookkeeping.
#include "scene_editor.h"

#include "document_command.h"

namespace rs::ui {

SceneEditor::SceneEditor(QObject* parent) : QObject(parent) {}

void SceneEditor::edit(const QString& text, SceneDocument after, MergeKind merge,
                       const QString& mergeKey) {
    // QUndoStack takes ownership of the command.
    undo_.push(new DocumentCommand(this, text, doc_, std::move(after), merge, mergeKey,
                                   mergeSerial_));
}

void SceneEditor::replaceDocument(SceneDocument doc) {
    doc_ = std::move(doc);
    if (selection_ != kNoObject && selection_ != kCameraSelection && !doc_.findObject(selection_) &&
        !doc_.findLight(selection_))
        setSelection(kNoObject);
    Q_EMIT documentChanged();
}

void SceneEditor::preview(SceneDocument doc) {
    if (!beforePreview_) beforePreview_ = doc_;
    replaceDocument(std::move(doc));
}

void SceneEditor::endPreview() {
    if (!beforePreview_) return;
    SceneDocument before = std::move(*beforePreview_);
    beforePreview_.reset();
    replaceDocument(std::move(before));
}

void SceneEditor::resetDocument(SceneDocument doc, const QString& filePath) {
    beforePreview_.reset();
    undo_.clear();
    doc_ = std::move(doc);
    selection_ = kNoObject;
    setFilePath(filePath);
    Q_EMIT documentReset();
    Q_EMIT documentChanged();
    Q_EMIT selectionChanged(selection_);
}

void SceneEditor::setFilePath(const QString& path) {
    filePath_ = path;
    Q_EMIT filePathChanged(path);
}

void SceneEditor::setSelection(ObjectId id) {
    if (id == selection_) return;
    selection_ = id;
    closeMerge();
    Q_EMIT selectionChanged(id);
}

}  // namespace rs::ui
