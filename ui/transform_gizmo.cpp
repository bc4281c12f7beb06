// TransformGizmo: every handle is laid out in widget pixels from the projection of the pivot
// and of points along the gizmo's axes, so it keeps its size on screen.
#include "transform_gizmo.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace rs::ui {

namespace {
constexpr double kArrowStartPx = 18.0;  ///< The centre is left free: a press there picks.
constexpr double kPlaneNearPx = 24.0, kPlaneFarPx = 40.0;
constexpr double kScaleBoxPx = 5.0;  ///< Half the scale box's side.
constexpr double kGrabPx = 6.0;      ///< How near a line a press grabs it.
constexpr int kRingSegments = 64;
constexpr double kRingMarginPx = 4.0;  ///< Kept between a ring and the frame's edge.
/// An axis whose arrow is shorter than this share of its length points at the viewer.
constexpr double kMinForeshortening = 0.15;

const QColor kAxisColors[3] = {QColor(225, 60, 60), QColor(110, 200, 50), QColor(60, 120, 235)};
const QColor kActiveColor(255, 220, 70);

double distance(const QPointF& a, const QPointF& b) {
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

/// Distance from `p` to segment a-b.
double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b) {
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return distance(p, a + t * ab);
}

/// Area of a simple polygon (shoelace).
double area(const QPolygonF& q) {
    double twice = 0.0;
    for (int i = 0; i < q.size(); ++i) {
        const QPointF& a = q[i];
        const QPointF& b = q[(i + 1) % q.size()];
        twice += a.x() * b.y() - b.x() * a.y();
    }
    return std::abs(twice) / 2.0;
}

QPointF along(const QPointF& from, const QPointF& to, double px) {
    const double len = distance(from, to);
    return len > 0.0 ? from + (to - from) * (px / len) : from;
}
}  // namespace

Mat3 gizmoAxes(const SceneDocument& doc, ObjectId active, bool local) {
    // A spot or a sun shines along its local -Z, as Blender's do: its own X and Y lie across
    // the beam, so a local rotation tilts it.
    if (const Light* l = local ? doc.findLight(active) : nullptr) {
        const Vec3 beam = l->type == LightType::Spot          ? l->target - l->position
                          : l->type == LightType::Directional ? l->direction
                                                              : Vec3(0.0f);
        const float len = glm::length(beam);
        if (len <= 1e-6f) return Mat3(1.0f);
        const Vec3 z = -beam / len;
        const Vec3 helper = std::abs(z.y) < 0.99f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
        const Vec3 x = glm::normalize(glm::cross(helper, z));
        return Mat3(x, glm::cross(z, x), z);
    }
    const Object* o = local ? doc.findObject(active) : nullptr;
    if (!o || std::holds_alternative<PlaneGeometry>(o->geometry)) return Mat3(1.0f);
    // The rotation of T * R * S: the matrix's columns with their scale divided out.
    const Mat3 m(o->transform.matrix());
    Mat3 axes;
    for (int i = 0; i < 3; ++i) {
        const float len = glm::length(m[i]);
        axes[i] = len > 1e-8f ? m[i] / len : Vec3(0.0f);
        if (len <= 1e-8f) axes[i][i] = 1.0f;
    }
    return axes;
}

TransformGizmo::TransformGizmo(const ViewProjection& view, const Vec3& pivot, const Mat3& axes) {
    const auto c = view.project(pivot);
    const float pxPerUnit = view.projectedLength(pivot, 1.0f);
    if (!c || pxPerUnit <= 0.0f) return;
    valid_ = true;
    centre_ = *c;
    const float unit = 1.0f / pxPerUnit;  // World length of one widget pixel at the pivot.
    // The rings stay inside the frame while the pivot is well inside it (near an edge they
    // shrink, down to just outside the scale boxes).
    const QRectF frame(view.imageRect());
    const double room = std::min({centre_.x() - frame.left(), frame.right() - centre_.x(),
                                  centre_.y() - frame.top(), frame.bottom() - centre_.y()}) -
                        kRingMarginPx;
    const double ringPx = std::clamp(room, kScalePx + 2.0 * kScaleBoxPx, kRingPx);
    for (int i = 0; i < 3; ++i) {
        Axis& a = axes_[i];
        const auto end = view.project(pivot + axes[i] * float(kArrowPx) * unit);
        if (!end || distance(*end, centre_) < kArrowPx * kMinForeshortening) continue;
        a.shown = true;
        // Foreshortened as the axis is: an arrow towards the viewer is drawn shorter.
        const double len = distance(*end, centre_);
        a.tip = *end;
        a.scaleBox = along(centre_, *end, len * kScalePx / kArrowPx);
    }
    for (int i = 0; i < 3; ++i) {
        const Vec3 u = axes[(i + 1) % 3], v = axes[(i + 2) % 3];
        Axis& a = axes_[i];
        // The square between the other two axes, in their plane.
        const Vec3 corners[4] = {u * float(kPlaneNearPx) + v * float(kPlaneNearPx),
                                 u * float(kPlaneFarPx) + v * float(kPlaneNearPx),
                                 u * float(kPlaneFarPx) + v * float(kPlaneFarPx),
                                 u * float(kPlaneNearPx) + v * float(kPlaneFarPx)};
        for (const Vec3& k : corners)
            if (const auto q = view.project(pivot + k * unit)) a.planeSquare << *q;
        // Seen edge-on, the square is a sliver nobody could aim at.
        if (a.planeSquare.size() != 4 || area(a.planeSquare) < 16.0) a.planeSquare.clear();
    }
    // Rings of `radius` pixels at the pivot; a ring towards the viewer projects a little wider,
    // so what reaches past the frame shrinks them once more.
    const auto makeRings = [&](double radius) {
        double overshoot = 0.0;
        for (int i = 0; i < 3; ++i) {
            const Vec3 u = axes[(i + 1) % 3], v = axes[(i + 2) % 3];
            Axis& a = axes_[i];
            a.ring.clear();
            for (int s = 0; s <= kRingSegments; ++s) {
                const float t = 2.0f * float(M_PI) * float(s) / kRingSegments;
                const Vec3 p = pivot + (u * std::cos(t) + v * std::sin(t)) * float(radius) * unit;
                const auto q = view.project(p);
                if (!q) continue;
                a.ring.push_back(*q);
                overshoot = std::max({overshoot, frame.left() + kRingMarginPx - q->x(),
                                      q->x() - frame.right() + kRingMarginPx,
                                      frame.top() + kRingMarginPx - q->y(),
                                      q->y() - frame.bottom() + kRingMarginPx});
            }
        }
        return overshoot;
    };
    double radius = ringPx;
    for (int round = 0; round < 3; ++round) {
        const double overshoot = makeRings(radius);
        const double smaller = std::max(kScalePx + 2.0 * kScaleBoxPx, radius - overshoot - 1.0);
        if (overshoot <= 0.0 || smaller >= radius) break;
        radius = smaller;
    }
}

std::optional<GizmoHandle> TransformGizmo::handleAt(const QPointF& p) const {
    if (!valid_) return std::nullopt;
    // Small handles first: each sits on or near a larger one.
    for (int i = 0; i < 3; ++i)
        if (axes_[i].shown && std::abs(p.x() - axes_[i].scaleBox.x()) <= kScaleBoxPx + 2 &&
            std::abs(p.y() - axes_[i].scaleBox.y()) <= kScaleBoxPx + 2)
            return GizmoHandle{TransformKind::Scale, i, false};
    for (int i = 0; i < 3; ++i)
        if (!axes_[i].planeSquare.isEmpty() &&
            axes_[i].planeSquare.containsPoint(p, Qt::OddEvenFill))
            return GizmoHandle{TransformKind::Move, i, true};
    int best = -1;
    double bestDist = kGrabPx;
    for (int i = 0; i < 3; ++i) {
        if (!axes_[i].shown) continue;
        const double d =
            distanceToSegment(p, along(centre_, axes_[i].tip, kArrowStartPx), axes_[i].tip);
        if (d <= bestDist) best = i, bestDist = d;
    }
    if (best >= 0) return GizmoHandle{TransformKind::Move, best, false};
    for (int i = 0; i < 3; ++i) {
        const auto& r = axes_[i].ring;
        for (std::size_t s = 1; s < r.size(); ++s) {
            const double d = distanceToSegment(p, r[s - 1], r[s]);
            if (d <= bestDist) best = i, bestDist = d;
        }
    }
    if (best >= 0) return GizmoHandle{TransformKind::Rotate, best, false};
    return std::nullopt;
}

QRectF TransformGizmo::bounds() const {
    if (!valid_) return {};
    // By coordinates: QRectF::united ignores a rectangle of no size, i.e. every point.
    double x0 = centre_.x(), y0 = centre_.y(), x1 = x0, y1 = y0;
    const auto add = [&](const QPointF& p) {
        x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
        x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
    };
    for (const Axis& a : axes_) {
        if (a.shown) add(a.tip), add(a.scaleBox);
        for (const QPointF& p : a.planeSquare) add(p);
        for (const QPointF& p : a.ring) add(p);
    }
    // Scale boxes, arrow heads and pens reach past the points above.
    constexpr double kReach = 12.0;
    return QRectF(QPointF(x0, y0), QPointF(x1, y1)).adjusted(-kReach, -kReach, kReach, kReach);
}

std::optional<QPointF> TransformGizmo::grabPoint(const GizmoHandle& h) const {
    if (!valid_) return std::nullopt;
    const Axis& a = axes_[h.axis];
    switch (h.kind) {
        case TransformKind::Move:
            if (h.plane) {
                if (a.planeSquare.isEmpty()) return std::nullopt;
                return a.planeSquare.boundingRect().center();
            }
            if (!a.shown) return std::nullopt;
            return along(centre_, a.tip, 0.75 * distance(centre_, a.tip));
        case TransformKind::Scale:
            if (!a.shown) return std::nullopt;
            return a.scaleBox;
        case TransformKind::Rotate: {
            // The ring's point farthest from the other axes' handles: along the screen's
            // most open direction, i.e. the ring point farthest from every arrow tip.
            std::optional<QPointF> best;
            double bestScore = -1.0;
            for (const QPointF& q : a.ring) {
                double score = 1e9;
                for (const Axis& other : axes_)
                    if (other.shown) score = std::min(score, distance(q, other.scaleBox));
                if (score > bestScore) best = q, bestScore = score;
            }
            return best;
        }
    }
    return std::nullopt;
}

void TransformGizmo::paint(QPainter& p, const std::optional<GizmoHandle>& active) const {
    if (!valid_) return;
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    const auto colour = [&](const GizmoHandle& h) {
        return active && *active == h ? kActiveColor : kAxisColors[h.axis];
    };
    // Rings behind the arrows, thin so the image stays readable.
    for (int i = 0; i < 3; ++i) {
        const auto& r = axes_[i].ring;
        if (r.size() < 2) continue;
        p.setPen(QPen(colour({TransformKind::Rotate, i, false}), 2.0));
        p.setBrush(Qt::NoBrush);
        p.drawPolyline(r.data(), int(r.size()));
    }
    for (int i = 0; i < 3; ++i) {
        const Axis& a = axes_[i];
        if (!a.planeSquare.isEmpty()) {
            QColor fill = colour({TransformKind::Move, i, true});
            fill.setAlpha(110);
            p.setPen(QPen(fill.darker(130), 1.0));
            p.setBrush(fill);
            p.drawPolygon(a.planeSquare);
        }
        if (!a.shown) continue;
        const QColor arrow = colour({TransformKind::Move, i, false});
        p.setPen(QPen(arrow, 3.0, Qt::SolidLine, Qt::RoundCap));
        p.drawLine(along(centre_, a.tip, kArrowStartPx), a.tip);
        // The arrow head: a triangle at the tip, along the arrow.
        const QPointF dir = (a.tip - centre_) / std::max(1.0, distance(a.tip, centre_));
        const QPointF side(-dir.y(), dir.x());
        p.setPen(Qt::NoPen);
        p.setBrush(arrow);
        p.drawPolygon(QPolygonF({a.tip + dir * 10.0, a.tip + side * 5.0, a.tip - side * 5.0}));
        const QColor box = colour({TransformKind::Scale, i, false});
        p.setPen(QPen(box.darker(150), 1.0));
        p.setBrush(box);
        p.drawRect(QRectF(a.scaleBox - QPointF(kScaleBoxPx, kScaleBoxPx),
                          QSizeF(2 * kScaleBoxPx, 2 * kScaleBoxPx)));
    }
    p.setPen(QPen(QColor(240, 240, 240), 1.5));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(centre_, 4.0, 4.0);
    p.restore();
}

}  // namespace rs::ui
