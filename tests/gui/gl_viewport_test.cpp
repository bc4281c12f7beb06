// A real window under Xvfb (xcb, Mesa GL): the OpenGL viewport must show the session's frame
// as the CPU tone mapping gives it, and draw the selection outline, the light glyphs and the
// transform gizmo.
#include <QGuiApplication>
#include <QSurfaceFormat>
#include <QtTest>
#include <cmath>

#include "display_choice.h"
#include "gl_frame_view.h"
#include "gui_test_support.h"
#include "passepartout.h"
#include "preferences.h"
#include "scene_edits.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class GlViewportTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void openGLViewport_ShowsTheToneMappedFrame();
    void openGLViewport_AfterEditsUploadedByRectangles_ShowsTheSessionFrame();
    void openGLViewport_ThroughTheSceneCamera_DimsOnlyOutsideTheOutputFrame();
    void openGLViewport_DrawsTheGizmo_AndOutlinesEverySelectedObject();
    void automaticDisplay_PicksSoftwareOnLlvmpipe_OpenGLOnAGpu();
};

namespace {

/// Pixels of the viewport's grab that differ from the CPU shading of `frame` by more than 3
/// levels (the outline where `selected` is set must match exactly).
/// True where a light glyph is painted over the frame (those pixels are the glyph's).
bool underGlyph(MainWindow& w, const QPoint& p) {
    for (const LightGlyph& g : w.viewport()->lightGlyphs())
        if (std::hypot(p.x() - g.centre.x(), p.y() - g.centre.y()) <= g.radius + 3.0) return true;
    return false;
}

int differingPixels(MainWindow& w, const DisplayFrame& frame, ObjectId selected) {
    const QImage expected = viewportImage(frame, ViewMode::Color, {selected});
    const QImage shown =
        w.viewport()->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    int bad = 0;
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            const QPoint at = w.viewport()->widgetPointOf(x, y);
            if (underGlyph(w, at)) continue;
            const QColor a = shown.pixelColor(at), b = expected.pixelColor(x, y);
            bad += std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()),
                             std::abs(a.blue() - b.blue())}) > 3;
        }
    return bad;
}

}  // namespace

/// Preferences → Display as a user would leave it for the next start.
static void setDisplayPreference(DisplayKind kind) {
    Preferences prefs = loadPreferences();
    prefs.display = kind;
    savePreferences(prefs);
}

void GlViewportTest::initTestCase() {
    isolateSettings();
    QCOMPARE(QGuiApplication::platformName(), QStringLiteral("xcb"));
    // Automatic would pick the raster view on this software GL: these tests are OpenGL's.
    setDisplayPreference(DisplayKind::OpenGL);
}

void GlViewportTest::openGLViewport_ShowsTheToneMappedFrame() {
    MainWindow w;
    w.resize(1000, 700);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY2(w.viewport()->frameView()->usesOpenGL(), "no OpenGL viewport under xcb/Mesa");
    QVERIFY(w.openFile(scenePath("reference-room.scene.json")));
    QVERIFY(traceViewport(w, QSize(320, 180), 2));  // A 160x90 frame, drawn at twice its size.
    QTest::qWait(50);

    const auto frame = w.viewport()->frame();
    const QImage expected = toneMappedImage(*frame);
    const QImage shown =
        w.viewport()->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    QVERIFY(!shown.isNull());
    int worst = 0, bad = 0;
    for (int y = 0; y < frame->height; ++y)
        for (int x = 0; x < frame->width; ++x) {
            const QPoint p = w.viewport()->widgetPointOf(x, y);
            if (underGlyph(w, p)) continue;
            const QColor a = shown.pixelColor(p), b = expected.pixelColor(x, y);
            const int d = std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()),
                                    std::abs(a.blue() - b.blue())});
            worst = std::max(worst, d);
            bad += d > 3;
        }
    QVERIFY2(bad == 0,
             qPrintable(QStringLiteral("%1 pixels differ by more than 3 levels (worst %2)")
                            .arg(bad)
                            .arg(worst)));
    // The light glyph is drawn over the OpenGL frame too (a native window hides widgets over
    // it): the room's white ceiling light shows as a white disc.
    const auto glyphs = w.viewport()->lightGlyphs();
    QCOMPARE(glyphs.size(), std::size_t(1));
    const QColor centre = shown.pixelColor(glyphs.front().centre.toPoint());
    QVERIFY2(centre.red() > 245 && centre.green() > 245 && centre.blue() > 245,
             qPrintable(centre.name()));

    // Selecting an object draws its outline in the shader.
    const ObjectId blue = idOf(w, "blue ball");
    w.editor()->setSelection(blue);
    QTest::qWait(50);
    const QImage outlined =
        w.viewport()->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    int outlinePixels = 0;
    for (int y = 0; y < frame->height; ++y)
        for (int x = 0; x < frame->width; ++x)
            if (onOutline(*frame, x, y, {blue}))
                outlinePixels += outlined.pixelColor(w.viewport()->widgetPointOf(x, y)) ==
                                 QColor(kOutlineRgb[0], kOutlineRgb[1], kOutlineRgb[2]);
    QVERIFY(outlinePixels > 10);
    w.editor()->undoStack()->setClean();
}

void GlViewportTest::openGLViewport_AfterEditsUploadedByRectangles_ShowsTheSessionFrame() {
    MainWindow w;
    w.resize(1000, 700);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(scenePath("reference-room.scene.json")));
    QVERIFY(traceViewport(w, QSize(320, 180), 1));
    const ObjectId blue = idOf(w, "blue ball");
    w.editor()->setSelection(blue);
    w.viewport()->setGizmoVisible(false);  // Its pixels are not the frame's.
    QTest::qWait(50);
    // Steps of a drag with repaints between them: colour and ids go up by rectangles.
    w.session()->beginInteraction(blue);
    for (int k = 0; k < 8; ++k) {
        SceneDocument doc = w.editor()->document();
        moveBy(doc, blue, Vec3(0.1f, 0.03f, 0.0f));
        w.editor()->edit(QStringLiteral("Move object"), std::move(doc), MergeKind::Drag,
                         QString::number(blue));
        QTest::qWait(20);
    }
    w.session()->endInteraction();
    QVERIFY(settle(w));
    QTest::qWait(50);
    const DisplayFrame full = DisplayFrame::fromSession(w.session()->session());
    QCOMPARE(differingPixels(w, full, blue), 0);
    // Bit for bit what uploading the whole frame at once draws.
    auto* view = dynamic_cast<GlFrameView*>(w.viewport()->frameView());
    QVERIFY(view);
    const QImage incremental = view->grabImage();
    view->forgetUploads();
    const QImage whole = view->grabImage();
    QVERIFY(!incremental.isNull());
    QCOMPARE(incremental, whole);
    w.editor()->undoStack()->setClean();
}

void GlViewportTest::openGLViewport_ThroughTheSceneCamera_DimsOnlyOutsideTheOutputFrame() {
    MainWindow w;
    w.resize(1000, 700);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(scenePath("reference-room.scene.json")));
    // Taller than the 16:9 output: the output frame spans rows 70 to 249 (passepartout.h).
    QVERIFY(traceViewport(w, QSize(320, 320), 2));
    QTest::qWait(50);
    const auto frame = w.viewport()->frame();
    const QImage expected = toneMappedImage(*frame);
    const QImage shown =
        w.viewport()->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    auto ratio = [&](int y0, int y1) {
        double a = 0.0, b = 0.0;
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < 320; ++x) {
                const QColor s = shown.pixelColor(x, y), e = expected.pixelColor(x / 2, y / 2);
                a += s.red() + s.green() + s.blue();
                b += e.red() + e.green() + e.blue();
            }
        return b > 0.0 ? a / b : 0.0;
    };
    const double above = ratio(4, 64), inside = ratio(90, 230), below = ratio(256, 316);
    QVERIFY2(std::abs(above - kPassepartoutKeep) < 0.05, qPrintable(QString::number(above)));
    QVERIFY2(std::abs(below - kPassepartoutKeep) < 0.05, qPrintable(QString::number(below)));
    QVERIFY2(std::abs(inside - 1.0) < 0.03, qPrintable(QString::number(inside)));
    w.editor()->undoStack()->setClean();
}

void GlViewportTest::openGLViewport_DrawsTheGizmo_AndOutlinesEverySelectedObject() {
    MainWindow w;
    w.resize(1000, 700);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.viewport()->frameView()->usesOpenGL());
    QVERIFY(w.openFile(scenePath("reference-room.scene.json")));
    w.setRenderSize(160, 90);
    QVERIFY(settle(w));
    const ObjectId blue = idOf(w, "blue ball"), chrome = idOf(w, "chrome ball");
    w.editor()->setSelection(std::vector{blue, chrome});
    QTest::qWait(100);
    const auto gizmo = w.viewport()->gizmo();
    QVERIFY(gizmo);
    const auto grabShown = [&] {
        return w.viewport()->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    };
    const QImage with = grabShown();
    w.viewport()->setGizmoVisible(false);
    QTest::qWait(100);
    const QImage without = grabShown();
    // The X arrow is painted red into the GL framebuffer; without the gizmo the frame is there.
    const QPointF arrow = *gizmo->grabPoint({TransformKind::Move, 0, false});
    int red = 0, changed = 0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const QPoint p = arrow.toPoint() + QPoint(dx, dy);
            const QColor c = with.pixelColor(p);
            red += c.red() > c.green() + 80 && c.red() > c.blue() + 80;
            changed += c != without.pixelColor(p);
        }
    QVERIFY2(red >= 3 && changed >= 3,
             qPrintable(QStringLiteral("%1 red, %2 changed").arg(red).arg(changed)));
    // Some ring is drawn too: the gizmo's rotate handle.
    const QPointF ring = *gizmo->grabPoint({TransformKind::Rotate, 1, false});
    int ringChanged = 0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const QPoint p = ring.toPoint() + QPoint(dx, dy);
            ringChanged += with.pixelColor(p) != without.pixelColor(p);
        }
    QVERIFY(ringChanged >= 2);
    // Both selected balls are outlined by the shader.
    const auto frame = w.viewport()->frame();
    for (ObjectId id : {blue, chrome}) {
        int outline = 0;
        for (int y = 0; y < frame->height; ++y)
            for (int x = 0; x < frame->width; ++x)
                if (onOutline(*frame, x, y, {id}))
                    outline += without.pixelColor(w.viewport()->widgetPointOf(x, y)) ==
                               QColor(kOutlineRgb[0], kOutlineRgb[1], kOutlineRgb[2]);
        QVERIFY2(outline > 5, qPrintable(QString::number(id)));
    }
    w.editor()->undoStack()->setClean();
}

void GlViewportTest::automaticDisplay_PicksSoftwareOnLlvmpipe_OpenGLOnAGpu() {
    // This machine's OpenGL is Mesa's software renderer (LIBGL_ALWAYS_SOFTWARE=1).
    QVERIFY2(softwareRenderer(openGLRenderer()), qPrintable(openGLRenderer()));
    setDisplayPreference(DisplayKind::Automatic);
    {
        MainWindow w;
        QVERIFY(!w.viewport()->frameView()->usesOpenGL());
    }
    setOpenGLRendererOverride(QStringLiteral("NVIDIA GeForce RTX 3060/PCIe/SSE2"));
    {
        MainWindow w;
        QVERIFY(w.viewport()->frameView()->usesOpenGL());
    }
    setOpenGLRendererOverride({});
    setDisplayPreference(DisplayKind::OpenGL);

    // Changed live in Preferences: the other view takes over and shows the same frame.
    MainWindow w;
    w.resize(1000, 700);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.viewport()->frameView()->usesOpenGL());
    QVERIFY(w.openFile(scenePath("reference-room.scene.json")));
    QVERIFY(traceViewport(w, QSize(320, 180), 2));
    for (DisplayKind kind : {DisplayKind::Software, DisplayKind::OpenGL}) {
        Preferences prefs = loadPreferences();
        prefs.display = kind;
        w.applyPreferences(prefs);
        QCOMPARE(w.viewport()->frameView()->usesOpenGL(), kind == DisplayKind::OpenGL);
        QVERIFY(settle(w));
        QTest::qWait(50);
        const DisplayFrame full = DisplayFrame::fromSession(w.session()->session());
        QCOMPARE(differingPixels(w, full, kNoObject), 0);
    }
    QCOMPARE(loadPreferences().display, DisplayKind::OpenGL);  // Remembered.
    w.editor()->undoStack()->setClean();
}

int main(int argc, char** argv) {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QSurfaceFormat::setDefaultFormat(format);
    QApplication app(argc, argv);
    GlViewportTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "gl_viewport_test.moc"
