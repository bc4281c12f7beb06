// TransformGizmo: every handle is laid out in widget pixels from the projection of the pivot
// and of points along the gizmo's axes, so it keeps its size on screen.
#include "viewport/transform_gizmo.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace rs::ui {

namespace {
constexpr double kArrowStartPx = 18.0;  ///< The centre is left free: a press there picks.
constexpr double kPlaneNearPx = 24.0, kPlaneFarPx = 40.0;
constexpr double kMinSquarePx = 1.5;    ///< A plane square narrower than this is not shown.
constexpr double kScaleBoxPx = 5.0;     ///< Half the scale box's side.
constexpr double kMinScaleBoxPx = 3.0;  ///< The same on the smallest gizmo.
constexpr double kHeadPx = 10.0;        ///< Length of an arrow head (half as wide).
constexpr double kGrabPx = 6.0;         ///< How near a line a press grabs it (at full size).
constexpr int kRingSegments = 64;
/// How far past the shapes' points the pens and antialiasing reach.
constexpr double kRingReachPx = 3.0, kLineReachPx = 3.0, kFillReachPx = 2.0;
constexpr double kCentrePx = 4.0;  ///< Radius of the circle drawn at the pivot.
/// An axis whose arrow is shorter than this share of its length points at the viewer.
/// (Shorter, little of it would reach past the free centre.)
constexpr double kMinForeshortening = 0.35;

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
    centre_ = *c;
    // Where each axis goes on screen per pixel of its length at the pivot (the projection's
    // derivative there): every handle is laid out from these, so a ring is an ellipse about
    // the pivot no wider than its radius times its axes' stretch.
    const float unit = 1.0f / pxPerUnit;  // World length of one widget pixel at the pivot.
    QPointF screen[3];
    for (int i = 0; i < 3; ++i) {
        const auto end = view.project(pivot + axes[i] * unit);
        if (!end) return;
        screen[i] = *end - centre_;
    }
    valid_ = true;
    // Whole inside the frame: near its edge the gizmo shrinks as a whole (its handles keep
    // their order, rings outside the scale boxes), down to kMinScale.
    const QRectF frame(view.imageRect());
    const double room = std::min({centre_.x() - frame.left(), frame.right() - centre_.x(),
                                  centre_.y() - frame.top(), frame.bottom() - centre_.y()}) -
                        kRingReachPx;
    double scale = std::clamp(room / kRingPx, kMinScale, 1.0);
    for (int round = 0; round < 6; ++round) {
        layOut(screen, scale);
        const QRectF b = bounds();
        const double overshoot = std::max({frame.left() - b.left(), b.right() - frame.right(),
                                           frame.top() - b.top(), b.bottom() - frame.bottom()});
        if (overshoot <= 0.0 || scale <= kMinScale) break;
        scale = std::max(kMinScale, scale - (overshoot + 0.5) / kRingPx);
    }
}

void TransformGizmo::layOut(const QPointF (&screen)[3], double scale) {
    scale_ = scale;
    arrowStartPx_ = kArrowStartPx * scale;
    boxHalfPx_ = std::max(kMinScaleBoxPx, kScaleBoxPx * scale);
    headPx_ = kHeadPx * std::max(scale, 0.4);
    const double arrowPx = kArrowPx * scale;
    for (int i = 0; i < 3; ++i) {
        Axis& a = axes_[i];
        a = Axis{};
        // Foreshortened as the axis is: an arrow towards the viewer is drawn shorter.
        const QPointF end = centre_ + screen[i] * arrowPx;
        if (distance(end, centre_) < arrowPx * kMinForeshortening) continue;
        a.shown = true;
        a.tip = end;
        a.scaleBox = centre_ + screen[i] * (kScalePx * scale);
    }
    const double nearPx = kPlaneNearPx * scale, farPx = kPlaneFarPx * scale;
    const double ringPx = kRingPx * scale;
    for (int i = 0; i < 3; ++i) {
        const QPointF u = screen[(i + 1) % 3], v = screen[(i + 2) % 3];
        Axis& a = axes_[i];
        // The square between the other two axes, in their plane.
        a.planeSquare << centre_ + u * nearPx + v * nearPx << centre_ + u * farPx + v * nearPx
                      << centre_ + u * farPx + v * farPx << centre_ + u * nearPx + v * farPx;
        // Seen edge-on, the square is a sliver nobody could aim at: narrower than
        // kMinSquarePx across either pair of sides.
        const double sides = std::max(distance(a.planeSquare[0], a.planeSquare[1]),
                                      distance(a.planeSquare[1], a.planeSquare[2]));
        if (area(a.planeSquare) < kMinSquarePx * std::max(sides, 1.0)) a.planeSquare.clear();
        for (int s = 0; s <= kRingSegments; ++s) {
            const double t = 2.0 * M_PI * double(s) / kRingSegments;
            a.ring.push_back(centre_ + (u * std::cos(t) + v * std::sin(t)) * ringPx);
        }
    }
}

std::optional<GizmoHandle> TransformGizmo::handleAt(const QPointF& p) const {
    if (!valid_) return std::nullopt;
    // Small handles first: each sits on or near a larger one. A scale box's margin comes
    // after the arrows: on a small gizmo it would cover a short arrow whole.
    const auto inBox = [&](int i, double margin) {
        return axes_[i].shown && std::abs(p.x() - axes_[i].scaleBox.x()) <= boxHalfPx_ + margin &&
               std::abs(p.y() - axes_[i].scaleBox.y()) <= boxHalfPx_ + margin;
    };
    for (int i = 0; i < 3; ++i)
        if (inBox(i, 0.5)) return GizmoHandle{TransformKind::Scale, i, false};
    for (int i = 0; i < 3; ++i)
        if (!axes_[i].planeSquare.isEmpty() &&
            axes_[i].planeSquare.containsPoint(p, Qt::OddEvenFill))
            return GizmoHandle{TransformKind::Move, i, true};
    int best = -1;
    // A smaller gizmo's handles lie closer together: each grabs less around it.
    const double reach = std::max(scale_, 0.5);
    double bestDist = kGrabPx * reach;
    for (int i = 0; i < 3; ++i) {
        if (!axes_[i].shown) continue;
        const double d =
            distanceToSegment(p, along(centre_, axes_[i].tip, arrowStartPx_), axes_[i].tip);
        if (d <= bestDist) best = i, bestDist = d;
    }
    if (best >= 0) return GizmoHandle{TransformKind::Move, best, false};
    for (int i = 0; i < 3; ++i)
        if (inBox(i, 2.0 * reach)) return GizmoHandle{TransformKind::Scale, i, false};
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
    // By coordinates: QRectF::united ignores a rectangle of no size, i.e. every point. Each
    // point with how far its pen, fill and antialiasing reach past it.
    double x0 = centre_.x(), y0 = centre_.y(), x1 = x0, y1 = y0;
    const auto add = [&](const QPointF& p, double reach) {
        x0 = std::min(x0, p.x() - reach), y0 = std::min(y0, p.y() - reach);
        x1 = std::max(x1, p.x() + reach), y1 = std::max(y1, p.y() + reach);
    };
    add(centre_, kCentrePx + kFillReachPx);
    for (const Axis& a : axes_) {
        if (a.shown) {
            add(a.tip, kLineReachPx);
            const QPointF dir = (a.tip - centre_) / std::max(1.0, distance(a.tip, centre_));
            const QPointF side(-dir.y(), dir.x());
            for (const QPointF& q :
                 {a.tip + dir * headPx_, a.tip + side * headPx_ / 2, a.tip - side * headPx_ / 2})
                add(q, kFillReachPx);
            add(a.scaleBox, boxHalfPx_ + kFillReachPx);
        }
        for (const QPointF& p : a.planeSquare) add(p, kFillReachPx);
        for (const QPointF& p : a.ring) add(p, kRingReachPx);
    }
    return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

bool TransformGizmo::shows(const GizmoHandle& h) const {
    if (!valid_ || h.axis < 0 || h.axis > 2) return false;
    const Axis& a = axes_[h.axis];
    if (h.kind == TransformKind::Rotate) return a.ring.size() >= 2;
    return h.plane ? !a.planeSquare.isEmpty() : a.shown;
}

std::optional<QPointF> TransformGizmo::grabPoint(const GizmoHandle& h) const {
    if (!valid_) return std::nullopt;
    const Axis& a = axes_[h.axis];
    switch (h.kind) {
        case TransformKind::Move:
            if (h.plane) {
                if (a.planeSquare.isEmpty()) return std::nullopt;
                // Its middle, or the point of it nearest the middle that grabs it (another
                // square may lie over part of it).
                const QPolygonF& q = a.planeSquare;
                std::optional<QPointF> best;
                double bestDist = 1e9;
                for (int i = 1; i < 8; ++i)
                    for (int j = 1; j < 8; ++j) {
                        const double u = i / 8.0, v = j / 8.0;
                        const QPointF at = (1 - u) * (1 - v) * q[0] + u * (1 - v) * q[1] +
                                           u * v * q[2] + (1 - u) * v * q[3];
                        const double d = std::hypot(u - 0.5, v - 0.5);
                        if (d < bestDist && handleAt(at) == std::optional<GizmoHandle>(h))
                            best = at, bestDist = d;
                    }
                return best;
            }
            if (!a.shown) return std::nullopt;
            // Three quarters of the way out, or the point nearest it along the arrow that
            // grabs it (a plane square or a scale box may lie over part of a short one).
            for (int k = 0; k <= 30; ++k) {
                const double t = 0.75 + ((k % 2) ? 0.05 : -0.05) * ((k + 1) / 2);
                const QPointF q = along(
                    centre_, a.tip, arrowStartPx_ + t * (distance(centre_, a.tip) - arrowStartPx_));
                if (t >= 0.0 && t <= 1.0 && handleAt(q) == std::optional<GizmoHandle>(h)) return q;
            }
            return std::nullopt;
        case TransformKind::Scale:
            if (!a.shown) return std::nullopt;
            return a.scaleBox;
        case TransformKind::Rotate: {
            // Of the ring's points that grab it (not another handle over it), the one
            // farthest from every scale box: along the screen's most open direction.
            std::optional<QPointF> best;
            double bestScore = -1.0;
            for (const QPointF& q : a.ring) {
                if (handleAt(q) != std::optional<GizmoHandle>(h)) continue;
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
        p.drawLine(along(centre_, a.tip, arrowStartPx_), a.tip);
        // The arrow head: a triangle at the tip, along the arrow.
        const QPointF dir = (a.tip - centre_) / std::max(1.0, distance(a.tip, centre_));
        const QPointF side(-dir.y(), dir.x());
        p.setPen(Qt::NoPen);
        p.setBrush(arrow);
        p.drawPolygon(QPolygonF(
            {a.tip + dir * headPx_, a.tip + side * headPx_ / 2, a.tip - side * headPx_ / 2}));
        const QColor box = colour({TransformKind::Scale, i, false});
        p.setPen(QPen(box.darker(150), 1.0));
        p.setBrush(box);
        p.drawRect(QRectF(a.scaleBox - QPointF(boxHalfPx_, boxHalfPx_),
                          QSizeF(2 * boxHalfPx_, 2 * boxHalfPx_)));
    }
    p.setPen(QPen(QColor(240, 240, 240), 1.5));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(centre_, kCentrePx, kCentrePx);
    p.restore();
}

}  // namespace rs::ui
