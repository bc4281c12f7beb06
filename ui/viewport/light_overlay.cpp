// Light glyphs: lights are not geometry in a Whitted render, so the viewport draws and picks
// them itself, in front of whatever surface lies behind.
#include "viewport/light_overlay.h"

#include <QPainter>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "display/display_frame.h"
#include "viewport/passepartout.h"

namespace rs::ui {

namespace {
constexpr float kPointGlyphPx = 6.0f;
/// Small glyphs are easier to hit with a margin.
constexpr float kMinPickPx = 9.0f;
/// A sun's arrows: their length and spacing on screen, whatever the distance.
constexpr float kSunArrowPx = 56.0f;
constexpr float kSunSpacingPx = 14.0f;
constexpr double kArrowHeadPx = 8.0;
constexpr int kCircleSegments = 40;

/// Two unit vectors orthogonal to unit `a` and to each other.
std::pair<Vec3, Vec3> basisAround(const Vec3& a) {
    const Vec3 helper = std::abs(a.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    const Vec3 u = glm::normalize(glm::cross(a, helper));
    return {u, glm::cross(a, u)};
}

/// The segment between two world points, when both are in front of the view.
void addLine(LightGlyph& g, const ViewProjection& view, const Vec3& a, const Vec3& b) {
    const auto pa = view.project(a), pb = view.project(b);
    if (pa && pb) g.lines.emplace_back(*pa, *pb);
}

/// An arrow head at `tip` of the screen segment from `from`: two short strokes back.
void addHead(LightGlyph& g, const QPointF& from, const QPointF& tip) {
    const QLineF shaft(tip, from);
    if (shaft.length() < kArrowHeadPx) return;
    for (double turn : {25.0, -25.0}) {
        QLineF stroke = shaft;
        stroke.setLength(kArrowHeadPx);
        stroke.setAngle(shaft.angle() + turn);
        g.lines.push_back(stroke);
    }
}

void addSpot(LightGlyph& g, const Light& l, const ViewProjection& view) {
    const Vec3 axis = l.target - l.position;
    const float d = glm::length(axis);
    if (d <= 1e-6f) return;
    const Vec3 a = axis / d;
    const auto [u, v] = basisAround(a);
    addLine(g, view, l.position, l.target);
    for (float degrees : {l.coneRadius, l.coneFalloff}) {
        const float r = d * std::tan(glm::radians(std::clamp(degrees, 0.0f, 89.0f)));
        QPolygonF loop;
        for (int i = 0; i < kCircleSegments; ++i) {
            const float t = 2.0f * std::numbers::pi_v<float> * float(i) / kCircleSegments;
            const auto p = view.project(l.target + r * (std::cos(t) * u + std::sin(t) * v));
            if (!p) {
                loop.clear();
                break;
            }
            loop << *p;
        }
        if (!loop.isEmpty()) g.loops.push_back(loop);
        if (degrees == l.coneFalloff)  // Rays along the cone's outer edge.
            for (const Vec3& side : {u, -u, v, -v})
                addLine(g, view, l.position, l.target + r * side);
    }
}

void addSun(LightGlyph& g, const Light& l, const ViewProjection& view) {
    const float len = glm::length(l.direction);
    const float pxPerUnit = view.projectedLength(l.position, 1.0f);
    if (len <= 1e-6f || pxPerUnit <= 0.0f) return;
    const Vec3 dir = l.direction / len;
    const auto [u, v] = basisAround(dir);
    const float unit = 1.0f / pxPerUnit;  // World length of one widget pixel at the anchor.
    for (float side : {-1.0f, 0.0f, 1.0f}) {
        const Vec3 from = l.position + u * (side * kSunSpacingPx * unit);
        const Vec3 to = from + dir * (kSunArrowPx * unit);
        const auto pa = view.project(from), pb = view.project(to);
        if (!pa || !pb) continue;
        g.lines.emplace_back(*pa, *pb);
        addHead(g, *pa, *pb);
    }
}
}  // namespace

std::vector<LightGlyph> lightGlyphs(const SceneDocument& doc, const ViewProjection& view) {
    std::vector<LightGlyph> glyphs;
    if (!view.valid()) return glyphs;
    for (const Light& l : doc.lights) {
        const auto at = view.project(l.position);
        if (!at) continue;
        LightGlyph g;
        g.id = l.id;
        g.centre = *at;
        g.radius = l.type == LightType::Sphere
                       ? std::max(kPointGlyphPx * 0.5f, view.projectedLength(l.position, l.radius))
                       : kPointGlyphPx;
        const Color c = glm::clamp(l.color, Color(0.0f), Color(1.0f));
        g.color = QColor::fromRgbF(c.x, c.y, c.z);
        if (l.type == LightType::Spot) addSpot(g, l, view);
        if (l.type == LightType::Directional) addSun(g, l, view);
        glyphs.push_back(g);
    }
    return glyphs;
}

ObjectId pickLight(const std::vector<LightGlyph>& glyphs, const QPointF& p) {
    ObjectId best = kNoObject;
    double bestDist = 0.0;
    for (const LightGlyph& g : glyphs) {
        const double d = std::hypot(p.x() - g.centre.x(), p.y() - g.centre.y());
        if (d <= std::max(g.radius, kMinPickPx) && (best == kNoObject || d < bestDist))
            best = g.id, bestDist = d;
    }
    return best;
}

QRegion glyphRegion(const LightGlyph& g, int margin) {
    const int extent = int(std::ceil(std::max(double(g.radius), double(kPointGlyphPx)))) + margin;
    QRegion r(QRect(g.centre.toPoint() - QPoint(extent, extent), QSize(2 * extent, 2 * extent)));
    // A diagonal line's bounding box is generous, but a glyph has only a few of them.
    for (const QLineF& line : g.lines)
        r += QRectF(line.p1(), line.p2())
                 .normalized()
                 .toAlignedRect()
                 .adjusted(-margin, -margin, margin, margin);
    for (const QPolygonF& loop : g.loops)
        r += loop.boundingRect().toAlignedRect().adjusted(-margin, -margin, margin, margin);
    return r;
}

void paintLightGlyphs(QPainter& p, const std::vector<LightGlyph>& glyphs,
                      const std::vector<ObjectId>& selected) {
    p.setRenderHint(QPainter::Antialiasing);
    const QColor highlight(kOutlineRgb[0], kOutlineRgb[1], kOutlineRgb[2]);
    for (const LightGlyph& g : glyphs) {
        const bool chosen = std::find(selected.begin(), selected.end(), g.id) != selected.end();
        const double r = g.radius;
        if (!g.lines.empty() || !g.loops.empty()) {
            // Direction and cone: thin, so the surfaces behind stay readable.
            p.setBrush(Qt::NoBrush);
            p.setPen(QPen(chosen ? highlight : g.color, chosen ? 2.0 : 1.2));
            for (const QLineF& line : g.lines) p.drawLine(line);
            p.setPen(QPen(chosen ? highlight : g.color, chosen ? 1.6 : 1.0, Qt::DashLine));
            for (const QPolygonF& loop : g.loops) p.drawPolygon(loop);
        }
        if (r > kPointGlyphPx) {
            // A sphere light: its outline, so the surfaces it lights stay visible through it.
            p.setBrush(Qt::NoBrush);
            p.setPen(QPen(chosen ? highlight : g.color, chosen ? 2.5 : 1.5, Qt::DashLine));
            p.drawEllipse(g.centre, r, r);
        }
        const double dot = std::min(r, double(kPointGlyphPx));
        p.setPen(QPen(chosen ? highlight : QColor(20, 20, 20), chosen ? 2.5 : 1.0));
        p.setBrush(g.color);
        p.drawEllipse(g.centre, dot, dot);
    }
}

}  // namespace rs::ui
