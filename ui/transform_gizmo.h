// The transform gizmo: move arrows, plane squares, rotate rings and scale boxes drawn with
// QPainter over the viewport (not ray traced), and which of them is under the mouse.
#pragma once

#include <QPointF>
#include <QPolygonF>
#include <optional>
#include <vector>

#include "modal_transform.h"
#include "scene/document.h"
#include "view_projection.h"

class QPainter;

namespace rs::ui {

/// A part of the gizmo the mouse can grab: dragging it runs a G / R / S gesture locked to it.
struct GizmoHandle {
    TransformKind kind = TransformKind::Move;
    int axis = 0;        ///< 0/1/2 for the gizmo's X/Y/Z.
    bool plane = false;  ///< Move in the plane normal to `axis` (the square between the others).
    bool operator==(const GizmoHandle&) const = default;
};

/// The axes the gizmo shows for the selection, as columns: the world's, or (local) the
/// active object's own rotation, Blender's transform orientations (a spot's or a sun's local
/// -Z is where it shines).
Mat3 gizmoAxes(const SceneDocument& doc, ObjectId active, bool local);

/// The gizmo of one pose, at a fixed size on screen whatever the distance.
class TransformGizmo {
public:
    static constexpr double kArrowPx = 70.0;  ///< Length of a move arrow.
    static constexpr double kScalePx = 92.0;  ///< Distance of a scale box from the centre.
    /// Radius of a rotate ring; less for a pivot nearer the frame's edge than that.
    static constexpr double kRingPx = 115.0;

    /// The gizmo about `pivot` with `axes` (columns) seen through `view`.
    TransformGizmo(const ViewProjection& view, const Vec3& pivot, const Mat3& axes);
    /// False when the pivot is behind the view (nothing is drawn or grabbed).
    bool valid() const { return valid_; }
    /// The handle under widget point `p`, if any.
    std::optional<GizmoHandle> handleAt(const QPointF& p) const;
    /// A widget point that grabs `h` (tests press there); nullopt when it is not shown.
    std::optional<QPointF> grabPoint(const GizmoHandle& h) const;
    /// Widget rectangle that holds everything paint() draws.
    QRectF bounds() const;
    /// Draws the gizmo, `active` (the handle being dragged) highlighted.
    void paint(QPainter& p, const std::optional<GizmoHandle>& active) const;

private:
    /// Screen geometry of one axis; `shown` is false for an axis seen end-on.
    struct Axis {
        bool shown = false;
        QPointF tip;                ///< End of the arrow.
        QPointF scaleBox;           ///< Centre of the scale box.
        QPolygonF planeSquare;      ///< The square of the plane normal to this axis.
        std::vector<QPointF> ring;  ///< The rotate ring about this axis (closed polyline).
    };
    bool valid_ = false;
    QPointF centre_;
    Axis axes_[3];
};

}  // namespace rs::ui
