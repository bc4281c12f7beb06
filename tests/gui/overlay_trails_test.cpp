// The raster view's overlay (gizmo, light glyphs) leaves no strokes behind: after selecting,
// dragging while passes run, undoing, deselecting, hiding the gizmo and reopening the file,
// what the window shows (its backing store) is the frame shaded afresh, outside the glyphs.
#include <QScreen>
#include <QtTest>
#include <cmath>

#include "adapter/frame_handover.h"
#include "display/raster_frame_view.h"
#include "document/scene_edits.h"
#include "gui_test_support.h"
#include "image/tonemap.h"
#include "viewport/viewport_overlay.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class OverlayTrailsTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();
    void selectDragUndoDeselectHideReopen_LeaveNoOverlayPixels();

private:
    /// Frame pixels on screen that differ from the final frame shaded with `selected`
    /// outlined, away from what the overlay draws now; -1 when too few pixels could be
    /// compared.
    int stalePixels(const std::vector<ObjectId>& selected);

    std::unique_ptr<MainWindow> window_;
};

void OverlayTrailsTest::init() {
    window_ = std::make_unique<MainWindow>();
    window_->resize(1000, 700);
    window_->viewport()->setFixedSize(320, 180);
    window_->show();
    QVERIFY(window_->openFile(scenePath("reference-room.scene.json")));
    QVERIFY(settleAtViewportSize(*window_, QSize(320, 180)));
    QVERIFY(!window_->viewport()->frameView()->usesOpenGL());
}

void OverlayTrailsTest::cleanup() {
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

int OverlayTrailsTest::stalePixels(const std::vector<ObjectId>& selected) {
    MainWindow& w = *window_;
    if (!settle(w)) return -2;
    QTest::qWait(80);  // The last repaint and the backing store's flush.
    const DisplayFrame full = wholeFrame(renderSession(w));
    const QImage expected =
        viewportImage(full, ViewMode::Color, selected).convertToFormat(QImage::Format_RGB888);
    const QImage screen =
        w.screen()->grabWindow(w.winId()).toImage().convertToFormat(QImage::Format_RGB888);
    const QPoint origin = w.viewport()->mapTo(&w, QPoint(0, 0));
    // What the overlay draws now (glyphs, gizmo), as an alpha mask of the viewport.
    QImage overlay(w.viewport()->size(), QImage::Format_ARGB32);
    overlay.fill(Qt::transparent);
    ViewportOverlay* layer = w.viewport()->findChild<ViewportOverlay*>();
    if (!layer) return -3;
    layer->render(&overlay, QPoint(), QRegion(), QWidget::RenderFlags());
    auto overlayNow = [&](const QPoint& p) {
        constexpr int kReach = 3;  // antialiased edges
        for (int dy = -kReach; dy <= kReach; ++dy)
            for (int dx = -kReach; dx <= kReach; ++dx) {
                const QPoint q = p + QPoint(dx, dy);
                if (overlay.rect().contains(q) && qAlpha(overlay.pixel(q)) != 0) return true;
            }
        return false;
    };
    int bad = 0, compared = 0;
    for (int y = 0; y < full.height; ++y)
        for (int x = 0; x < full.width; ++x) {
            const QPoint at = w.viewport()->widgetPointOf(x, y);
            if (overlayNow(at)) continue;
            ++compared;
            bad += screen.pixelColor(origin + at) != expected.pixelColor(x, y);
        }
    return compared > full.width * full.height / 2 ? bad : -1;
}

void OverlayTrailsTest::selectDragUndoDeselectHideReopen_LeaveNoOverlayPixels() {
    MainWindow& w = *window_;
    const ObjectId blue = idOf(w, "blue ball");
    const ObjectId chrome = idOf(w, "chrome ball");
    w.viewport()->setGizmoVisible(true);
    w.editor()->setSelection(blue);
    QCOMPARE(stalePixels({blue}), 0);
    QVERIFY(w.viewport()->gizmo().has_value());

    // A drag whose steps arrive while passes run: the gizmo moves with the ball while tiles
    // of the frame under it are repainted.
    w.session()->beginInteraction(blue);
    for (int k = 0; k < 12; ++k) {
        SceneDocument doc = w.editor()->document();
        moveBy(doc, blue, Vec3(0.1f, 0.04f, 0.0f));
        w.editor()->edit(QStringLiteral("Move object"), std::move(doc), MergeKind::Drag,
                         QString::number(blue));
        QTest::qWait(9);
    }
    w.session()->endInteraction();
    w.editor()->closeMerge();
    QCOMPARE(stalePixels({blue}), 0);

    // Undo brings the ball and its gizmo back; another object's gizmo replaces it.
    w.editor()->undoStack()->undo();
    QCOMPARE(stalePixels({blue}), 0);
    w.editor()->setSelection(chrome);
    QCOMPARE(stalePixels({chrome}), 0);

    // Nothing selected: no gizmo, no outline.
    w.editor()->setSelection(kNoObject);
    QVERIFY(!w.viewport()->gizmo().has_value());
    QCOMPARE(stalePixels({}), 0);

    // Selected with the gizmo hidden: the outline alone.
    w.editor()->setSelection(blue);
    QCOMPARE(stalePixels({blue}), 0);
    w.viewport()->setGizmoVisible(false);
    QVERIFY(!w.viewport()->gizmo().has_value());
    QCOMPARE(stalePixels({blue}), 0);

    // Reopening the file clears the selection and everything drawn for it.
    w.viewport()->setGizmoVisible(true);
    QCOMPARE(stalePixels({blue}), 0);
    w.editor()->undoStack()->setClean();
    QVERIFY(w.openFile(scenePath("reference-room.scene.json")));
    QCOMPARE(stalePixels({}), 0);
}

QTEST_MAIN(OverlayTrailsTest)
#include "overlay_trails_test.moc"
