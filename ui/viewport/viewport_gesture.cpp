// Viewport G / R / S gestures, from keys or from a gizmo handle: one merged undo step each,
// under the session's drag policies (the same beginInteraction / endInteraction the mouse
// drag uses), whether they move, rotate or scale.
#include <QCursor>

#include "adapter/session_controller.h"
#include "document/scene_editor.h"
#include "viewport/viewport.h"

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

bool Viewport::beginTransform(TransformKind kind) {
    if (gesture_ || drag_.active()) return false;
    // The gesture measures from where the cursor is now; a key press gives no position.
    QPointF cursor = mapFromGlobal(QCursor::pos());
    if (!rect().contains(cursor.toPoint())) cursor = drag_.lastPos();
    return startGesture(kind, cursor, std::nullopt);
}

bool Viewport::startGesture(TransformKind kind, const QPointF& cursor,
                            const std::optional<GizmoHandle>& handle) {
    std::vector<ObjectId> ids = editor_->selectedIds();
    if (ids.empty()) return false;
    drag_.disarmBox();
    editor_->closeMerge();
    const SceneDocument& doc = editor_->document();
    gesture_.emplace(kind, doc, ids, cursor, gizmoAxes(doc, ids.back(), localAxes_), handle);
    drag_.moveTo(cursor.toPoint());
    setFocus(Qt::OtherFocusReason);
    // A gizmo drag holds a button, which tracks the mouse anyway.
    if (!handle) setMouseTracking(true);
    session_->beginInteraction(gesture_->transform().ids().front());
    Q_EMIT statusMessage(gesture_->transform().describe(projection()));
    repaintOverlay();
    syncModal();
    return true;
}

void Viewport::updateGesture() {
    if (!gesture_) return;
    // Only the selection comes from the gesture; the rest is the current document, as in
    // the mouse drag.
    SceneDocument doc = gesture_->applied(editor_->document(), projection());
    Q_EMIT statusMessage(gesture_->transform().describe(projection()));
    if (doc.sameContent(editor_->document())) return;
    dragEdit(gestureText(gesture_->transform().kind()), std::move(doc), kGestureMergeKey);
}

void Viewport::finishGesture(bool cancel) {
    if (!gesture_) return;
    if (cancel) {
        // Merged into the gesture's step, the restore leaves it empty and the stack drops it.
        SceneDocument doc = gesture_->restored(editor_->document());
        if (!doc.sameContent(editor_->document()))
            dragEdit(gestureText(gesture_->transform().kind()), std::move(doc), kGestureMergeKey);
    } else {
        updateGesture();
    }
    gesture_.reset();
    setMouseTracking(false);
    session_->endInteraction();
    editor_->closeMerge();
    Q_EMIT statusMessage({});
    repaintOverlay();
    syncModal();
}

void Viewport::cancelInteraction() {
    if (gesture_) finishGesture(true);
    if (drag_.active()) finishDrag(true);
    drag_.disarmBox();
    syncModal();
}

void Viewport::abandonDrag() {
    const bool interacting = gesture_ || drag_.kind() == MouseDrag::Kind::Object;
    gesture_.reset();
    drag_.finish();
    setMouseTracking(false);
    if (interacting) session_->endInteraction();
    editor_->closeMerge();
    Q_EMIT statusMessage({});
    repaintOverlay();
    syncModal();
}

}  // namespace rs::ui
