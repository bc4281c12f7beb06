// The open document, its undo stack, its file and the selection: the single source of truth
// the viewport, outliner and property panel observe.
#pragma once

#include <QObject>
#include <QString>
#include <QUndoStack>
#include <optional>
#include <vector>

#include "scene/document.h"
#include "scene/document_change.h"

namespace rs::ui {

/// Merge keys group consecutive edits into one undo step (a drag, a slider sweep).
enum class MergeKind { None = -1, Drag = 1, Property = 2, Camera = 3 };

/// Owns the SceneDocument; every change goes through edit() as an undoable command.
class SceneEditor : public QObject {
    Q_OBJECT
public:
    explicit SceneEditor(QObject* parent = nullptr);

    /// The current document.
    const SceneDocument& document() const { return doc_; }
    /// What the last documentChanged() changed (everything after documentReset()), so a
    /// listener updates what an edit touched rather than the whole scene.
    const DocumentChange& lastChange() const { return lastChange_; }
    /// The undo stack (its clean state is the saved state).
    QUndoStack* undoStack() { return &undo_; }

    /// Pushes an undoable change from the current document to `after`. Consecutive edits with
    /// the same merge kind and key become one step.
    void edit(const QString& text, SceneDocument after, MergeKind merge = MergeKind::None,
              const QString& mergeKey = {});
    /// Ends the current merge run: the next edit starts a new undo step.
    void closeMerge() { ++mergeSerial_; }
    /// Replaces the document without undo (used by undo commands themselves).
    void replaceDocument(SceneDocument doc);
    /// Shows `doc` as the document, without an undo step, until endPreview() (a colour
    /// dialog's live preview); the first call keeps the document to go back to.
    void preview(SceneDocument doc);
    /// Puts back the document from before preview(); nothing when no preview runs.
    void endPreview();
    /// Loads a new document (Open/New): clears undo history, sets the file, clears selection.
    void resetDocument(SceneDocument doc, const QString& filePath);

    /// The scene file path; empty for an unsaved new scene.
    QString filePath() const { return filePath_; }
    void setFilePath(const QString& path);

    // The selection: any number of lights and objects, or the camera alone. It is the one
    // place that says what "the selected objects" are (edits that act on several use it).
    /// The active entity: the last one selected (the property panel and the outliner's
    /// current row show it); kNoObject for none; kCameraSelection for the camera.
    ObjectId selection() const;
    /// Every selected light and object, in the order they were selected (the active one
    /// last); empty when nothing or the camera is selected.
    const std::vector<ObjectId>& selectedIds() const { return selected_; }
    bool isSelected(ObjectId id) const;
    /// Replaces the selection with `id` alone (kNoObject: none; kCameraSelection: the camera).
    void setSelection(ObjectId id);
    /// Replaces the selection with `ids` (duplicates and ids absent from the document are
    /// dropped); the last becomes the active one.
    void setSelection(const std::vector<ObjectId>& ids);
    /// Adds `id` to the selection (as the active one), or removes it when selected:
    /// Ctrl/Shift-click.
    void toggleSelected(ObjectId id);
    /// Pseudo id of the camera in selections (never a real document id in practice).
    static constexpr ObjectId kCameraSelection = 0xFFFFFFFFu;

    /// The image files the document names (textures, the environment) may have been saved
    /// again on disk: when it names any, imagesReloaded() asks whoever shows them to look
    /// again (the viewport's session, thumbnails, material previews). The document does not
    /// change; no undo step. The window calls it when it comes back to the front (from a
    /// paint program, say) and from File > Reload Images.
    void reloadImages();

    /// Serial used by commands to decide whether they may merge.
    int mergeSerial() const { return mergeSerial_; }

Q_SIGNALS:
    /// The document content changed (edit, undo, redo, open).
    void documentChanged();
    /// A new document was loaded (structure may be entirely different).
    void documentReset();
    void selectionChanged(rs::ObjectId id);
    void filePathChanged(const QString& path);
    /// reloadImages(): image files the document names may have changed on disk.
    void imagesReloaded();

private:
    SceneDocument doc_;
    DocumentChange lastChange_ = DocumentChange::everything();
    QUndoStack undo_;
    QString filePath_;
    std::vector<ObjectId> selected_;
    bool cameraSelected_ = false;
    int mergeSerial_ = 0;
    std::optional<SceneDocument> beforePreview_;
};

}  // namespace rs::ui
