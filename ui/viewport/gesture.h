// A G / R / S gesture running in the viewport, and the gizmo handle it was started from.
#pragma once

#include <optional>
#include <vector>

#include "scene/document.h"
#include "viewport/modal_transform.h"
#include "viewport/transform_gizmo.h"
#include "viewport/view_projection.h"

namespace rs::ui {

/// One running gesture: the ModalTransform that turns keys and cursor into a document, and
/// the gizmo handle it was started from. A handle's gesture ends when its button is released;
/// one started by a key ends with a click.
class Gesture {
public:
    /// A `kind` gesture on `ids` of `start` from `cursor`, its locks along `axes` (columns);
    /// locked to `handle` when a gizmo handle started it.
    Gesture(TransformKind kind, const SceneDocument& start, const std::vector<ObjectId>& ids,
            const QPointF& cursor, const Mat3& axes, const std::optional<GizmoHandle>& handle);

    ModalTransform& transform() { return transform_; }
    const ModalTransform& transform() const { return transform_; }
    /// The gizmo handle that started it (drawn highlighted), or nullopt for a key's.
    const std::optional<GizmoHandle>& handle() const { return handle_; }
    /// `current` with the gesture's entities as it shows them through `view`; the rest as in
    /// `current`, so other edits made meanwhile survive.
    SceneDocument applied(SceneDocument current, const ViewProjection& view) const;
    /// `current` with the gesture's entities back where it found them.
    SceneDocument restored(SceneDocument current) const;

private:
    ModalTransform transform_;
    std::optional<GizmoHandle> handle_;
};

}  // namespace rs::ui
