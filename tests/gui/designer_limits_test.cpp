// Nothing hangs, nothing terminates, in the designer: Render Image asks before a render over
// the cost budget, and an allocation that fails (in the viewport's session or a Render Image
// job) is reported while the document stays as it was.
#include <sys/resource.h>

#include <QProgressDialog>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>
#include <fstream>

#include "gui_test_support.h"
#include "io/scene_io.h"
#include "shell/error_reporter.h"
#include "shell/responsive_wait.h"
#include "shell/user_confirmation.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class DesignerLimitsTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void renderImageOverBudget_AsksFirst_AndDeclineStartsNothing();
    void renderImageOverAreaLimit_IsRefusedWithMessage();
    void outOfMemory_IsReported_AndDocumentKept();
    void largeScene_OpensAndSaves_WhileTheWindowKeepsTicking();

private:
    std::unique_ptr<MainWindow> window_;
    QStringList errors_;
    QStringList questions_;
    bool answer_ = false;
    QTemporaryDir dir_;
};

void DesignerLimitsTest::init() {
    errors_.clear();
    questions_.clear();
    setErrorHandler(
        [this](const QString& title, const QString& text) { errors_ << title + ": " + text; });
    setConfirmationHandler([this](const QString&, const QString& text) {
        questions_ << text;
        return answer_;
    });
    QVERIFY(openRoomWindow(window_));
}

void DesignerLimitsTest::cleanup() {
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
    setErrorHandler({});
    setConfirmationHandler({});
}

void DesignerLimitsTest::renderImageOverBudget_AsksFirst_AndDeclineStartsNothing() {
    SceneDocument doc = window_->editor()->document();
    doc.render.maxDepth = 44;  // The room's glass and mirrors: about 1e4 rays a sample.
    window_->editor()->edit(QStringLiteral("Deep"), doc);
    const SceneDocument before = window_->editor()->document();
    answer_ = false;
    QVERIFY(!window_->renderImage(dir_.filePath(QStringLiteral("deep.png")), 8000, 8000));
    QCOMPARE(questions_.size(), 1);
    QVERIFY2(questions_.first().contains(QStringLiteral("ray budget")),
             qPrintable(questions_.first()));
    QVERIFY(window_->findChildren<QProgressDialog*>().isEmpty());  // No job was started.
    QVERIFY(window_->editor()->document().sameContent(before));
    // Within the budget nothing is asked.
    QVERIFY(window_->renderImage(dir_.filePath(QStringLiteral("small.png")), 32, 18));
    QCOMPARE(questions_.size(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(dir_.filePath(QStringLiteral("small.png"))), 30000);
}

void DesignerLimitsTest::renderImageOverAreaLimit_IsRefusedWithMessage() {
    answer_ = true;  // Even when the user insists, the area limit holds.
    QVERIFY(window_->renderImage(dir_.filePath(QStringLiteral("huge.png")), 16384, 16384));
    QTRY_COMPARE_WITH_TIMEOUT(errors_.size(), 1, 30000);
    QVERIFY2(errors_.first().contains(QStringLiteral("at most 64 Mpixels")),
             qPrintable(errors_.first()));
    QVERIFY(!QFileInfo::exists(dir_.filePath(QStringLiteral("huge.png"))));
}

void DesignerLimitsTest::outOfMemory_IsReported_AndDocumentKept() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    QSKIP("sanitizers reserve more address space than the limit allows");
#else
    const SceneDocument before = window_->editor()->document();
    const int undoSteps = window_->editor()->undoStack()->count();
    // Half a GiB more address space than the process has now: an 8000 x 8000 render (64
    // Mpixels, within the area limit) and the deep frame of a 6000 x 4000 viewport (24
    // Mpixels) need gigabytes, so their allocations throw bad_alloc.
    // The big window (and its backing store) first, traced at 1/4 while no limit holds.
    window_->viewport()->setPreviewDivider(4);
    window_->viewport()->setFixedSize(6000, 4000);
    QVERIFY(
        QTest::qWaitFor([&] { return window_->viewport()->size() == QSize(6000, 4000); }, 5000));
    QTest::qWait(50);
    rlimit old{};
    QCOMPARE(getrlimit(RLIMIT_AS, &old), 0);
    long pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlimit tight{rlim_t(pages) * 4096 + (rlim_t(1) << 29), old.rlim_max};
    QCOMPARE(setrlimit(RLIMIT_AS, &tight), 0);
    window_->viewport()->setPreviewDivider(1);  // The viewport's session: its deep frame.
    window_->session()->flushUpdate();
    QVERIFY(window_->renderImage(dir_.filePath(QStringLiteral("big.exr")), 8000, 8000));
    const bool reported = QTest::qWaitFor(
        [&] {
            return !errors_.isEmpty() &&
                   window_->statusBar()->currentMessage().contains(QStringLiteral("out of memory"));
        },
        60000);
    setrlimit(RLIMIT_AS, &old);
    int sessionWidth = 0;
    renderSession(*window_).withFrame(
        [&](const DeepFrame& f, const auto&) { sessionWidth = f.width(); });
    QVERIFY2(reported,
             qPrintable(errors_.join('\n') + " | " + window_->statusBar()->currentMessage() +
                        QStringLiteral(" | traced %1x%2, session frame width %3")
                            .arg(window_->viewport()->tracedSize().width())
                            .arg(window_->viewport()->tracedSize().height())
                            .arg(sessionWidth)));
    QVERIFY2(errors_.first().contains(QStringLiteral("out of memory")),
             qPrintable(errors_.first()));
    // The document is as it was, and so is its history.
    QVERIFY(window_->editor()->document().sameContent(before));
    QCOMPARE(window_->editor()->undoStack()->count(), undoSteps);
    // And the viewport renders again at its next size.
    QVERIFY(traceViewport(*window_, QSize(320, 180), 2));
    QCOMPARE(window_->viewport()->frame()->width, 160);
#endif
}

void DesignerLimitsTest::largeScene_OpensAndSaves_WhileTheWindowKeepsTicking() {
    // 20,000 spheres: some 1.6 MB of scene file, read and written off the GUI thread.
    const QString path = dir_.filePath(QStringLiteral("many.scene.json"));
    {
        std::ofstream out(path.toStdString());
        out << R"({"format": "raystudio-scene", "version": 1, "camera": {"position": [0, 2, 8], "target": [0, 0, 0]},)"
            << R"("lights": [{"name": "key", "type": "point", "position": [0, 5, 5]}], "objects": [)";
        for (int i = 0; i < 20000; ++i)
            out << (i ? "," : "") << R"({"name": "ball )" << i
                << R"(", "type": "sphere", "center": [)" << (i % 120) * 0.1 - 6 << ", 0, "
                << (i / 120) * -0.1 << R"(], "radius": 0.04})";
        out << "]}";
    }
    QVERIFY(QFileInfo(path).size() >= kResponsiveFileBytes);
    int ticks = 0;
    QTimer timer;
    timer.setInterval(1);
    QObject::connect(&timer, &QTimer::timeout, [&] { ++ticks; });
    timer.start();
    QVERIFY2(window_->openFile(path), qPrintable(errors_.join(QLatin1Char('\n'))));
    QCOMPARE(window_->editor()->document().objects.size(), std::size_t(20000));
    QCOMPARE(window_->editor()->document().objects[19999].name, std::string("ball 19999"));
    // The GUI thread ran its timers while the file was read.
    QVERIFY2(ticks > 0, "no timer ran while the scene was read");
    const int opened = ticks;

    const QString saved = dir_.filePath(QStringLiteral("saved.scene.json"));
    QVERIFY(window_->saveFile(saved));
    QVERIFY2(ticks > opened, "no timer ran while the scene was written");
    QVERIFY(window_->editor()->undoStack()->isClean());
    const SceneLoadResult back = loadScene(saved.toStdString());
    QVERIFY(back.ok());
    QVERIFY(back.document.sameContent(window_->editor()->document()));

    // A file that cannot be read is still an error, named, with the document kept.
    const QString bad = dir_.filePath(QStringLiteral("bad.scene.json"));
    {
        std::ofstream out(bad.toStdString());
        out << R"({"format": "raystudio-scene", "version": 1, "objects": [)"
            << std::string(1 << 21, ' ') << "{]}";
    }
    QVERIFY(!window_->openFile(bad));
    QCOMPARE(errors_.size(), 1);
    QVERIFY2(errors_.first().contains(QStringLiteral("bad.scene.json")),
             qPrintable(errors_.first()));
    QCOMPARE(window_->editor()->document().objects.size(), std::size_t(20000));
}

QTEST_MAIN(DesignerLimitsTest)
#include "designer_limits_test.moc"
