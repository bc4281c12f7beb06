// The display path under QT_QPA_PLATFORM=offscreen (raster viewport): the frame handed over
// tile by tile ends equal to the session's, and exposure edits reach the viewport and export.
#include <QScreen>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <future>
#include <thread>

#include "adapter/frame_handover.h"
#include "display/raster_frame_view.h"
#include "document/scene_edits.h"
#include "gui_test_support.h"
#include "image/tonemap.h"
#include "viewport/viewport_pacing.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class DisplayTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void mergeRects_CoversTheSamePixels();
    void incrementalHandover_EqualsFullCopyAfterThePass();
    void debugBuffers_HandedOverOnlyWhileShown_ThenIncrementallyEqual();
    void rasterView_RepaintsOnlyChangedRectangles_ScreenEqualsTheFullImage();
    void rasterView_QuarterResolutionOrbit_ShowsEachPixelMappedAlone();
    void toneMapRect_CopiesOnlyRowsEqualToTheOneAbove();
    void handover_WhileTheFrameLockIsHeld_ReturnsAtOnce_AndCatchesUpAfter();
    void exposureEdit_ChangesShownImageAndExport_UndoRestoresThem();
    void export_ThroughTheSceneCamera_IsItsOutputFrameOnly();
    void toneMapEdit_ChangesShownImage_UndoRestoresIt();
    void repaintPacing_StillAtItsPace_InteractionInputAndPassEndsAtOnce();
    void stillFrame_TilesWaitForThePace_ThePassEndShowsThemAtOnce();
    void interaction_EveryHandoverTakenAtOnce();
    void orbit_OnlyWholeFramesShownWhileMoving();

private:
    QImage shownImage() const;
    QImage exported(const QString& name);

    std::unique_ptr<MainWindow> window_;
    QTemporaryDir dir_;
};

/// Drags `id` in `steps` small moves that arrive while passes run, so the viewport copies
/// partial passes, then lets go.
static void dragWhilePassesRun(MainWindow& w, ObjectId id, int steps) {
    w.session()->beginInteraction(id);
    for (int k = 0; k < steps; ++k) {
        SceneDocument doc = w.editor()->document();
        moveBy(doc, id, Vec3(0.08f, 0.02f, 0.0f));
        w.editor()->edit(QStringLiteral("Move object"), std::move(doc), MergeKind::Drag,
                         QString::number(id));
        QTest::qWait(7);
    }
    w.session()->endInteraction();
}

void DisplayTest::init() {
    window_ = std::make_unique<MainWindow>();
    window_->resize(1000, 700);
    window_->viewport()->setFixedSize(320, 180);  // The viewport's frame: 10 x 6 tiles of 32.
    window_->show();
    QVERIFY(window_->openFile(scenePath("reference-room.scene.json")));
    QVERIFY(settleAtViewportSize(*window_, QSize(320, 180)));
}

void DisplayTest::cleanup() {
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

/// The CPU-shaded image the raster viewport draws.
QImage DisplayTest::shownImage() const {
    auto* view = dynamic_cast<RasterFrameView*>(window_->viewport()->frameView());
    return view ? view->frameImage().convertToFormat(QImage::Format_RGB888) : QImage();
}

/// File → Export of the current frame, read back.
QImage DisplayTest::exported(const QString& name) {
    const QString path = dir_.filePath(name);
    if (!window_->exportFrame(path)) return {};
    return QImage(path).convertToFormat(QImage::Format_RGB888);
}

/// The largest difference of any channel of two equally sized RGB888 images (256 if not).
static int maxDifference(const QImage& a, const QImage& b) {
    if (a.size() != b.size() || a.isNull()) return 256;
    int worst = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < 3 * a.width(); ++x)
            worst =
                std::max(worst, std::abs(int(a.constScanLine(y)[x]) - int(b.constScanLine(y)[x])));
    return worst;
}

/// The 8-bit level of display-linear `d`, sRGB's curve written out here (IEC 61966-2-1), not
/// the product's srgbEncode.
static int srgbLevel(double d) {
    d = std::clamp(d, 0.0, 1.0);
    const double e = d <= 0.0031308 ? 12.92 * d : 1.055 * std::pow(d, 1.0 / 2.4) - 0.055;
    return int(std::lround(255.0 * e));
}

/// Pixels of `shown` more than one level from `expected(hdr)` (levels of R, G, B) of the
/// frame's colour at the same pixel: the image is the frame's size. One level, since the
/// product rounds float arithmetic where `expected` rounds doubles.
template <class Expected>
static int pixelsOffTheClosedForm(const QImage& shown, const DisplayFrame& frame,
                                  Expected expected) {
    if (shown.size() != QSize(frame.width, frame.height)) return frame.width * frame.height;
    int off = 0;
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            const std::array<int, 3> want = expected(frame.color[std::size_t(y) * frame.width + x]);
            const uchar* got = shown.constScanLine(y) + 3 * x;
            bool bad = false;
            for (int c = 0; c < 3; ++c) bad = bad || std::abs(int(got[c]) - want[c]) > 1;
            off += bad;
        }
    return off;
}

template <class T>
static bool sameBits(const LargeVector<T>& a, const LargeVector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(T) * a.size()) == 0;
}

void DisplayTest::mergeRects_CoversTheSamePixels() {
    const QSize frame(200, 100);
    std::vector<QRect> tiles;
    for (int y = 0; y < 100; y += 32)
        for (int x = 0; x < 200; x += 32)
            if ((x / 32 + y / 32) % 3 != 0)
                tiles.push_back(QRect(x, y, 32, 32) & QRect(QPoint(), frame));
    tiles.push_back(tiles.front());  // A tile committed twice.
    auto cover = [&](const std::vector<QRect>& rects) {
        std::vector<uint8_t> c(std::size_t(frame.width() * frame.height()), 0);
        for (const QRect& r : rects)
            for (int y = r.top(); y <= r.bottom(); ++y)
                for (int x = r.left(); x <= r.right(); ++x)
                    c[std::size_t(y * frame.width() + x)] = 1;
        return c;
    };
    const std::vector<QRect> merged = mergeRects(tiles, frame);
    QVERIFY(merged.size() < tiles.size());
    QVERIFY(cover(merged) == cover(tiles));
}

void DisplayTest::incrementalHandover_EqualsFullCopyAfterThePass() {
    MainWindow& w = *window_;
    const ObjectId blue = idOf(w, "blue ball");
    w.editor()->setSelection(blue);
    dragWhilePassesRun(w, blue, 12);
    QVERIFY(settle(w));

    const auto shown = w.viewport()->frame();
    const DisplayFrame full = wholeFrame(renderSession(w));
    QCOMPARE(shown->width, full.width);
    QCOMPARE(shown->height, full.height);
    QVERIFY(sameBits(shown->color, full.color));
    QVERIFY(sameBits(shown->id, full.id));
    QVERIFY(sameBits(shown->depth, full.depth));
    QVERIFY(sameBits(shown->flags, full.flags));
    // No view shows normals or ray costs: they were not handed over.
    QVERIFY(shown->normal.empty());
    QVERIFY(shown->cost.empty());
    // The raster view re-shaded only what changed; it must still equal shading it all.
    const QImage expected = viewportImage(full, ViewMode::Color, {blue});
    QCOMPARE(shownImage(), expected.convertToFormat(QImage::Format_RGB888));
}

void DisplayTest::debugBuffers_HandedOverOnlyWhileShown_ThenIncrementallyEqual() {
    MainWindow& w = *window_;
    Viewport* v = w.viewport();
    const ObjectId blue = idOf(w, "blue ball");
    QVERIFY(v->frame()->normal.empty());
    QVERIFY(v->frame()->cost.empty());
    // Switching to a view that shows them copies them at once, whole.
    v->setViewMode(ViewMode::Cost);
    {
        const DisplayFrame full = wholeFrame(renderSession(w));
        QVERIFY(sameBits(v->frame()->normal, full.normal));
        QVERIFY(sameBits(v->frame()->cost, full.cost));
    }
    // While it is shown they follow the edits tile by tile.
    dragWhilePassesRun(w, blue, 8);
    QVERIFY(settle(w));
    {
        const auto shown = v->frame();
        const DisplayFrame full = wholeFrame(renderSession(w));
        QVERIFY(sameBits(shown->color, full.color));
        QVERIFY(sameBits(shown->normal, full.normal));
        QVERIFY(sameBits(shown->cost, full.cost));
        QVERIFY(sameBits(shown->depth, full.depth));
        QVERIFY(sameBits(shown->id, full.id));
    }
    // Back to colour: the next hand-over drops them.
    v->setViewMode(ViewMode::Color);
    SceneDocument doc = w.editor()->document();
    moveBy(doc, blue, Vec3(-0.2f, 0.0f, 0.0f));
    w.editor()->edit(QStringLiteral("Move object"), std::move(doc));
    QVERIFY(settle(w));
    QVERIFY(v->frame()->normal.empty());
    QVERIFY(v->frame()->cost.empty());
    const DisplayFrame full = wholeFrame(renderSession(w));
    QVERIFY(sameBits(v->frame()->color, full.color));
    QVERIFY(sameBits(v->frame()->depth, full.depth));
}

void DisplayTest::rasterView_RepaintsOnlyChangedRectangles_ScreenEqualsTheFullImage() {
    MainWindow& w = *window_;
    const ObjectId blue = idOf(w, "blue ball");
    w.viewport()->setGizmoVisible(false);  // Its pixels are not the frame's.
    w.editor()->setSelection(blue);
    QVERIFY(settle(w));
    // The view is told about a few rectangles at a time and repaints only those: what reaches
    // the window (its backing store) must still be the whole frame, shaded afresh.
    w.session()->beginInteraction(blue);
    for (int k = 0; k < 10; ++k) {
        SceneDocument doc = w.editor()->document();
        moveBy(doc, blue, Vec3(-0.08f, 0.03f, 0.0f));
        w.editor()->edit(QStringLiteral("Move object"), std::move(doc), MergeKind::Drag,
                         QString::number(blue));
        QTest::qWait(7);
    }
    w.session()->endInteraction();
    QVERIFY(settle(w));
    const DisplayFrame full = wholeFrame(renderSession(w));
    const QPoint origin = w.viewport()->mapTo(&w, QPoint(0, 0));
    auto underGlyph = [&](const QPoint& p) {
        for (const LightGlyph& g : w.viewport()->lightGlyphs())
            if (std::hypot(p.x() - g.centre.x(), p.y() - g.centre.y()) <= g.radius + 3.0)
                return true;
        return false;
    };
    // Frame pixels on screen that differ from shading the whole frame with `selected`.
    auto stalePixels = [&](ObjectId selected) {
        QTest::qWait(50);  // The last repaint and the backing store's flush.
        const QImage expected =
            viewportImage(full, ViewMode::Color, {selected}).convertToFormat(QImage::Format_RGB888);
        const QImage screen =
            w.screen()->grabWindow(w.winId()).toImage().convertToFormat(QImage::Format_RGB888);
        int bad = 0, compared = 0;
        for (int y = 0; y < full.height; ++y)
            for (int x = 0; x < full.width; ++x) {
                const QPoint at = w.viewport()->widgetPointOf(x, y);
                if (underGlyph(at)) continue;
                ++compared;
                bad += screen.pixelColor(origin + at) != expected.pixelColor(x, y);
            }
        return compared > full.width * full.height / 2 ? bad : -1;
    };
    QCOMPARE(stalePixels(blue), 0);
    // Selecting another object re-shades only near the two outlines; the screen follows.
    const ObjectId chrome = idOf(w, "chrome ball");
    w.editor()->setSelection(chrome);
    QCOMPARE(stalePixels(chrome), 0);
}

/// The colour view shaded pixel by pixel (toDisplay8 of one colour at a time, no outline):
/// what the raster view's row and run reuse must reproduce.
static QImage eachPixelMappedAlone(const DisplayFrame& f) {
    QImage img(f.width, f.height, QImage::Format_RGB888);
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            toDisplay8(f.color[std::size_t(y) * std::size_t(f.width) + std::size_t(x)], f.tonemap,
                       f.exposure, img.scanLine(y) + 3 * x);
    return img;
}

void DisplayTest::rasterView_QuarterResolutionOrbit_ShowsEachPixelMappedAlone() {
    // A quarter-resolution orbit pass gives each 4 x 4 block one ray's value; the raster view
    // maps a repeated colour once and copies its bytes. The whole frame shown while moving
    // must be the session's, and its image every pixel mapped on its own.
    MainWindow& w = *window_;
    w.viewport()->setGizmoVisible(false);
    w.editor()->setSelection(std::vector<ObjectId>{});  // No outline: colours alone.
    InteractionPolicy policy = renderSession(w).policy();
    policy.resolution = MovingResolution::Quarter;
    policy.governorTargetMs = 0.0;  // Exactly the settings: every orbit pass is quarter.
    renderSession(w).setPolicy(policy);
    QVERIFY(settle(w));
    w.session()->beginInteraction(kNoObject);
    SceneDocument doc = w.editor()->document();
    doc.camera.position.x += 0.05f;
    w.editor()->edit(QStringLiteral("Orbit"), std::move(doc), MergeKind::Drag,
                     QStringLiteral("camera"));
    w.session()->flushUpdate();
    const uint64_t generation = renderSession(w).generation();
    QVERIFY(renderSession(w).waitForPass(generation, std::chrono::seconds(60)));
    // The pass's end is handed over by the event loop; the session waits, still moving.
    DisplayFrame session;
    QTRY_VERIFY((session = wholeFrame(renderSession(w)),
                 w.viewport()->frame()->generation >= generation &&
                     sameBits(w.viewport()->frame()->color, session.color)));
    const DisplayFrame& shown = *w.viewport()->frame();
    QVERIFY(sameBits(shown.id, session.id));
    QVERIFY(sameBits(shown.depth, session.depth));
    // Blocks, not pixels: each whole 4 x 4 block holds its top-left pixel's colour.
    int blocks = 0, uniform = 0;
    for (int by = 0; by + 4 <= shown.height; by += 4)
        for (int bx = 0; bx + 4 <= shown.width; bx += 4, ++blocks) {
            const Color c = shown.color[std::size_t(by) * std::size_t(shown.width) + bx];
            bool same = true;
            for (int y = by; y < by + 4; ++y)
                for (int x = bx; x < bx + 4; ++x)
                    same = same && std::memcmp(&c, &shown.color[std::size_t(y) * shown.width + x],
                                               sizeof(Color)) == 0;
            uniform += same;
        }
    QCOMPARE(uniform, blocks);
    QCOMPARE(shownImage(), eachPixelMappedAlone(session));
    w.session()->endInteraction();
    QVERIFY(settle(w));
    // And the full-resolution frame after it.
    QCOMPARE(shownImage(), eachPixelMappedAlone(wholeFrame(renderSession(w))));
}

void DisplayTest::toneMapRect_CopiesOnlyRowsEqualToTheOneAbove() {
    // Rows that repeat the one above within the rectangle, rows that differ from it only
    // after their first pixel or only outside the rectangle, and runs of equal pixels: the
    // rectangle's bytes must be each pixel's own, and the bytes outside it untouched.
    DisplayFrame f;
    f.width = 12;
    f.height = 8;
    f.tonemap = ToneMap::Aces;
    f.exposure = 0.4f;
    f.color.assign(std::size_t(f.width * f.height), Color(0.3f));
    const auto at = [&](int x, int y) -> Color& { return f.color[std::size_t(y * f.width + x)]; };
    for (int x = 0; x < f.width; ++x) at(x, 0) = Color(0.05f * float(x / 3), 0.2f, 0.7f);
    for (int x = 0; x < f.width; ++x) at(x, 1) = at(x, 0);  // repeats row 0
    for (int x = 0; x < f.width; ++x) at(x, 2) = at(x, 1);
    at(7, 2) = Color(2.0f, 0.1f, 0.1f);  // differs after its first pixel
    for (int x = 0; x < f.width; ++x) at(x, 3) = at(x, 2);
    at(11, 3) = Color(0.9f);             // differs outside the rectangle
    at(0, 3) = Color(0.0f, 0.9f, 0.0f);  // and at its left, outside too
    for (int x = 0; x < f.width; ++x) at(x, 4) = Color(0.01f * float(x));
    const QRect rect(1, 0, 10, 6);  // columns 1..10, rows 0..5
    QImage image(f.width, f.height, QImage::Format_RGB888);
    image.fill(Qt::magenta);
    toneMapRect(f, rect, image);
    const QImage alone = eachPixelMappedAlone(f);
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            QCOMPARE(image.pixelColor(x, y),
                     rect.contains(x, y) ? alone.pixelColor(x, y) : QColor(Qt::magenta));
}

void DisplayTest::handover_WhileTheFrameLockIsHeld_ReturnsAtOnce_AndCatchesUpAfter() {
    MainWindow& w = *window_;
    const ObjectId blue = idOf(w, "blue ball");
    SceneDocument doc = w.editor()->document();
    moveBy(doc, blue, Vec3(0.3f, 0.0f, 0.0f));
    w.editor()->edit(QStringLiteral("Move object"), std::move(doc));
    w.session()->flushUpdate();
    // The edit's tiles are committed; the viewport has not looked (no event loop ran).
    QVERIFY(renderSession(w).waitUntilComplete(std::chrono::seconds(60)));
    const uint64_t shownSerial = w.viewport()->frame()->serial;

    // Another thread holds the frame lock (as an edit's dirty marking does). It lets go after
    // 20 s on its own, so a hand-over that waited would return, late, with a new frame.
    std::promise<void> held, release;
    std::thread holder([&] {
        renderSession(w).withFrame([&](const DeepFrame&, const auto&) {
            held.set_value();
            release.get_future().wait_for(std::chrono::seconds(20));
        });
    });
    held.get_future().wait();
    const int busy = w.session()->handoverStats().busy;
    const auto frame = w.session()->displayFrame(SessionController::FrameWait::TryOnly);
    const bool waited = frame->serial != shownSerial;
    release.set_value();
    holder.join();
    QVERIFY2(!waited, "the hand-over waited for the frame lock");
    QCOMPARE(w.session()->handoverStats().busy, busy + 1);

    // It comes back by itself: the viewport ends with the session's frame.
    const DisplayFrame full = wholeFrame(renderSession(w));
    QTRY_VERIFY(w.viewport()->frame()->serial != shownSerial &&
                sameBits(w.viewport()->frame()->color, full.color) &&
                sameBits(w.viewport()->frame()->id, full.id));
}

void DisplayTest::export_ThroughTheSceneCamera_IsItsOutputFrameOnly() {
    // A square output in a 320 x 180 viewport: the viewport shows a 180 x 180 frame with a
    // dimmed margin either side; the export is that square alone, the frame's middle.
    SceneDocument doc = window_->editor()->document();
    doc.render.width = doc.render.height = 400;
    window_->editor()->edit(QStringLiteral("Square"), std::move(doc));
    QVERIFY(settle(*window_));
    QVERIFY(window_->viewport()->throughSceneCamera());
    const QImage whole = shownImage();
    QCOMPARE(whole.size(), QSize(320, 180));
    const QImage square = exported(QStringLiteral("square.png"));
    QCOMPARE(square.size(), QSize(180, 180));
    QCOMPARE(maxDifference(square, whole.copy(70, 0, 180, 180)), 0);
    // Looking through a view of one's own there is no output frame: all of it.
    window_->viewport()->setAxisView(AxisView::Front);
    QVERIFY(settle(*window_));
    QCOMPARE(exported(QStringLiteral("view.png")).size(), QSize(320, 180));
}

void DisplayTest::exposureEdit_ChangesShownImageAndExport_UndoRestoresThem() {
    MainWindow& w = *window_;
    const QImage before = shownImage();
    const QImage exportedBefore = exported(QStringLiteral("before.png"));
    QVERIFY(!before.isNull() && !exportedBefore.isNull());
    const float exposure = w.editor()->document().render.exposure;

    SceneDocument doc = w.editor()->document();
    doc.render.exposure = exposure + 1.0f;
    w.editor()->edit(QStringLiteral("Exposure"), std::move(doc));
    // Nothing is re-traced: no tile will announce the change, yet the viewport must follow.
    QTRY_COMPARE(w.viewport()->frame()->exposure, exposure + 1.0f);
    const QImage brighter = shownImage();
    QVERIFY(brighter != before);
    // Each pixel is the clamp operator of its radiance times 2^exposure, in sRGB.
    const double gain = std::exp2(double(exposure) + 1.0);
    QCOMPARE(pixelsOffTheClosedForm(brighter, *w.viewport()->frame(),
                                    [&](const Color& hdr) {
                                        return std::array<int, 3>{srgbLevel(gain * hdr.x),
                                                                  srgbLevel(gain * hdr.y),
                                                                  srgbLevel(gain * hdr.z)};
                                    }),
             0);
    // The session's pixels shaded with the document's exposure.
    DisplayFrame full = wholeFrame(renderSession(w));
    full.exposure = w.editor()->document().render.exposure;
    QCOMPARE(brighter,
             viewportImage(full, ViewMode::Color, {}).convertToFormat(QImage::Format_RGB888));
    const QImage exportedBrighter = exported(QStringLiteral("brighter.png"));
    QVERIFY(exportedBrighter != exportedBefore);
    QVERIFY(maxDifference(exportedBefore, before) <= 1);  // The file writer rounds its own way.
    QVERIFY(maxDifference(exportedBrighter, brighter) <= 1);

    w.editor()->undoStack()->undo();
    QTRY_COMPARE(w.viewport()->frame()->exposure, exposure);
    QCOMPARE(shownImage(), before);
    QCOMPARE(exported(QStringLiteral("undone.png")), exportedBefore);
}

void DisplayTest::toneMapEdit_ChangesShownImage_UndoRestoresIt() {
    MainWindow& w = *window_;
    const QImage before = shownImage();
    SceneDocument doc = w.editor()->document();
    QCOMPARE(doc.render.tonemap, ToneMap::Clamp);
    doc.render.tonemap = ToneMap::Reinhard;
    w.editor()->edit(QStringLiteral("Tone map"), std::move(doc));
    QTRY_COMPARE(w.viewport()->frame()->tonemap, ToneMap::Reinhard);
    QVERIFY(shownImage() != before);
    // Each pixel is Reinhard's L / (1 + L) of its Rec. 709 luminance L, the colour scaled by
    // the same factor, in sRGB (the room's exposure is 0).
    QCOMPARE(w.editor()->document().render.exposure, 0.0f);
    QCOMPARE(pixelsOffTheClosedForm(
                 shownImage(), *w.viewport()->frame(),
                 [](const Color& hdr) {
                     const double lum = 0.2126 * hdr.x + 0.7152 * hdr.y + 0.0722 * hdr.z;
                     const double k = lum > 0.0 ? 1.0 / (1.0 + lum) : 0.0;
                     return std::array<int, 3>{srgbLevel(k * hdr.x), srgbLevel(k * hdr.y),
                                               srgbLevel(k * hdr.z)};
                 }),
             0);
    w.editor()->undoStack()->undo();
    QTRY_COMPARE(w.viewport()->frame()->tonemap, ToneMap::Clamp);
    QCOMPARE(shownImage(), before);
}

void DisplayTest::repaintPacing_StillAtItsPace_InteractionInputAndPassEndsAtOnce() {
    RepaintPacing p(80, 250);
    QCOMPARE(p.delay(1000), int64_t(0));  // Nothing shown yet: at once.
    p.handedOver(1000);
    QCOMPARE(p.delay(1000), int64_t(80));  // Still: the next look waits for the pace.
    QCOMPARE(p.delay(1030), int64_t(50));
    QCOMPARE(p.delay(1080), int64_t(0));
    QCOMPARE(p.delay(5000), int64_t(0));  // After a quiet spell, an edit's first tiles at once.
    p.passCompleted();
    QCOMPARE(p.delay(1010), int64_t(0));  // The end of a pass at once,
    p.handedOver(1010);
    QCOMPARE(p.delay(1020), int64_t(70));  // and only once.
    p.setInteracting(true);
    QCOMPARE(p.delay(1020), int64_t(0));  // A drag or an orbit: every look at once.
    p.setInteracting(false);
    QCOMPARE(p.delay(1020), int64_t(70));
    p.input(1015);  // A wheel step: its followers as they come, for the quiet time.
    QCOMPARE(p.delay(1020), int64_t(0));
    QCOMPARE(p.delay(1264), int64_t(0));
    p.handedOver(1264);
    QCOMPARE(p.delay(1265), int64_t(79));  // 250 ms after the input: still again.
}

/// Paces the viewport's still frames once an hour, moves the blue ball and waits until the
/// session has traced the edit whole, without running the event loop (so nothing the
/// controller offers has been handed over yet). False if the session did not finish.
static bool moveBallAtAnHoursPace(MainWindow& w) {
    w.viewport()->setRepaintPacing(RepaintPacing(3600 * 1000, 0));
    SceneDocument doc = w.editor()->document();
    moveBy(doc, idOf(w, "blue ball"), Vec3(0.3f, 0.0f, 0.0f));
    w.editor()->edit(QStringLiteral("Move object"), std::move(doc));
    w.session()->flushUpdate();
    return renderSession(w).waitUntilComplete(std::chrono::seconds(60));
}

void DisplayTest::stillFrame_TilesWaitForThePace_ThePassEndShowsThemAtOnce() {
    MainWindow& w = *window_;
    Viewport* v = w.viewport();
    // A still frame's pace of an hour: only the end of a pass can hand its tiles over.
    const uint64_t shownSerial = v->frame()->serial;
    // The edit's tiles are committed; their passes' ends are queued (no event loop ran).
    QVERIFY(moveBallAtAnHoursPace(w));
    // The controller offers new pixels (as its repaint timer does): a still frame waits.
    Q_EMIT w.session()->frameUpdated();
    QCOMPARE(v->frame()->serial, shownSerial);
    // The queued end of the pass is shown at once, long before the hour; it ends equal to
    // the session's frame, and the raster view to shading all of it.
    const DisplayFrame full = wholeFrame(renderSession(w));
    QTRY_VERIFY(v->frame()->serial != shownSerial && sameBits(v->frame()->color, full.color));
    QVERIFY(sameBits(v->frame()->id, full.id));
    QVERIFY(sameBits(v->frame()->depth, full.depth));
    QVERIFY(sameBits(v->frame()->flags, full.flags));
    const QImage expected = viewportImage(full, ViewMode::Color, w.editor()->selectedIds());
    QCOMPARE(shownImage(), expected.convertToFormat(QImage::Format_RGB888));
}

void DisplayTest::interaction_EveryHandoverTakenAtOnce() {
    MainWindow& w = *window_;
    Viewport* v = w.viewport();
    const uint64_t shownSerial = v->frame()->serial;
    QVERIFY(moveBallAtAnHoursPace(w));
    // The right button held on the viewport: an orbit runs (the press handed nothing over).
    const QPoint centre = v->rect().center();
    QTest::mousePress(v, Qt::RightButton, {}, centre);
    QCOMPARE(v->frame()->serial, shownSerial);
    Q_EMIT w.session()->frameUpdated();
    QVERIFY(v->frame()->serial != shownSerial);
    const DisplayFrame full = wholeFrame(renderSession(w));
    QVERIFY(sameBits(v->frame()->color, full.color));
    QTest::mouseRelease(v, Qt::RightButton, {}, centre);
    QVERIFY(settle(w));
}

/// Frames the viewport was handed while the camera moved in `steps` small steps that arrive
/// while passes run, as (whole, torn) counts; then lets go.
static std::pair<int, int> framesWhileOrbiting(MainWindow& w, int steps) {
    int whole = 0, torn = 0;
    bool moving = true;
    const QMetaObject::Connection c = QObject::connect(
        w.session(), &SessionController::frameHandedOver, [&](quint64, bool isWhole) {
            if (moving) ++(isWhole ? whole : torn);
        });
    w.session()->beginInteraction(kNoObject);
    for (int k = 0; k < steps; ++k) {
        SceneDocument doc = w.editor()->document();
        doc.camera.position.x += 0.02f;
        w.editor()->edit(QStringLiteral("Orbit"), std::move(doc), MergeKind::Drag,
                         QStringLiteral("camera"));
        QTest::qWait(3);
    }
    moving = false;
    QObject::disconnect(c);
    w.session()->endInteraction();
    return {whole, torn};
}

void DisplayTest::orbit_OnlyWholeFramesShownWhileMoving() {
    // Every orbit step re-traces the whole frame, and the next move arrives while it runs:
    // the viewport keeps the last whole frame rather than show one made of two cameras.
    MainWindow& w = *window_;
    const auto [whole, torn] = framesWhileOrbiting(w, 60);
    QCOMPARE(torn, 0);
    QVERIFY(whole > 0);
    QVERIFY(settle(w));
    const DisplayFrame full = wholeFrame(renderSession(w));
    QVERIFY(sameBits(w.viewport()->frame()->color, full.color));
}

QTEST_MAIN(DisplayTest)
#include "display_test.moc"
