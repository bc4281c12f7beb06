// One G / R / S gesture (Blender's modal transforms): axis locks, typed values, snapping.
#pragma once

#include <QPointF>
#include <QString>
#include <vector>

#include "scene/document.h"
#include "viewport/view_projection.h"

namespace rs::ui {

/// What a gesture does to the selection.
enum class TransformKind { Move, Rotate, Scale };

/// The state of a gesture; result() is the document it shows for the input so far.
class ModalTransform {
public:
    /// Ctrl while moving snaps to these steps.
    static constexpr float kGridStep = 0.25f;
    static constexpr float kAngleStepDeg = 15.0f;
    static constexpr float kScaleStep = 0.1f;

    /// What a key press meant.
    enum class KeyResult { Updated, Confirm, Cancel, Unhandled };

    ModalTransform(TransformKind kind, SceneDocument start, std::vector<ObjectId> ids,
                   const QPointF& cursor);

    /// X/Y/Z lock (again: unlock; Shift+X/Y/Z: the plane normal to that axis), G/R/S
    /// switch, digits . - Backspace type a value, Enter confirms, Esc cancels.
    KeyResult keyPress(int key, const QString& text);
    /// Locks to `axis` (0/1/2; -1 free) or, with `plane`, to the plane normal to it: what a
    /// gizmo handle grabs.
    void lock(int axis, bool plane);
    /// The axes the locks use, as columns: identity for world space, the active object's
    /// rotation for local space.
    void setOrientation(const Mat3& axes) { axes_ = axes; }
    /// The cursor moved; `snap` while Ctrl is held.
    void setCursor(const QPointF& cursor, bool snap);
    void setSnap(bool snap) { snap_ = snap; }
    /// The start document with the gesture applied, as seen through `view`.
    SceneDocument result(const ViewProjection& view) const;
    /// A status line with what the gesture does so far, as seen through `view`: "Move X
    /// D 1.250 (1.250)", "Move D 0.500 0.000 -0.250 (0.559)", "Rotate Z 45.0°", "Scale 1.250".
    QString describe(const ViewProjection& view) const;

    TransformKind kind() const { return kind_; }
    const SceneDocument& start() const { return start_; }
    const std::vector<ObjectId>& ids() const { return ids_; }
    const QPointF& cursor() const { return cursor_; }

private:
    Vec3 axisVector() const;
    /// `v` with each component along axes_ rounded to `step`.
    Vec3 snappedInAxes(const Vec3& v, float step) const;
    bool typedValue(float& value) const;
    Vec3 moveDelta(const ViewProjection& view) const;
    float rotateDegrees(const ViewProjection& view, Vec3& axis) const;
    Vec3 scaleFactors(const ViewProjection& view) const;

    TransformKind kind_;
    SceneDocument start_;
    std::vector<ObjectId> ids_;
    Vec3 pivot_;
    QPointF startCursor_, cursor_;
    bool snap_ = false;
    int axis_ = -1;       ///< -1 free, else 0/1/2 for X/Y/Z.
    bool plane_ = false;  ///< Locked to the plane normal to axis_ instead of along it.
    Mat3 axes_{1.0f};
    QString typed_;
};

}  // namespace rs::ui
