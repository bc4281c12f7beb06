// Gesture: a ModalTransform applied to the document as it is now.
#include "viewport/gesture.h"

#include "document/scene_edits.h"

namespace rs::ui {

Gesture::Gesture(TransformKind kind, const SceneDocument& start, const std::vector<ObjectId>& ids,
                 const QPointF& cursor, const Mat3& axes, const std::optional<GizmoHandle>& handle)
    : transform_(kind, start, ids, cursor), handle_(handle) {
    transform_.setOrientation(axes);
    if (handle) transform_.lock(handle->axis, handle->plane);
}

SceneDocument Gesture::applied(SceneDocument current, const ViewProjection& view) const {
    const SceneDocument moved = transform_.result(view);
    for (ObjectId id : transform_.ids()) restoreEntity(current, moved, id);
    return current;
}

SceneDocument Gesture::restored(SceneDocument current) const {
    for (ObjectId id : transform_.ids()) restoreEntity(current, transform_.start(), id);
    return current;
}

}  // namespace rs::ui
