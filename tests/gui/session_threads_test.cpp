// The designer's threads together: mouse drags, orbits and property edits posted while the
// session's workers trace, a Render Image job running beside them, and every hand-over from
// those threads to the widgets (GuiMailbox). Run in the release build as a behaviour test
// and, in packaging/setup.sh test, in the ThreadSanitizer build, where any data race between
// the GUI thread, the session's scheduler, its workers and the job fails it.
#include <QFile>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "gui_test_support.h"
#include "integrator/renderer.h"
#include "jobs/gui_mailbox.h"
#include "shell/error_reporter.h"
#include "snapshot/compiled_scene.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class SessionThreadsTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void mailbox_RunsCallsInPostedOrderOnTheGuiThread_AndDropsThemWithItsContext();
    void editsWhilePassesRun_EndInTheFullRenderOfTheLastDocument();
};

void SessionThreadsTest::mailbox_RunsCallsInPostedOrderOnTheGuiThread_AndDropsThemWithItsContext() {
    auto context = std::make_unique<QObject>();
    const GuiMailbox mailbox(context.get());
    std::vector<int> seen;  // Written only on the GUI thread, by the calls.
    bool offThread = false;
    QThread* gui = QThread::currentThread();
    std::thread poster([&] {
        for (int i = 0; i < 1000; ++i)
            mailbox.post([&, i] {
                offThread = offThread || QThread::currentThread() != gui;
                seen.push_back(i);
            });
    });
    poster.join();
    QVERIFY(seen.empty());  // Nothing runs on the posting thread or before the event loop.
    QTRY_COMPARE(seen.size(), std::size_t(1000));
    QVERIFY(!offThread);
    QVERIFY(std::is_sorted(seen.begin(), seen.end()));

    // Posted, then the context goes: the call is dropped, and later posts are ignored.
    bool ran = false;
    mailbox.post([&] { ran = true; });
    context.reset();
    mailbox.post([&] { ran = true; });
    QTest::qWait(50);
    QVERIFY(!ran);
}

void SessionThreadsTest::editsWhilePassesRun_EndInTheFullRenderOfTheLastDocument() {
    QStringList errors;
    setErrorHandler(
        [&](const QString& title, const QString& text) { errors << title + ": " + text; });
    std::unique_ptr<MainWindow> window;
    QVERIFY(openRoomWindow(window));
    Viewport* v = window->viewport();

    // A Render Image job on its own thread, reporting progress and tiles through the mailbox.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("during-edits.png"));
    QVERIFY(window->renderImage(path, 320, 180));

    // Drag the blue ball with pauses short enough that passes are cut by the next move.
    const ObjectId blue = idOf(*window, "blue ball");
    const auto [x, y] = pixelOf(*v->frame(), blue);
    QVERIFY(x >= 0);
    const QPoint start = v->widgetPointOf(x, y);
    QTest::mousePress(v, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 12; ++i) {
        QTest::mouseMove(v, start + QPoint(3 * i, -i));
        QTest::qWait(3);
    }
    QTest::mouseRelease(v, Qt::LeftButton, {}, start + QPoint(36, -12));
    QVERIFY(window->editor()->document().findObject(blue)->transform.translate.x > 0.05f);

    // Orbit the view (a camera edit to the session, not to the document) while it refines.
    const QPoint centre(v->width() / 2, v->height() / 2);
    QTest::mousePress(v, Qt::RightButton, {}, centre);
    for (int i = 1; i <= 8; ++i) {
        QTest::mouseMove(v, centre + QPoint(4 * i, 0));
        QTest::qWait(3);
    }
    QTest::mouseRelease(v, Qt::RightButton, {}, centre + QPoint(32, 0));

    // Edits that trace nothing new (exposure) and one that re-traces everything (a material).
    SceneDocument doc = window->editor()->document();
    doc.render.exposure = 0.5f;
    window->editor()->replaceDocument(doc);
    QTest::qWait(2);
    doc.materials.front().color = Color(0.2f, 0.7f, 0.3f);
    window->editor()->replaceDocument(doc);

    QVERIFY(settle(*window));
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(path), 60000);  // The job finished beside the edits.

    // The session's frame is the full render of the snapshot it shows (view camera and all),
    // and that snapshot carries the last document's material.
    bool compared = false;
    renderSession(*window).withFrame([&](const DeepFrame& f,
                                         const std::shared_ptr<const CompiledScene>& scene) {
        QVERIFY(scene);
        QVERIFY(scene->materials().at(1).color == Color(0.2f, 0.7f, 0.3f));  // Slot 0: the default.
        const RenderResult full = renderImage(*scene);
        QCOMPARE(full.image.pixels.size(), f.color().size());
        float worst = 0.0f;
        for (std::size_t i = 0; i < f.color().size(); ++i) {
            const Color d = glm::abs(full.image.pixels[i] - f.color()[i]);
            worst = std::max({worst, d.x, d.y, d.z});
        }
        QVERIFY2(worst <= 1e-5f, qPrintable(QStringLiteral("max difference %1").arg(worst)));
        compared = true;
    });
    QVERIFY(compared);
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));

    window->editor()->undoStack()->setClean();
    window.reset();
    setErrorHandler({});
}

QTEST_MAIN(SessionThreadsTest)
#include "session_threads_test.moc"
