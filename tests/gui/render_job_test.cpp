// Render -> Render Image as a background job (issue 16), offscreen with real input events:
// the designer stays editable while a render runs, renders queue and all finish, Cancel in
// the status bar stops one at once, the Render window fills in tile by tile, and closing
// asks before it cancels.
#include <QAbstractButton>
#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QImage>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include "gui_test_support.h"
#include "image/image_io.h"
#include "integrator/renderer.h"
#include "jobs/render_queue.h"
#include "jobs/render_status.h"
#include "jobs/render_window.h"
#include "shell/error_reporter.h"
#include "shell/user_confirmation.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

namespace {

/// Tiles (32 px, the renderer's default) of `image` with a non-black pixel, and all tiles.
std::pair<int, int> litTiles(const QImage& image) {
    int lit = 0, total = 0;
    for (int ty = 0; ty < image.height(); ty += 32) {
        for (int tx = 0; tx < image.width(); tx += 32, ++total) {
            bool any = false;
            for (int y = ty; y < std::min(image.height(), ty + 32) && !any; ++y)
                for (int x = tx; x < std::min(image.width(), tx + 32) && !any; ++x)
                    any = (image.pixel(x, y) & 0xffffff) != 0;
            lit += any;
        }
    }
    return {lit, total};
}

}  // namespace

class RenderJobTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void dragWhileRendering_IsAppliedAndUndoable_AndTheViewportRenders();
    void whileTheUserDrags_TheRenderWaits_ThenGoesOn();
    void editsWhileRendering_RenderShowsTheDocumentAsItWasWhenStarted();
    void twoQueuedRenders_BothFinishAndWriteTheirFiles();
    void cancelFromStatusBar_StopsPromptly_AndWritesNothing();
    void renderWindow_ShowsThePartialImageTileByTile();
    void renderWindow_OpensWhollyOnTheScreen_EvenFromAWindowAtItsEdge();
    void closingDuringARender_AsksFirst_ThenCancelsPromptly();
    void unsavedChangesPrompt_IsAnswerableWhileRendering();

private:
    /// Makes the document's full renders take many seconds (64 samples a pixel everywhere),
    /// so only a cancel ends one at 3840x2160 quickly; the viewport stays at 160x90.
    void makeRendersSlow();
    /// Drags the blue ball `moves` x 4 pixels to the right with real mouse events; false when
    /// it is not on screen.
    bool dragBlueBall(int moves);

    std::unique_ptr<MainWindow> window_;
    QStringList errors_;
    QStringList questions_;
    bool answer_ = true;
    QTemporaryDir dir_;
};

void RenderJobTest::init() {
    errors_.clear();
    questions_.clear();
    answer_ = true;
    setErrorHandler(
        [this](const QString& title, const QString& text) { errors_ << title + ": " + text; });
    setConfirmationHandler([this](const QString&, const QString& text) {
        questions_ << text;
        return answer_;
    });
    QVERIFY(openRoomWindow(window_));
}

void RenderJobTest::cleanup() {
    if (window_) {
        window_->editor()->undoStack()->setClean();  // No save prompt on close.
        window_.reset();
    }
    setErrorHandler({});
    setConfirmationHandler({});
}

bool RenderJobTest::dragBlueBall(int moves) {
    Viewport* v = window_->viewport();
    const auto [x, y] = pixelOf(*v->frame(), idOf(*window_, "blue ball"));
    if (x < 0) return false;
    const QPoint start = v->widgetPointOf(x, y);
    QTest::mousePress(v, Qt::LeftButton, {}, start);
    for (int i = 1; i <= moves; ++i) QTest::mouseMove(v, start + QPoint(4 * i, 0));
    QTest::mouseRelease(v, Qt::LeftButton, {}, start + QPoint(4 * moves, 0));
    return true;
}

void RenderJobTest::makeRendersSlow() {
    SceneDocument doc = window_->editor()->document();
    doc.render.supersampling = 64;
    doc.render.adaptiveSupersampling = false;  // Every sample in the first pass, tile by tile.
    window_->editor()->replaceDocument(doc);
}

void RenderJobTest::dragWhileRendering_IsAppliedAndUndoable_AndTheViewportRenders() {
    makeRendersSlow();
    QVERIFY(settle(*window_));
    const QString path = dir_.filePath(QStringLiteral("during-drag.png"));
    QVERIFY(window_->renderImage(path, 3840, 2160));
    QVERIFY(window_->renderQueue()->busy());

    // A drag of the blue ball with real mouse events, while the render runs.
    const ObjectId blue = idOf(*window_, "blue ball");
    const Vec3 before = window_->editor()->document().findObject(blue)->transform.translate;
    const int steps = window_->editor()->undoStack()->count();
    QVERIFY(dragBlueBall(8));

    const Vec3 moved = window_->editor()->document().findObject(blue)->transform.translate;
    QVERIFY2(moved.x > before.x + 0.05f, qPrintable(QString::number(moved.x - before.x)));
    QCOMPARE(window_->editor()->undoStack()->count(), steps + 1);  // One undo step.
    // The viewport follows the edit to a final frame while the render still runs.
    QVERIFY(settle(*window_));
    QVERIFY(window_->renderQueue()->busy());

    window_->editor()->undoStack()->undo();
    QVERIFY(window_->editor()->document().findObject(blue)->transform.translate == before);
    QVERIFY(window_->renderQueue()->busy());
    window_->renderQueue()->cancelAll();
    QVERIFY(!QFileInfo::exists(path));
    QVERIFY(!window_->renderStatus()->isVisible());
    QVERIFY(errors_.isEmpty());
}

void RenderJobTest::whileTheUserDrags_TheRenderWaits_ThenGoesOn() {
    makeRendersSlow();
    QVERIFY(settle(*window_));
    const QString path = dir_.filePath(QStringLiteral("held.png"));
    QVERIFY(window_->renderImage(path, 960, 540));
    RenderQueue* queue = window_->renderQueue();
    QVERIFY(queue->busy() && !queue->held());
    int done = 0;
    connect(queue, &RenderQueue::progressed, this, [&](int d, int, double) { done = d; });
    QTRY_VERIFY_WITH_TIMEOUT(done > 0, 60000);
    // A drag begins: the render's workers wait between tiles, at most the tiles already
    // started finish (one a thread), and the viewport has the cores.
    window_->session()->beginInteraction(idOf(*window_, "blue ball"));
    QVERIFY(queue->held());
    for (int i = 0, before = -1; i < 40 && done != before; ++i) {  // Tiles under way finish.
        before = done;
        QTest::qWait(700);
    }
    const int atHold = done;
    QTest::qWait(1000);
    QCOMPARE(done, atHold);
    // Let go: it goes on.
    window_->session()->endInteraction();
    QVERIFY(!queue->held());
    QTRY_VERIFY_WITH_TIMEOUT(done > atHold, 60000);
    queue->cancelAll();
    QVERIFY(errors_.isEmpty());
}

void RenderJobTest::editsWhileRendering_RenderShowsTheDocumentAsItWasWhenStarted() {
    makeRendersSlow();
    QVERIFY(settle(*window_));
    SceneDocument asStarted = window_->editor()->document();
    const QString path = dir_.filePath(QStringLiteral("as-started.exr"));
    QVERIFY(window_->renderImage(path, 96, 54));
    QVERIFY(window_->renderQueue()->busy());
    // Drag the blue ball with real mouse events while the render runs.
    const ObjectId blue = idOf(*window_, "blue ball");
    QVERIFY(dragBlueBall(8));
    QVERIFY(!(window_->editor()->document().findObject(blue)->transform.translate ==
              asStarted.findObject(blue)->transform.translate));
    QTRY_VERIFY_WITH_TIMEOUT(!window_->renderQueue()->busy(), 120000);
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join(QStringLiteral("; "))));

    // The file is what a command-line render of the document at the start gives.
    asStarted.render.width = 96;
    asStarted.render.height = 54;
    RenderOptions options;
    options.ids = false;
    const RenderResult expected = renderImage(CompiledScene(asStarted), options);
    ImageRgb written;
    std::string error;
    QVERIFY2(readImage(path.toStdString(), written, error), error.c_str());
    QCOMPARE(written.width, 96);
    QCOMPARE(written.height, 54);
    float worst = 0.0f;
    for (std::size_t i = 0; i < written.pixels.size(); ++i) {
        const Color d = glm::abs(written.pixels[i] - expected.image.pixels[i]);
        worst = std::max(worst, std::max(d.x, std::max(d.y, d.z)));
    }
    QVERIFY2(worst <= 1e-5f, qPrintable(QString::number(worst)));
}

void RenderJobTest::twoQueuedRenders_BothFinishAndWriteTheirFiles() {
    QSignalSpy finished(window_->renderQueue(), &RenderQueue::finished);
    const QString first = dir_.filePath(QStringLiteral("first.png"));
    const QString second = dir_.filePath(QStringLiteral("second.png"));
    QVERIFY(window_->renderImage(first, 64, 36));
    QVERIFY(window_->renderImage(second, 48, 30));
    QCOMPARE(window_->renderQueue()->queued(), 1);  // The second waits for the first.

    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 30000);
    QCOMPARE(finished.at(0).at(0).toString(), first);
    QCOMPARE(finished.at(1).at(0).toString(), second);
    QVERIFY(finished.at(0).at(1).toBool());
    QVERIFY(finished.at(1).at(1).toBool());
    QCOMPARE(QImage(first).size(), QSize(64, 36));
    QCOMPARE(QImage(second).size(), QSize(48, 30));
    QVERIFY(!window_->renderQueue()->busy());
    QTRY_VERIFY(!window_->renderStatus()->isVisible());
    QVERIFY(errors_.isEmpty());
}

void RenderJobTest::renderWindow_OpensWhollyOnTheScreen_EvenFromAWindowAtItsEdge() {
    // The main window pushed against the screen's bottom-right corner; a wide render.
    const QRect area = window_->screen()->availableGeometry();
    window_->move(area.right() - window_->frameGeometry().width() / 3,
                  area.bottom() - window_->frameGeometry().height() / 3);
    QApplication::processEvents();
    makeRendersSlow();
    QVERIFY(window_->renderImage(dir_.filePath(QStringLiteral("edge.png")), 3840, 1080));
    QWidget* shown = nullptr;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            for (QWidget* w : QApplication::topLevelWidgets())
                if (w != window_.get() && w->isVisible() && w->inherits("rs::ui::RenderWindow"))
                    shown = w;
            return shown != nullptr;
        }(),
        10000);
    QVERIFY2(area.contains(shown->frameGeometry()),
             qPrintable(QStringLiteral("%1,%2 %3x%4 outside %5x%6")
                            .arg(shown->frameGeometry().x())
                            .arg(shown->frameGeometry().y())
                            .arg(shown->frameGeometry().width())
                            .arg(shown->frameGeometry().height())
                            .arg(area.width())
                            .arg(area.height())));
    window_->renderQueue()->cancelAll();
}

void RenderJobTest::cancelFromStatusBar_StopsPromptly_AndWritesNothing() {
    makeRendersSlow();
    const QString path = dir_.filePath(QStringLiteral("cancelled.png"));
    QSignalSpy progressed(window_->renderQueue(), &RenderQueue::progressed);
    QSignalSpy finished(window_->renderQueue(), &RenderQueue::finished);
    QVERIFY(window_->renderImage(path, 3840, 2160));
    QTRY_VERIFY_WITH_TIMEOUT(progressed.count() >= 2, 20000);

    RenderStatus* status = window_->renderStatus();
    QVERIFY(status->isVisible());
    QVERIFY(window_->statusBar()->isAncestorOf(status));
    QVERIFY2(status->text().contains(QStringLiteral("cancelled.png")) &&
                 status->text().contains(QStringLiteral("left")),
             qPrintable(status->text()));
    QPushButton* cancel = status->cancelButton();
    QVERIFY(cancel->isVisible());
    // Cancel stays put while the words beside it change (a moving button misses clicks).
    const QPoint at = cancel->mapTo(window_.get(), QPoint(0, 0));
    for (const double left : {1.0, 3000.0, 20000.0, 45.0}) {
        Q_EMIT window_->renderQueue()->progressed(3, 100, left);
        QApplication::processEvents();
        QCOMPARE(cancel->mapTo(window_.get(), QPoint(0, 0)), at);
    }

    QElapsedTimer timer;
    timer.start();
    QTest::mouseClick(cancel, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 5000);
    const qint64 ms = timer.elapsed();
    QVERIFY2(ms < 5000, qPrintable(QStringLiteral("cancel took %1 ms").arg(ms)));
    QVERIFY(!finished.first().at(1).toBool());             // Not ok,
    QVERIFY(finished.first().at(2).toString().isEmpty());  // and no error: cancelled.
    QVERIFY(!window_->renderQueue()->busy());
    QTest::qWait(200);
    QVERIFY(!QFileInfo::exists(path));
    QVERIFY(!status->isVisible());
    QVERIFY(errors_.isEmpty());
}

void RenderJobTest::renderWindow_ShowsThePartialImageTileByTile() {
    makeRendersSlow();
    RenderQueue* queue = window_->renderQueue();
    RenderWindow* view = window_->renderWindow();
    // Looked at when the tenth tile arrives: the window has drawn it (it is connected first).
    QImage shown, grabbed;
    bool stillRunning = false;
    int tiles = 0;
    connect(queue, &RenderQueue::tileReady, this, [&] {
        if (++tiles != 10) return;
        stillRunning = queue->busy();
        shown = view->image().copy();
        grabbed = view->grab().toImage();
    });
    const QString path = dir_.filePath(QStringLiteral("partial.png"));
    QVERIFY(window_->renderImage(path, 1280, 720));
    QVERIFY(view->isVisible());
    QTRY_VERIFY_WITH_TIMEOUT(tiles >= 10, 30000);

    QVERIFY(stillRunning);
    QCOMPARE(shown.size(), QSize(1280, 720));
    const auto [lit, total] = litTiles(shown);
    QVERIFY2(lit >= 5 && lit < total, qPrintable(QStringLiteral("%1 of %2").arg(lit).arg(total)));
    // On screen too: the window paints some rendered pixels and some still black.
    const auto [litOnScreen, _] = litTiles(grabbed);
    QVERIFY(litOnScreen > 0);
    window_->renderQueue()->cancelAll();
    QVERIFY(!QFileInfo::exists(path));
}

void RenderJobTest::closingDuringARender_AsksFirst_ThenCancelsPromptly() {
    makeRendersSlow();
    window_->editor()->undoStack()->setClean();
    const QString path = dir_.filePath(QStringLiteral("closed.png"));
    QVERIFY(window_->renderImage(path, 3840, 2160));
    QVERIFY(window_->renderImage(dir_.filePath(QStringLiteral("queued.png")), 3840, 2160));
    QTest::qWait(300);

    answer_ = false;  // "No": the window stays and so does the render.
    QVERIFY(!window_->close());
    QCOMPARE(questions_.size(), 1);
    QVERIFY2(questions_.first().contains(QStringLiteral("1 more are queued")),
             qPrintable(questions_.first()));
    QVERIFY(window_->renderQueue()->busy());

    answer_ = true;
    QElapsedTimer timer;
    timer.start();
    QVERIFY(window_->close());
    window_.reset();
    const qint64 ms = timer.elapsed();
    QVERIFY2(ms < 5000, qPrintable(QStringLiteral("closing took %1 ms").arg(ms)));
    QCOMPARE(questions_.size(), 2);
    QTest::qWait(200);
    QVERIFY(!QFileInfo::exists(path));
    QVERIFY(!QFileInfo::exists(dir_.filePath(QStringLiteral("queued.png"))));
}

QTEST_MAIN(RenderJobTest)
void RenderJobTest::unsavedChangesPrompt_IsAnswerableWhileRendering() {
    makeRendersSlow();
    QVERIFY(settle(*window_));
    // An unsaved edit, made with the mouse.
    QVERIFY(dragBlueBall(6));
    QVERIFY(!window_->editor()->undoStack()->isClean());
    const QString path = dir_.filePath(QStringLiteral("unsaved.png"));
    QVERIFY(window_->renderImage(path, 3840, 2160));
    QVERIFY(window_->renderQueue()->busy());

    // The save prompt comes up over the designer, not under a progress dialog, and a click
    // on Discard answers it while the render still runs.
    bool answered = false;
    QTimer::singleShot(300, [&] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        QVERIFY(box);
        QVERIFY(window_->renderQueue()->busy());
        QAbstractButton* discard = box->button(QMessageBox::Discard);
        QVERIFY(discard);
        QTest::mouseClick(discard, Qt::LeftButton);
        answered = true;
    });
    answer_ = true;  // and yes, stop the render
    QVERIFY(window_->close());
    QVERIFY(answered);
    window_.reset();
    QTest::qWait(200);
    QVERIFY(!QFileInfo::exists(path));
}

#include "render_job_test.moc"
