// Lights in the viewport: glyphs drawn with QPainter over the frame, and picking them.
#pragma once

#include <QColor>
#include <QLineF>
#include <QPointF>
#include <QPolygonF>
#include <QRegion>
#include <vector>

#include "scene/document.h"
#include "viewport/view_projection.h"

class QPainter;

namespace rs::ui {

/// Where a light is drawn: a small disc for a point light, its projected sphere for a sphere
/// light; a spot adds the line to its target and its cone (rays along the falloff edge, circles
/// at the radius and falloff angles at the target's distance); a sun (no position) adds
/// parallel arrows along its direction from its anchor (Light::position).
struct LightGlyph {
    ObjectId id = kNoObject;
    QPointF centre;
    float radius = 0.0f;  ///< Widget pixels.
    QColor color;
    std::vector<QLineF> lines;     ///< Widget coordinates: axis, cone rays, arrows.
    std::vector<QPolygonF> loops;  ///< Widget coordinates, closed: the cone's circles.
};

/// Glyphs of the document's lights in front of the view camera.
std::vector<LightGlyph> lightGlyphs(const SceneDocument& doc, const ViewProjection& view);
/// The light whose glyph is under widget point `p` (the nearest centre wins), or kNoObject.
ObjectId pickLight(const std::vector<LightGlyph>& glyphs, const QPointF& p);

/// Widget pixels glyph `g` paints on (its disc, lines and circles), `margin` pixels wider:
/// what must be repainted when it appears, moves or goes.
QRegion glyphRegion(const LightGlyph& g, int margin);

/// Draws `glyphs` (those of `selected` highlighted) with `p`, in widget coordinates.
void paintLightGlyphs(QPainter& p, const std::vector<LightGlyph>& glyphs,
                      const std::vector<ObjectId>& selected);

}  // namespace rs::ui
