// Lights in the viewport: glyphs drawn with QPainter over the frame, and picking them.
#pragma once

#include "scene/document.h"
#include "view_projection.h"

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QWidget>

#include <vector>

class QPainter;

namespace rs::ui {

/// Where a light is drawn: a small disc for a point light, its projected sphere otherwise.
struct LightGlyph {
    ObjectId id = kNoObject;
    QPointF centre;
    float radius = 0.0f;  ///< Widget pixels.
    QColor color;
};

/// Glyphs of the document's lights in front of the view camera.
std::vector<LightGlyph> lightGlyphs(const SceneDocument& doc, const ViewProjection& view);
/// The light whose glyph is under widget point `p` (the nearest centre wins), or kNoObject.
ObjectId pickLight(const std::vector<LightGlyph>& glyphs, const QPointF& p);

/// Draws `glyphs` (the one of `selected` highlighted) with `p`, in widget coordinates.
void paintLightGlyphs(QPainter& p, const std::vector<LightGlyph>& glyphs, ObjectId selected);

/// Transparent widget over the frame view that draws the glyphs (and the passepartout); mouse
/// events pass through.
class LightOverlay : public QWidget {
    Q_OBJECT
public:
    explicit LightOverlay(QWidget* parent = nullptr);
    /// Shows `glyphs`, the one of `selected` highlighted.
    void setGlyphs(std::vector<LightGlyph> glyphs, ObjectId selected);
    const std::vector<LightGlyph>& glyphs() const { return glyphs_; }
    ObjectId selected() const { return selected_; }
    /// Dims what lies outside `outputFrame` (empty: nothing), under the glyphs.
    void setPassepartout(const QRectF& outputFrame);
    const QRectF& passepartout() const { return passepartout_; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::vector<LightGlyph> glyphs_;
    ObjectId selected_ = kNoObject;
    QRectF passepartout_;
};

}  // namespace rs::ui
