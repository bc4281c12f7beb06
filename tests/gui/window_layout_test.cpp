// The main window as a user opens it: at 1500 x 950 with the render settings in the
// Properties dock, every colour row's value field is whole inside the dock; and the
// designer's own measurement (--measure-orbit) when the viewport is resized after the open.
#include <QCommandLineParser>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QtTest>

#include "drag_measurement.h"
#include "gui_test_support.h"
#include "panels/property_panel.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class WindowLayoutTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void renderSettings_At1500x950_EveryColourRowFitsTheDock();
    void measureOrbit_WhenTheViewportIsResizedAfterTheOpen_StillCompletes();
};

namespace {

/// `w`'s rectangle in `area`'s viewport coordinates.
QRect rectIn(const QWidget* w, const QScrollArea* area) {
    return QRect(w->mapTo(area->viewport(), QPoint(0, 0)), w->size());
}

}  // namespace

void WindowLayoutTest::renderSettings_At1500x950_EveryColourRowFitsTheDock() {
    QSettings().remove(QStringLiteral("window"));  // The first run's layout, none saved.
    MainWindow window;
    window.resize(1500, 950);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openFile(scenePath("reference-room.scene.json")));
    window.editor()->setSelection(kNoObject);  // The panel shows the render settings.
    QVERIFY(settle(window));
    QTest::qWait(200);  // Let the docks take their final widths.
    PropertyPanel* panel = window.propertyPanel();
    const QRect inside = panel->viewport()->rect();
    const auto values = panel->findChildren<QDoubleSpinBox*>(QStringLiteral("colorValue"));
    const auto swatches = panel->findChildren<QPushButton*>(QStringLiteral("colorButton"));
    QVERIFY2(values.size() >= 2, "Background and Ambient at least");
    QCOMPARE(swatches.size(), values.size());
    QList<QWidget*> fields(values.begin(), values.end());
    fields.append(QList<QWidget*>(swatches.begin(), swatches.end()));
    for (QWidget* w : fields) {
        QVERIFY(w->isVisible());
        const QRect r = rectIn(w, panel);
        // Across, that is: the panel scrolls up and down, never sideways.
        QVERIFY2(r.left() >= inside.left() && r.right() <= inside.right(),
                 qPrintable(QStringLiteral("%1 at x %2..%3, the dock's view 0..%4")
                                .arg(w->objectName())
                                .arg(r.left())
                                .arg(r.right())
                                .arg(inside.right())));
        // Wide enough for what it shows: a value of a few digits, the swatch's three numbers.
        if (auto* spin = qobject_cast<QDoubleSpinBox*>(w))
            QVERIFY2(spin->width() >= spin->minimumSizeHint().width(),
                     qPrintable(QStringLiteral("%1 < %2")
                                    .arg(spin->width())
                                    .arg(spin->minimumSizeHint().width())));
    }
    window.editor()->undoStack()->setClean();
}

void WindowLayoutTest::measureOrbit_WhenTheViewportIsResizedAfterTheOpen_StillCompletes() {
    QCommandLineParser parser;
    addMeasurementOptions(parser);
    QVERIFY(parser.parse({QStringLiteral("raystudio"), QStringLiteral("--measure-orbit"),
                          scenePath("reference-room.scene.json"), QStringLiteral("--frames"),
                          QStringLiteral("4"), QStringLiteral("--json")}));
    // Right after the open the window narrows (the viewport with it), and once more a little
    // later: each new size reaches the session only once it rests, while the full frames
    // are being measured.
    QSize resizedTo;
    int resizes = 0;
    const auto afterOpen = [&](QWidget& window) {
        window.resize(window.width() - 120, window.height() - 40);
        ++resizes;
        QTimer::singleShot(Viewport::kResizeSettleMs + 60, &window, [&] {
            window.resize(window.width() - 60, window.height());
            resizedTo = window.size();
            ++resizes;
        });
    };
    QCOMPARE(runRequestedMeasurement(parser, afterOpen), 0);
    QCOMPARE(resizes, 2);
    QVERIFY(resizedTo.isValid());
}

QTEST_MAIN(WindowLayoutTest)
#include "window_layout_test.moc"
