// A real window under Xvfb (xcb, Mesa GL): the OpenGL viewport must show the session's frame
// as the CPU tone mapping gives it, and draw the selection outline, the light glyphs and the
// transform gizmo.
#include <QtCore/qfloat16.h>

#include <QGuiApplication>
#include <QSurfaceFormat>
#include <QtTest>
#include <cmath>

#include "adapter/frame_handover.h"
#include "display/display_choice.h"
#include "display/gl_frame_view.h"
#include "document/scene_edits.h"
#include "gui_test_support.h"
#include "image/tonemap.h"
#include "shell/preferences.h"
#include "viewport/passepartout.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class GlViewportTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void openGLViewport_ShowsTheToneMappedFrame();
    void openGLShader_EveryOperatorAndExposure_AsTheCpuToneMap();
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

/// The shader's tone mapping (resources/shaders/frame.frag) against the CPU's
/// (render/image/tonemap.cpp) for every operator at three exposures, on greys from black to
/// far over white, colours whose channels straddle white (Reinhard maps their luminance, the
/// others each channel), and a value in sRGB's linear toe. Each input fills a block of a frame
/// the GL view shows at one frame pixel a widget pixel.
///
/// Tolerance: the view uploads the frame as half floats (11 significant bits: a relative error
/// up to 2^-12), so the CPU maps the same half-rounded input; what remains is the
/// framebuffer's rounding to 8 bits (half a level) and the GPU's float arithmetic (exp2, pow,
/// a division; Mesa's llvmpipe keeps them within a few ulps, far below a level). So the shown
/// level must be within 0.5 + 0.1 of 255 * srgb(toneMap(input)), and, counted in levels, within
/// one of the CPU's 8-bit code (toDisplay8) of the unrounded input. A branch computed
/// differently (another curve, another white point, other luminance weights, exposure applied
/// as e^stops) moves the levels of several inputs by more than that.
void GlViewportTest::openGLShader_EveryOperatorAndExposure_AsTheCpuToneMap() {
    const std::vector<Color> inputs = {Color(0.0f),
                                       Color(0.002f),
                                       Color(0.18f),
                                       Color(1.0f),
                                       Color(4.0f),
                                       Color(20.0f),
                                       Color(4.0f, 0.5f, 0.1f),
                                       Color(0.05f, 0.3f, 2.0f),
                                       Color(20.0f, 1.0f, 0.18f),
                                       Color(0.6f, 0.18f, 0.9f)};
    constexpr int kBlock = 12;
    const int width = int(inputs.size()) * kBlock, height = kBlock;
    QWidget host;
    host.setWindowTitle(QStringLiteral("tone map"));
    auto* view = new GlFrameView(&host);
    view->widget()->setGeometry(0, 0, width, height);
    host.resize(width, height);
    host.show();
    QVERIFY(QTest::qWaitForWindowExposed(&host));
    QVERIFY(QTest::qWaitForWindowExposed(view));

    std::vector<std::shared_ptr<DisplayFrame>> frames;  // kept: each upload is a new frame
    int checked = 0;
    double worst = 0.0;  // levels between the shown value and the unrounded CPU value
    for (ToneMap op : {ToneMap::Clamp, ToneMap::Linear, ToneMap::Reinhard, ToneMap::Aces})
        for (float exposure : {-2.0f, 0.0f, 1.5f}) {
            auto frame = std::make_shared<DisplayFrame>();
            frame->width = width;
            frame->height = height;
            frame->tonemap = op;
            frame->exposure = exposure;
            frame->serial = frames.size() + 1;
            frame->color.resize(std::size_t(width) * height);
            frame->id.assign(std::size_t(width) * height, kNoObject);
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x)
                    frame->color[std::size_t(y) * width + x] = inputs[std::size_t(x / kBlock)];
            frames.push_back(frame);
            QSignalSpy swapped(view, &QOpenGLWindow::frameSwapped);
            view->showFrame(frame, ViewMode::Color, {});
            QVERIFY(swapped.wait(5000));  // painted: the grab reads the framebuffer
            const QImage shown = view->grabImage().convertToFormat(QImage::Format_RGB888);
            QCOMPARE(shown.size(), QSize(width, height));
            for (std::size_t i = 0; i < inputs.size(); ++i) {
                const QColor got = shown.pixelColor(int(i) * kBlock + kBlock / 2, kBlock / 2);
                const int level[3] = {got.red(), got.green(), got.blue()};
                Color half;  // what the texture holds
                for (int c = 0; c < 3; ++c) half[c] = float(qfloat16(inputs[i][c]));
                const Color mapped = toneMap(half, op, exposure);
                uint8_t cpu[3];
                toDisplay8(inputs[i], op, exposure, cpu);
                for (int c = 0; c < 3; ++c) {
                    const double exact = 255.0 * double(srgbEncode(mapped[c]));
                    const QString where =
                        QStringLiteral(
                            "operator %1, exposure %2, input (%3, %4, %5), channel %6: "
                            "shown %7, CPU %8 (%9, 8-bit %10)")
                            .arg(int(op))
                            .arg(exposure)
                            .arg(inputs[i].x)
                            .arg(inputs[i].y)
                            .arg(inputs[i].z)
                            .arg(c)
                            .arg(level[c])
                            .arg(exact, 0, 'f', 3)
                            .arg(double(mapped[c]), 0, 'f', 5)
                            .arg(int(cpu[c]));
                    worst = std::max(worst, std::abs(level[c] - exact));
                    QVERIFY2(std::abs(level[c] - exact) <= 0.6, qPrintable(where));
                    QVERIFY2(std::abs(level[c] - int(cpu[c])) <= 1, qPrintable(where));
                    ++checked;
                }
            }
        }
    QCOMPARE(checked, 4 * 3 * 10 * 3);
    qInfo("tone map: shown within %.3f levels of the CPU's unrounded values", worst);
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
    const DisplayFrame full = wholeFrame(renderSession(w));
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
        const DisplayFrame full = wholeFrame(renderSession(w));
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
