// Viewport G / R / S gestures: one merged undo step each, under the session's drag policies
// (the same beginInteraction / endInteraction the mouse drag uses).
#include "viewport.h"

#include "scene_editor.h"
#include "scene_edits.h"
#include "session_controller.h"

#include <QCursor>

namespace rs::ui {

namespace {
const QString kGestureMergeKey = QStringLiteral("gesture");

QString gestureText(TransformKind kind) {
    switch (kind) {
        case TransformKind::Move:
            return Viewport::tr("Move");
        case TransformKind::Rotate:
            return Viewport::tr("Rotate");
        case TransformKind::Scale:
            return Viewport::tr("Scale");
    }
    return {};
}
}  // namespace

std::vector<ObjectId> Viewport::selectedIds() const {
    const ObjectId sel = editor_->selection();
    const SceneDocument& doc = editor_->document();
    if (doc.findObject(sel) || doc.findLight(sel)) return {sel};
    return {};
}

bool Viewport::beginTransform(TransformKind kind) {
    if (gesture_ || drag_ != Drag::None) return false;
    std::vector<ObjectId> ids = selectedIds();
    if (ids.empty()) return false;
    // The gesture measures from where the cursor is now; a key press gives no position.
    QPointF cursor = mapFromGlobal(QCursor::pos());
    if (!rect().contains(cursor.toPoint())) cursor = lastPos_;
    editor_->closeMerge();
    gesture_.emplace(kind, editor_->document(), std::move(ids), cursor);
    setFocus(Qt::OtherFocusReason);
    setMouseTracking(true);
    session_->beginInteraction(gesture_->ids().front());
    Q_EMIT statusMessage(gesture_->describe());
    return true;
}

void Viewport::updateGesture() {
    if (!gesture_) return;
    // Only the selection comes from the gesture; the rest is the current document, as in
    // the mouse drag.
    const SceneDocument moved = gesture_->result(projection());
    SceneDocument doc = editor_->document();
    for (ObjectId id : gesture_->ids()) restoreEntity(doc, moved, id);
    Q_EMIT statusMessage(gesture_->describe());
    if (doc.sameContent(editor_->document())) return;
    editor_->edit(gestureText(gesture_->kind()), std::move(doc), MergeKind::Drag, kGestureMergeKey);
}

void Viewport::finishGesture(bool cancel) {
    if (!gesture_) return;
    if (cancel) {
        // Merged into the gesture's step, the restore leaves it empty and the stack drops it.
        SceneDocument doc = editor_->document();
        for (ObjectId id : gesture_->ids()) restoreEntity(doc, gesture_->start(), id);
        if (!doc.sameContent(editor_->document()))
            editor_->edit(gestureText(gesture_->kind()), std::move(doc), MergeKind::Drag,
                          kGestureMergeKey);
    } else {
        updateGesture();
    }
    gesture_.reset();
    setMouseTracking(false);
    session_->endInteraction();
    editor_->closeMerge();
    Q_EMIT statusMessage({});
}

}  // namespace rs::ui
