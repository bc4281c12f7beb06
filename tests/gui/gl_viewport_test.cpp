// A real window under Xvfb (xcb, Mesa GL): the OpenGL viewport must show the session's frame
// as the CPU tone mapping gives it, and draw the selection outline.
#include "gui_test_support.h"

#include <QGuiApplication>
#include <QSurfaceFormat>
#include <QtTest>

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class GlViewportTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void openGLViewport_ShowsTheToneMappedFrame();
};

void GlViewportTest::initTestCase() {
    isolateSettings();
    QCOMPARE(QGuiApplication::platformName(), QStringLiteral("xcb"));
}

void GlViewportTest::openGLViewport_ShowsTheToneMappedFrame() {
    MainWindow w;
    w.resize(1000, 700);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY2(w.viewport()->frameView()->usesOpenGL(), "no OpenGL viewport under xcb/Mesa");
    QVERIFY(w.openFile(scenePath("reference-room.scene.json")));
    w.setRenderSize(160, 90);
    QVERIFY(settle(w));
    QTest::qWait(50);

    const auto frame = w.viewport()->frame();
    const QImage expected = toneMappedImage(*frame);
    const QImage shown = w.viewport()->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    QVERIFY(!shown.isNull());
    int worst = 0, bad = 0;
    for (int y = 0; y < frame->height; ++y)
        for (int x = 0; x < frame->width; ++x) {
            const QPoint p = w.viewport()->widgetPointOf(x, y);
            const QColor a = shown.pixelColor(p), b = expected.pixelColor(x, y);
            const int d = std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()),
                                    std::abs(a.blue() - b.blue())});
            worst = std::max(worst, d);
            bad += d > 3;
        }
    QVERIFY2(bad == 0, qPrintable(QStringLiteral("%1 pixels differ by more than 3 levels (worst %2)")
                                      .arg(bad).arg(worst)));

    // Selecting an object draws its outline in the shader.
    const ObjectId blue = idOf(w, "blue ball");
    w.editor()->setSelection(blue);
    QTest::qWait(50);
    const QImage outlined = w.viewport()->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    int outlinePixels = 0;
    for (int y = 0; y < frame->height; ++y)
        for (int x = 0; x < frame->width; ++x)
            if (onOutline(*frame, x, y, blue))
                outlinePixels += outlined.pixelColor(w.viewport()->widgetPointOf(x, y)) ==
                                 QColor(kOutlineRgb[0], kOutlineRgb[1], kOutlineRgb[2]);
    QVERIFY(outlinePixels > 10);
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
