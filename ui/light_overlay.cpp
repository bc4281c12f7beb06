// Light glyphs: lights are not geometry in a Whitted render, so the viewport draws and picks
// them itself, in front of whatever surface lies behind.
#include "light_overlay.h"

#include <QPainter>
#include <algorithm>
#include <cmath>

#include "display_frame.h"
#include "passepartout.h"

namespace rs::ui {

namespace {
constexpr float kPointGlyphPx = 6.0f;
/// Small glyphs are easier to hit with a margin.
constexpr float kMinPickPx = 9.0f;
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

void paintLightGlyphs(QPainter& p, const std::vector<LightGlyph>& glyphs,
                      const std::vector<ObjectId>& selected) {
    p.setRenderHint(QPainter::Antialiasing);
    const QColor highlight(kOutlineRgb[0], kOutlineRgb[1], kOutlineRgb[2]);
    for (const LightGlyph& g : glyphs) {
        const bool chosen = std::find(selected.begin(), selected.end(), g.id) != selected.end();
        const double r = g.radius;
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
