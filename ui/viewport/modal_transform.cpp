// ModalTransform: maps cursor, keys and typed numbers to a move, rotation or scale of the
// selection. Typed values win over the cursor, as in Blender.
#include "viewport/modal_transform.h"

#include <Qt>
#include <cmath>

#include "document/transform_edits.h"

namespace rs::ui {

namespace {

/// The point of line (a + s * axis) closest to the ray (o + t * d).
Vec3 closestOnAxis(const Vec3& a, const Vec3& axis, const Ray& ray) {
    const Vec3 w = a - ray.origin;
    const float b = glm::dot(axis, ray.dir), dd = glm::dot(ray.dir, ray.dir);
    const float aa = glm::dot(axis, axis);
    const float denom = aa * dd - b * b;
    if (std::abs(denom) < 1e-8f) return a;
    const float s = (b * glm::dot(ray.dir, w) - dd * glm::dot(axis, w)) / denom;
    return a + axis * s;
}

/// Where the ray meets the plane through `p` facing the view.
Vec3 onViewPlane(const Vec3& p, const Vec3& forward, const Ray& ray) {
    const float denom = glm::dot(ray.dir, forward);
    if (std::abs(denom) < 1e-6f) return p;
    return ray.at(glm::dot(p - ray.origin, forward) / denom);
}

float snapped(float v, float step) {
    return std::round(v / step) * step;
}

const char* const kAxisNames[] = {"X", "Y", "Z"};

}  // namespace

ModalTransform::ModalTransform(TransformKind kind, SceneDocument start, std::vector<ObjectId> ids,
                               const QPointF& cursor)
    : kind_(kind),
      start_(std::move(start)),
      ids_(std::move(ids)),
      startCursor_(cursor),
      cursor_(cursor) {
    pivot_ = pivotOf(start_, ids_);
}

ModalTransform::KeyResult ModalTransform::keyPress(int key, const QString& text) {
    switch (key) {
        case Qt::Key_Return:
        case Qt::Key_Enter:
            return KeyResult::Confirm;
        case Qt::Key_Escape:
            return KeyResult::Cancel;
        case Qt::Key_X:
        case Qt::Key_Y:
        case Qt::Key_Z: {
            // Shift+X gives an upper-case "X": the plane normal to X, as in Blender.
            const bool plane = text.size() == 1 && text[0].isUpper();
            const int axis = key - Qt::Key_X;
            if (axis_ == axis && plane_ == plane)
                lock(-1, false);
            else
                lock(axis, plane);
            return KeyResult::Updated;
        }
        case Qt::Key_G:
        case Qt::Key_R:
        case Qt::Key_S:
            kind_ = key == Qt::Key_G   ? TransformKind::Move
                    : key == Qt::Key_R ? TransformKind::Rotate
                                       : TransformKind::Scale;
            typed_.clear();
            return KeyResult::Updated;
        case Qt::Key_Backspace:
            typed_.chop(1);
            return KeyResult::Updated;
        case Qt::Key_Minus:
            // Blender's minus negates whatever has been typed, wherever the caret is.
            typed_ =
                typed_.startsWith(QLatin1Char('-')) ? typed_.mid(1) : QLatin1Char('-') + typed_;
            return KeyResult::Updated;
        default:
            break;
    }
    if (text.size() == 1 && (text[0].isDigit() || text[0] == QLatin1Char('.'))) {
        typed_ += text;
        return KeyResult::Updated;
    }
    return KeyResult::Unhandled;
}

void ModalTransform::lock(int axis, bool plane) {
    axis_ = axis;
    plane_ = axis >= 0 && plane;
}

void ModalTransform::setCursor(const QPointF& cursor, bool snap) {
    cursor_ = cursor;
    snap_ = snap;
}

Vec3 ModalTransform::axisVector() const {
    return axes_[axis_ < 0 ? 0 : axis_];
}

Vec3 ModalTransform::snappedInAxes(const Vec3& v, float step) const {
    Vec3 out(0.0f);
    for (int i = 0; i < 3; ++i) out += axes_[i] * snapped(glm::dot(v, axes_[i]), step);
    return out;
}

bool ModalTransform::typedValue(float& value) const {
    QString t = typed_;
    if (t.isEmpty() || t == QLatin1String("-")) return false;
    if (t == QLatin1String(".") || t == QLatin1String("-.")) t += QLatin1Char('0');
    bool ok = false;
    value = t.toFloat(&ok);
    return ok;
}

Vec3 ModalTransform::moveDelta(const ViewProjection& view) const {
    float typed = 0.0f;
    // A typed distance without an axis goes along X, as Blender's does; in a locked plane,
    // along the plane's first axis.
    if (typedValue(typed)) return (plane_ ? axes_[(axis_ + 1) % 3] : axisVector()) * typed;
    const Ray from = view.rayThrough(startCursor_), to = view.rayThrough(cursor_);
    Vec3 delta;
    if (axis_ >= 0 && !plane_) {
        const Vec3 axis = axisVector();
        float along =
            glm::dot(closestOnAxis(pivot_, axis, to) - closestOnAxis(pivot_, axis, from), axis);
        if (snap_) along = snapped(along, kGridStep);
        return axis * along;
    }
    // The view plane, or the locked plane (its normal is the locked axis).
    const Vec3 n = plane_ ? axisVector() : view.camera().forward();
    delta = onViewPlane(pivot_, n, to) - onViewPlane(pivot_, n, from);
    if (plane_) delta -= n * glm::dot(delta, n);
    return snap_ ? snappedInAxes(delta, kGridStep) : delta;
}

float ModalTransform::rotateDegrees(const ViewProjection& view, Vec3& axis) const {
    const Vec3 toViewer = -view.camera().forward();
    axis = axis_ >= 0 ? axisVector() : toViewer;
    float typed = 0.0f;
    if (typedValue(typed)) return typed;
    // Turning the cursor anticlockwise about the pivot turns the selection anticlockwise as
    // seen from here, whichever way the locked axis points.
    if (glm::dot(axis, toViewer) < 0.0f) axis = -axis;
    const QPointF c = view.project(pivot_).value_or(QPointF(0, 0));
    const QPointF a = startCursor_ - c, b = cursor_ - c;
    if (std::hypot(a.x(), a.y()) < 1.0 || std::hypot(b.x(), b.y()) < 1.0) return 0.0f;
    // Widget y grows down, so the screen angle's sign is flipped.
    float deg = -float(glm::degrees(std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x())));
    deg = std::remainder(deg, 360.0f);
    return snap_ ? snapped(deg, kAngleStepDeg) : deg;
}

Vec3 ModalTransform::scaleFactors(const ViewProjection& view) const {
    float f = 1.0f;
    if (!typedValue(f)) {
        const QPointF c = view.project(pivot_).value_or(QPointF(0, 0));
        const double from = std::hypot(startCursor_.x() - c.x(), startCursor_.y() - c.y());
        const double to = std::hypot(cursor_.x() - c.x(), cursor_.y() - c.y());
        f = from < 1.0 ? 1.0f : float(to / from);
        if (snap_) f = snapped(f, kScaleStep);
    }
    if (axis_ < 0) return Vec3(f);
    // Along the axis, or across the plane normal to it.
    Vec3 factors(plane_ ? f : 1.0f);
    factors[axis_] = plane_ ? 1.0f : f;
    return factors;
}

SceneDocument ModalTransform::result(const ViewProjection& view) const {
    SceneDocument doc = start_;
    switch (kind_) {
        case TransformKind::Move:
            translateAll(doc, ids_, moveDelta(view));
            break;
        case TransformKind::Rotate: {
            Vec3 axis;
            const float deg = rotateDegrees(view, axis);
            if (deg != 0.0f) rotateAll(doc, ids_, pivot_, axis, deg);
            break;
        }
        case TransformKind::Scale: {
            const Vec3 f = scaleFactors(view);
            if (f != Vec3(1.0f)) scaleAll(doc, ids_, pivot_, f, axes_);
            break;
        }
    }
    return doc;
}

QString ModalTransform::describe(const ViewProjection& view) const {
    static const char* const kinds[] = {"Move", "Rotate", "Scale"};
    QString s = QString::fromLatin1(kinds[int(kind_)]);
    if (axis_ >= 0 && plane_)
        s += QStringLiteral(" plane ") + QLatin1String(kAxisNames[(axis_ + 1) % 3]) +
             QLatin1String(kAxisNames[(axis_ + 2) % 3]);
    else if (axis_ >= 0)
        s += QLatin1Char(' ') + QLatin1String(kAxisNames[axis_]);
    if (!typed_.isEmpty()) s += QLatin1Char(' ') + typed_;
    // What the gesture does so far, as Blender's header shows it.
    const auto number = [](float v, int decimals) { return QString::number(v, 'f', decimals); };
    switch (kind_) {
        case TransformKind::Move: {
            const Vec3 d = moveDelta(view);
            s +=
                QStringLiteral("   D %1 %2 %3 (%4)")
                    .arg(number(d.x, 3), number(d.y, 3), number(d.z, 3), number(glm::length(d), 3));
            break;
        }
        case TransformKind::Rotate: {
            Vec3 axis;
            s += QStringLiteral("   %1°").arg(number(rotateDegrees(view, axis), 1));
            break;
        }
        case TransformKind::Scale: {
            const Vec3 f = scaleFactors(view);
            s += f.x == f.y && f.y == f.z
                     ? QStringLiteral("   %1").arg(number(f.x, 3))
                     : QStringLiteral("   %1 %2 %3")
                           .arg(number(f.x, 3), number(f.y, 3), number(f.z, 3));
            break;
        }
    }
    // A sun light is everywhere at once: moving it moves only where its glyph is drawn.
    if (kind_ != TransformKind::Rotate)
        for (ObjectId id : ids_)
            if (const Light* l = start_.findLight(id); l && l->type == LightType::Directional) {
                s += QStringLiteral(
                    "   (a sun light has no position: only its glyph moves; "
                    "R turns its direction)");
                break;
            }
    return s + QStringLiteral(
                   "   (X Y Z lock, type a value, Ctrl snaps, Enter/click confirms, Esc cancels)");
}

}  // namespace rs::ui
