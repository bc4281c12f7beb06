// Moving the selection with the mouse in the viewport: in the image plane, or along a world
// axis that X, Y or Z locks.
#pragma once

#include <QPoint>
#include <vector>

#include "scene/document.h"
#include "viewport/view_projection.h"

namespace rs::ui {

/// One object drag from press to release. The entities follow the cursor on the plane
/// parallel to the image through the anchor (the pressed entity's centre, or the point
/// pressed on a plane), or along the locked world axis; the point grabbed stays under the
/// cursor. Each step moves them from where they were at the start, so the steps never add up.
class ObjectDrag {
public:
    /// Drags `ids` (the selection, or the pressed entity alone) of `start`, grabbed at widget
    /// point `press` as seen through `view`, by the entity `pressed` with its centre at `anchor`.
    ObjectDrag(ObjectId pressed, std::vector<ObjectId> ids, SceneDocument start, const Vec3& anchor,
               const ViewProjection& view, const QPoint& press);

    /// The entity pressed (the drag's undo step is merged by it).
    ObjectId pressed() const { return pressed_; }
    /// X, Y or Z (0/1/2): locks the drag to that world axis, or frees it when it is locked.
    void toggleAxis(int axis) { axisLock_ = axisLock_ == axis ? -1 : axis; }
    /// `current` with the dragged entities moved for the cursor at `pos` as seen through
    /// `view` (the view now, not the one at press: the user may dolly during the drag).
    /// Everything else stays as in `current`, so other edits made meanwhile survive.
    SceneDocument moved(SceneDocument current, const ViewProjection& view, const QPoint& pos) const;
    /// `current` with the dragged entities back where they were at the start.
    SceneDocument restored(SceneDocument current) const;

private:
    /// The grabbed point under the cursor at `pos`.
    Vec3 grabbedAt(const ViewProjection& view, const QPoint& pos) const;

    ObjectId pressed_;
    std::vector<ObjectId> ids_;  ///< Every entity the drag moves.
    SceneDocument start_;
    Vec3 anchor_;            ///< Centre of the dragged object at press.
    Vec3 grabOffset_{0.0f};  ///< Press point on the drag plane minus the anchor.
    int axisLock_ = -1;      ///< -1 free, else 0/1/2 for X/Y/Z.
};

}  // namespace rs::ui
