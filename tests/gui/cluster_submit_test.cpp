// Render -> Submit to Cluster (issue 14), offscreen: the entry exists only where sbatch is on
// PATH; the dialog saves the scene first, runs `raystudio-cli farm submit` with its fields and
// shows the job ids and where the merged image appears, or the scheduler's refusal. sbatch
// here is a script that records its arguments and answers like sbatch --parsable; the real
// scheduler is exercised by tests/cluster/slurm_farm_test.sh.
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

#include "gui_test_support.h"
#include "jobs/cluster_submit_dialog.h"
#include "shell/user_confirmation.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

namespace {

/// Every action in the window's menus, by text.
QStringList menuTexts(const MainWindow& w) {
    QStringList texts;
    for (QAction* menu : w.menuBar()->actions())
        if (menu->menu())
            for (QAction* a : menu->menu()->actions()) texts << a->text();
    return texts;
}

}  // namespace

class ClusterSubmitTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void menuEntry_OnlyWhereSbatchIsOnPath();
    void submit_RunsFarmSubmitWithTheFields_AndShowsJobIdsAndWhereTheResultAppears();
    void submit_SchedulerRefusal_IsShownNotHidden();
    void unsavedScene_IsSavedFirstOrNothingIsSubmitted();

private:
    /// Puts a recording sbatch (answering `firstId`, then firstId + 1; or failing) and
    /// raystudio-cli on PATH.
    void installSbatch(bool fail = false);
    QString sbatchLog() const;

    QTemporaryDir dir_;
    QByteArray savedPath_;
    QStringList questions_;
    bool answer_ = true;
};

void ClusterSubmitTest::init() {
    savedPath_ = qgetenv("PATH");
    questions_.clear();
    answer_ = true;
    setConfirmationHandler([this](const QString&, const QString& text) {
        questions_ << text;
        return answer_;
    });
}

void ClusterSubmitTest::cleanup() {
    qputenv("PATH", savedPath_);
    setConfirmationHandler({});
}

void ClusterSubmitTest::installSbatch(bool fail) {
    const QString bin = dir_.filePath("bin");
    QDir().mkpath(bin);
    QFile script(bin + "/sbatch");
    QVERIFY(script.open(QIODevice::WriteOnly | QIODevice::Truncate));
    const QString log = dir_.filePath("sbatch.log");
    script.write(fail ? QByteArray("#!/bin/sh\necho 'sbatch: error: invalid partition specified: "
                                   "nope' >&2\nexit 1\n")
                      : ("#!/bin/sh\necho \"$@\" >> '" + log.toUtf8() + "'\nn=$(wc -l < '" +
                         log.toUtf8() + "')\necho $((4241 + n))\n"));
    script.close();
    script.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    qputenv("PATH", (bin + ":" RAYSTUDIO_CLI_DIR ":").toUtf8() + savedPath_);
}

QString ClusterSubmitTest::sbatchLog() const {
    QFile f(dir_.filePath("sbatch.log"));
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

void ClusterSubmitTest::menuEntry_OnlyWhereSbatchIsOnPath() {
    qputenv("PATH", "/nonexistent");
    QVERIFY(!clusterSubmitAvailable());
    {
        MainWindow w;
        QVERIFY(!menuTexts(w).contains("Submit to &Cluster..."));
    }
    installSbatch();
    QVERIFY(clusterSubmitAvailable());
    MainWindow w;
    QVERIFY(menuTexts(w).contains("Submit to &Cluster..."));
}

void ClusterSubmitTest::
    submit_RunsFarmSubmitWithTheFields_AndShowsJobIdsAndWhereTheResultAppears() {
    installSbatch();
    std::unique_ptr<MainWindow> w;
    QVERIFY(openRoomWindow(w));
    const QString scene = dir_.filePath("room.scene.json");
    QVERIFY(w->saveFile(scene));
    ClusterSubmitDialog* dialog = w->submitToClusterDialog();
    QVERIFY(dialog);
    QVERIFY(questions_.isEmpty());  // saved and clean: nothing to ask
    const QString out = dir_.filePath("poster.png");
    dialog->findChild<QLineEdit*>("clusterOutput")->setText(out);
    dialog->findChild<QSpinBox*>("clusterParts")->setValue(3);
    dialog->findChild<QLineEdit*>("clusterPartition")->setText("debug");
    dialog->findChild<QLineEdit*>("clusterTime")->setText("10:00");
    const QString note = dialog->findChild<QLabel*>("clusterNote")->text();
    QVERIFY2(note.contains(out) && note.contains("every node"), qPrintable(note));

    QSignalSpy finished(dialog, &ClusterSubmitDialog::submissionFinished);
    QTest::mouseClick(dialog->findChild<QPushButton*>("clusterSubmit"), Qt::LeftButton);
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.first().first().toBool(), true);
    const QString result = dialog->resultText();
    QVERIFY2(result.contains("render job 4242: 3 parts") &&
                 result.contains("merge job 4243: writes " + out),
             qPrintable(result));
    const QString log = sbatchLog();
    QVERIFY2(log.contains("--parsable " + out + ".parts/render.sbatch"), qPrintable(log));
    QVERIFY2(log.contains("--dependency=afterok:4242 " + out + ".parts/merge.sbatch"),
             qPrintable(log));
    QFile render(out + ".parts/render.sbatch");
    QVERIFY(render.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(render.readAll());
    for (const char* line : {"#SBATCH --array=0-2", "#SBATCH --partition=debug",
                             "#SBATCH --time=10:00", "'--width' '160' '--height' '90'"})
        QVERIFY2(text.contains(line), qPrintable(line + QString("\n") + text));
    QVERIFY(text.contains(scene));
    w->editor()->undoStack()->setClean();
}

void ClusterSubmitTest::submit_SchedulerRefusal_IsShownNotHidden() {
    installSbatch(true);
    std::unique_ptr<MainWindow> w;
    QVERIFY(openRoomWindow(w));
    QVERIFY(w->saveFile(dir_.filePath("refused.scene.json")));
    ClusterSubmitDialog* dialog = w->submitToClusterDialog();
    QVERIFY(dialog);
    QSignalSpy finished(dialog, &ClusterSubmitDialog::submissionFinished);
    dialog->submit();
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.first().first().toBool(), false);
    QVERIFY2(dialog->resultText().contains("Not submitted") &&
                 dialog->resultText().contains("invalid partition specified"),
             qPrintable(dialog->resultText()));
}

void ClusterSubmitTest::unsavedScene_IsSavedFirstOrNothingIsSubmitted() {
    installSbatch();
    std::unique_ptr<MainWindow> w;
    QVERIFY(openRoomWindow(w));
    const QString scene = dir_.filePath("edited.scene.json");
    QVERIFY(w->saveFile(scene));
    SceneDocument doc = w->editor()->document();
    doc.render.maxDepth += 1;
    w->editor()->edit("deeper", doc);
    QVERIFY(!w->editor()->undoStack()->isClean());
    answer_ = false;
    QVERIFY(w->submitToClusterDialog() == nullptr);
    QCOMPARE(questions_.size(), 1);
    QVERIFY(questions_.first().contains("Save the scene first?"));
    answer_ = true;
    QVERIFY(w->submitToClusterDialog() != nullptr);
    QVERIFY(w->editor()->undoStack()->isClean());  // saved: the nodes read what is shown
}

QTEST_MAIN(ClusterSubmitTest)
#include "cluster_submit_test.moc"
