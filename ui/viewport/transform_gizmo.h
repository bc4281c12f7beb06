// The transform gizmo: move arrows, plane squares, rotate rings and scale boxes drawn with
// QPainter over the viewport (not ray traced), and which of them is under the mouse.
#pragma once

#include <QPointF>
#include <QPolygonF>
#include <optional>
#include <vector>

#include "scene/document.h"
#include "viewport/modal_transform.h"
#include "viewport/view_projection.h"

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
    /// Radius of a rotate ring.
    static constexpr double kRingPx = 115.0;
    /// Near the frame's edge the whole gizmo shrinks to fit, down to this share of its size.
    static constexpr double kMinScale = 0.25;

    /// The gizmo about `pivot` with `axes` (columns) seen through `view`.
    TransformGizmo(const ViewProjection& view, const Vec3& pivot, const Mat3& axes);
    /// False when the pivot is behind the view (nothing is drawn or grabbed).
    bool valid() const { return valid_; }
    /// The handle under widget point `p`, if any.
    std::optional<GizmoHandle> handleAt(const QPointF& p) const;
    /// Whether `h` is drawn (an axis seen end-on has no arrow, a plane seen edge-on no square).
    bool shows(const GizmoHandle& h) const;
    /// A widget point that grabs `h` (tests press there); nullopt when it is not shown or
    /// other handles cover it whole.
    std::optional<QPointF> grabPoint(const GizmoHandle& h) const;
    /// Widget rectangle that holds everything paint() draws.
    QRectF bounds() const;
    /// The gizmo's size as a share of its full size (less near the frame's edge).
    double scale() const { return scale_; }
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
    /// Lays every handle out at `scale` of its full size from where each axis goes on screen
    /// per pixel of its length.
    void layOut(const QPointF (&screen)[3], double scale);

    bool valid_ = false;
    QPointF centre_;
    Axis axes_[3];
    double scale_ = 1.0;
    double arrowStartPx_ = 0.0;  ///< Where an arrow starts: the centre is left to picking.
    double boxHalfPx_ = 0.0;     ///< Half a scale box's side.
    double headPx_ = 0.0;        ///< Length of an arrow head.
};

}  // namespace rs::ui
