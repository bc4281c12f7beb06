// SceneEditor: document ownership, undoable edits and selection bookkeeping.
#include "document/scene_editor.h"

#include <algorithm>

#include "document/document_command.h"

namespace rs::ui {

SceneEditor::SceneEditor(QObject* parent) : QObject(parent) {}

void SceneEditor::edit(const QString& text, SceneDocument after, MergeKind merge,
                       const QString& mergeKey) {
    // QUndoStack takes ownership of the command.
    undo_.push(
        new DocumentCommand(this, text, doc_, std::move(after), merge, mergeKey, mergeSerial_));
}

void SceneEditor::replaceDocument(SceneDocument doc) {
    lastChange_ = describeChange(doc_, doc);
    doc_ = std::move(doc);
    // An undo or a delete may take selected entities away: the rest stay selected.
    std::vector<ObjectId> kept;
    for (ObjectId id : selected_)
        if (doc_.findObject(id) || doc_.findLight(id)) kept.push_back(id);
    if (kept != selected_) setSelection(kept);
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
    lastChange_ = DocumentChange::everything();
    selected_.clear();
    cameraSelected_ = false;
    setFilePath(filePath);
    Q_EMIT documentReset();
    Q_EMIT documentChanged();
    Q_EMIT selectionChanged(kNoObject);
}

void SceneEditor::setFilePath(const QString& path) {
    filePath_ = path;
    Q_EMIT filePathChanged(path);
}

void SceneEditor::reloadImages() {
    bool names = doc_.environment.present();
    for (const Material& m : doc_.materials)
        names = names || std::holds_alternative<ImageTexture>(m.pattern);
    if (names) Q_EMIT imagesReloaded();
}

ObjectId SceneEditor::selection() const {
    if (cameraSelected_) return kCameraSelection;
    return selected_.empty() ? kNoObject : selected_.back();
}

bool SceneEditor::isSelected(ObjectId id) const {
    return std::find(selected_.begin(), selected_.end(), id) != selected_.end();
}

void SceneEditor::setSelection(ObjectId id) {
    if (id == kCameraSelection) {
        if (cameraSelected_) return;
        selected_.clear();
        cameraSelected_ = true;
        closeMerge();
        Q_EMIT selectionChanged(id);
        return;
    }
    setSelection(id == kNoObject ? std::vector<ObjectId>{} : std::vector<ObjectId>{id});
}

void SceneEditor::setSelection(const std::vector<ObjectId>& ids) {
    std::vector<ObjectId> chosen;
    for (ObjectId id : ids)
        if ((doc_.findObject(id) || doc_.findLight(id)) &&
            std::find(chosen.begin(), chosen.end(), id) == chosen.end())
            chosen.push_back(id);
    if (!cameraSelected_ && chosen == selected_) return;
    selected_ = std::move(chosen);
    cameraSelected_ = false;
    closeMerge();
    Q_EMIT selectionChanged(selection());
}

void SceneEditor::toggleSelected(ObjectId id) {
    std::vector<ObjectId> ids = selected_;
    const auto it = std::find(ids.begin(), ids.end(), id);
    if (it != ids.end())
        ids.erase(it);
    else
        ids.push_back(id);
    setSelection(ids);
}

}  // namespace rs::ui
