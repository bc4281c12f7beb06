// The viewport traces the viewport (issue 10), offscreen: the session's frame follows the
// widget's size times the preview scale, picking follows the new mapping, the output frame is
// fitted into the view and dimmed around when looking through the scene camera.
#include <QComboBox>
#include <QElapsedTimer>
#include <QtTest>

#include "gui_test_support.h"
#include "integrator/renderer.h"
#include "shell/preferences.h"
#include "snapshot/compiled_scene.h"
#include "viewport/passepartout.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class ViewportSizeTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QVERIFY(openRoomWindow(window_)); }
    void cleanup();

    void resizingTheViewport_ChangesTheTracedSize_NotTheOutputSize();
    void resizing_IsPostedOnceTheEdgeRests();
    void previewScale_ChangesTheTracedSizeAgain_AlsoFromPreferences();
    void picking_AfterAResizeAndAtHalfScale_SelectsTheObjectUnderTheCursor();
    void narrowViewport_FitsTheOutputFrame_AndDimsAroundIt();

private:
    /// Where the blue ball's centre appears in a viewport of `widget` pixels through the scene
    /// camera, computed from the camera alone (valid while the widget is wider than the output).
    QPoint blueBallOnScreen(const QSize& widget) const;

    std::unique_ptr<MainWindow> window_;
};

void ViewportSizeTest::cleanup() {
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

QPoint ViewportSizeTest::blueBallOnScreen(const QSize& widget) const {
    const SceneDocument& doc = window_->editor()->document();
    const CompiledScene scene(doc);
    const Vec3 centre = scene.objectBounds(idOf(*window_, "blue ball")).center();
    // A view at least as wide as the output keeps the camera's vertical field (fovY).
    const CameraModel camera(doc.camera, widget.width(), widget.height());
    float px = 0.0f, py = 0.0f;
    if (!camera.project(centre, px, py)) return {-1, -1};
    return QPoint(int(px), int(py));
}

void ViewportSizeTest::resizingTheViewport_ChangesTheTracedSize_NotTheOutputSize() {
    Viewport* v = window_->viewport();
    QVERIFY(traceViewport(*window_, QSize(400, 240), 1));
    QCOMPARE(QSize(v->frame()->width, v->frame()->height), QSize(400, 240));
    QVERIFY(traceViewport(*window_, QSize(333, 187), 1));
    QCOMPARE(QSize(v->frame()->width, v->frame()->height), QSize(333, 187));
    // The session's own frame, not just the copy shown.
    int w = 0, h = 0;
    renderSession(*window_).withFrame([&](const DeepFrame& f, const auto&) {
        w = f.width();
        h = f.height();
    });
    QCOMPARE(QSize(w, h), QSize(333, 187));
    // The document's output size (Render Image, Export's caption, the CLI) is untouched.
    QCOMPARE(window_->editor()->document().render.width, 160);
    QCOMPARE(window_->editor()->document().render.height, 90);
    QVERIFY(!window_->editor()->undoStack()->canUndo());
}

void ViewportSizeTest::resizing_IsPostedOnceTheEdgeRests() {
    Viewport* v = window_->viewport();
    QVERIFY(traceViewport(*window_, QSize(320, 180), 1));
    const QSize before = v->tracedSize();
    // The edge moves: a resize every 30 ms, each before the previous has rested.
    QElapsedTimer sinceLast;
    bool checked = false;
    for (int w = 330; w <= 420; w += 30) {
        v->setFixedSize(w, 200);
        QVERIFY(QTest::qWaitFor([&] { return v->width() == w; }, 2000));
        sinceLast.start();
        QTest::qWait(30);
        // Unless this machine stalled past the settle time, nothing was posted yet.
        if (sinceLast.elapsed() < Viewport::kResizeSettleMs) {
            QCOMPARE(v->tracedSize(), before);
            checked = true;
        }
    }
    QVERIFY2(checked, "the machine was too slow to resize within the settle time");
    QVERIFY(settleAtViewportSize(*window_, QSize(420, 200)));
    QCOMPARE(QSize(v->frame()->width, v->frame()->height), QSize(420, 200));
}

void ViewportSizeTest::previewScale_ChangesTheTracedSizeAgain_AlsoFromPreferences() {
    Viewport* v = window_->viewport();
    QVERIFY(traceViewport(*window_, QSize(400, 240), 1));
    QVERIFY(traceViewport(*window_, QSize(400, 240), 2));
    QCOMPARE(QSize(v->frame()->width, v->frame()->height), QSize(200, 120));
    QVERIFY(traceViewport(*window_, QSize(401, 241), 4));
    QCOMPARE(QSize(v->frame()->width, v->frame()->height), QSize(101, 61));  // Rounded up.

    // Preferences -> Viewport preview scale reaches the viewport, and is remembered.
    PreferencesDialog* prefs = window_->showPreferences();
    auto* scale = prefs->findChild<QComboBox*>(QStringLiteral("previewScale"));
    QVERIFY(scale);
    scale->setCurrentIndex(1);  // 1/2
    QCOMPARE(v->previewDivider(), 2);
    QVERIFY(settleAtViewportSize(*window_, QSize(401, 241)));
    QCOMPARE(QSize(v->frame()->width, v->frame()->height), QSize(201, 121));
    QCOMPARE(loadPreferences().previewDivider, 2);
    scale->setCurrentIndex(0);
    QCOMPARE(v->previewDivider(), 1);
    prefs->close();
}

void ViewportSizeTest::picking_AfterAResizeAndAtHalfScale_SelectsTheObjectUnderTheCursor() {
    const ObjectId blue = idOf(*window_, "blue ball");
    Viewport* v = window_->viewport();
    // Wider than the output (16:9): the frame shows more of the room at the sides, and the
    // ball is where the scene camera projects it in the widget, not in a letterboxed image.
    for (const auto& [size, divider] :
         {std::pair{QSize(480, 180), 1}, std::pair{QSize(560, 200), 2}}) {
        QVERIFY(traceViewport(*window_, size, divider));
        const QPoint at = blueBallOnScreen(size);
        QVERIFY(v->rect().contains(at));
        window_->editor()->setSelection(kNoObject);
        QTest::mouseClick(v, Qt::LeftButton, {}, at);
        QCOMPARE(window_->editor()->selection(), blue);
        // A drag from there moves that ball (the drag plane comes from the same mapping).
        const float x0 = window_->editor()->document().findObject(blue)->transform.translate.x;
        QTest::mousePress(v, Qt::LeftButton, {}, at);
        for (int i = 1; i <= 5; ++i) QTest::mouseMove(v, at + QPoint(6 * i, 0));
        QTest::mouseRelease(v, Qt::LeftButton, {}, at + QPoint(30, 0));
        QVERIFY(window_->editor()->document().findObject(blue)->transform.translate.x > x0 + 0.05f);
        window_->editor()->undoStack()->undo();
        QVERIFY(settle(*window_));
    }
}

void ViewportSizeTest::narrowViewport_FitsTheOutputFrame_AndDimsAroundIt() {
    Viewport* v = window_->viewport();
    QVERIFY(traceViewport(*window_, QSize(320, 320), 1));
    QVERIFY(v->throughSceneCamera());
    const auto frame = v->frame();
    QCOMPARE(QSize(frame->width, frame->height), QSize(320, 320));

    // The output frame (16:9) spans the full width, rows 70 to 249: there the viewport shows
    // what a 320x180 render of the document shows.
    const QRectF output = v->projection().outputRect();
    QCOMPARE(output, QRectF(0, 70, 320, 180));
    SceneDocument doc = window_->editor()->document();
    doc.render.width = 320;
    doc.render.height = 180;
    RenderOptions options;
    const RenderResult render = renderImage(CompiledScene(doc), options);
    int same = 0;
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x)
            same += frame->idAt(x, y + 70) == render.ids[std::size_t(y) * 320 + x];
    QVERIFY2(same > 320 * 180 * 99 / 100, qPrintable(QString::number(same)));

    // Outside the output frame the picture is dimmed; inside it is not.
    const QImage plain = v->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    const QImage shown = v->grab().toImage().convertToFormat(QImage::Format_RGB888);
    auto brightness = [](const QImage& img, const QRect& r) {
        double sum = 0.0;
        for (int y = r.top(); y <= r.bottom(); ++y)
            for (int x = r.left(); x <= r.right(); ++x) {
                const QColor c = img.pixelColor(x, y);
                sum += c.red() + c.green() + c.blue();
            }
        return sum;
    };
    const QRect above(0, 5, 320, 60), inside(0, 100, 320, 120);
    QVERIFY(brightness(plain, above) > 0.0);
    const double dimmed = brightness(shown, above) / brightness(plain, above);
    QVERIFY2(std::abs(dimmed - kPassepartoutKeep) < 0.05, qPrintable(QString::number(dimmed)));
    QVERIFY(std::abs(brightness(shown, inside) / brightness(plain, inside) - 1.0) < 0.01);

    // A view of its own has no passepartout.
    QTest::keyClick(v, Qt::Key_1);  // Front view.
    QVERIFY(!v->throughSceneCamera());
    QVERIFY(settle(*window_));
    const QImage free = v->grab().toImage().convertToFormat(QImage::Format_RGB888);
    const QImage freePlain = v->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    QVERIFY(std::abs(brightness(free, above) / brightness(freePlain, above) - 1.0) < 0.01);
}

QTEST_MAIN(ViewportSizeTest)
#include "viewport_size_test.moc"
