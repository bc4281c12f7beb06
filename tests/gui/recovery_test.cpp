// Nothing lost: a designer killed with SIGKILL after an edit offers exactly that edit at the
// next start, a clean exit leaves no autosave, and a kill during a save never leaves a scene
// file that does not parse. The killed designers are this binary re-run in a child mode.
#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>
#include <csignal>
#include <cstdio>
#include <cstring>

#include "document/scene_editor.h"
#include "document/scene_file_writer.h"
#include "io/scene_io.h"
#include "shell/autosave.h"
#include "shell/main_window.h"

using namespace rs;
using namespace rs::ui;

namespace {

const char* const kRenamed = "recovered blue ball";

QString roomPath() {
    return QStringLiteral(RAYSTUDIO_SCENES_DIR "/reference-room.scene.json");
}

void useTestNames() {
    QCoreApplication::setOrganizationName(QStringLiteral("RayStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("RayStudioRecoveryTests"));
}

/// The room with "blue ball" renamed: the edit the killed designer makes.
SceneDocument editedRoom(const SceneDocument& room) {
    SceneDocument doc = room;
    for (Object& o : doc.objects.editable())
        if (o.name == "blue ball") o.name = kRenamed;
    return doc;
}

/// Child: a designer that opens `scene`, makes one edit, waits for its autosave, says so and
/// then waits to be killed (or, with `quit`, saves and exits cleanly).
int childEdit(int argc, char** argv, const QString& scene, bool quit) {
    QApplication app(argc, argv);
    useTestNames();
    MainWindow window;
    window.setAutosaveIntervalMs(50);
    window.show();
    if (!window.openFile(scene)) return 3;
    window.editor()->edit(QStringLiteral("Rename"), editedRoom(window.editor()->document()));
    const QString autosave = window.autosave()->path();
    QDeadlineTimer deadline(30000);
    while (!QFileInfo::exists(autosave) && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    if (!QFileInfo::exists(autosave)) return 4;
    std::printf("autosaved %s\n", qPrintable(autosave));
    std::fflush(stdout);
    if (quit) {
        if (!window.saveFile(scene)) return 5;
        window.close();
        return 0;
    }
    return app.exec();
}

/// Child: saves two versions of a big scene (n and n + 1 spheres) in turn, for ever.
int childSaveLoop(const QString& path, int n) {
    SceneDocument a;
    for (int i = 0; i < n; ++i) {
        Object o;
        o.name = "ball " + std::to_string(i);
        o.geometry = SphereGeometry{Vec3(float(i % 100), float(i / 100), -5.0f), 0.25f};
        a.addObject(std::move(o));
    }
    SceneDocument b = a;
    Object extra;
    extra.name = "extra";
    extra.geometry = SphereGeometry{};
    b.addObject(std::move(extra));
    for (long i = 0;; ++i) {
        QString error;
        if (!writeSceneFile(path, i % 2 ? b : a, error)) return 3;
        if (i == 0) {
            std::printf("saved\n");
            std::fflush(stdout);
        }
    }
}

/// Starts this binary in a child mode and waits for its first line.
bool startChild(QProcess& child, const QStringList& args, QByteArray* line = nullptr) {
    child.setProgram(QCoreApplication::applicationFilePath());
    child.setArguments(args);
    child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    child.start();
    if (!child.waitForStarted(10000)) return false;
    QDeadlineTimer deadline(60000);
    while (!child.canReadLine() && !deadline.hasExpired() && child.state() == QProcess::Running)
        child.waitForReadyRead(100);
    if (!child.canReadLine()) return false;
    const QByteArray first = child.readLine().trimmed();
    if (line) *line = first;
    return true;
}

void killHard(QProcess& child) {
    ::kill(pid_t(child.processId()), SIGKILL);
    child.waitForFinished(10000);
}

}  // namespace

class RecoveryTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void killedAfterEdit_NextStartOffersThatEdit();
    void cleanExit_LeavesNothingToRecover();
    void discard_RemovesTheAutosave();
    void killDuringSave_LeavesOldOrNewFile();

private:
    QTemporaryDir files_;
};

void RecoveryTest::init() {
    // No orphans of an earlier test (or run) in the shared state folder.
    QDir(Autosave::folder()).removeRecursively();
}

void RecoveryTest::killedAfterEdit_NextStartOffersThatEdit() {
    const QString scene = files_.filePath(QStringLiteral("room.scene.json"));
    QFile::remove(scene);
    QVERIFY(QFile::copy(roomPath(), scene));
    QProcess child;
    QByteArray line;
    QVERIFY(startChild(child, {QStringLiteral("--child-edit"), scene}, &line));
    QVERIFY2(line.startsWith("autosaved "), line.constData());
    killHard(child);
    QCOMPARE(child.exitStatus(), QProcess::CrashExit);

    MainWindow window;
    QVERIFY(window.openFile(roomPath()));  // What a start opens before it offers recovery.
    QVERIFY(window.offerRecovery(MainWindow::RecoveryAnswer::Recover));
    const SceneLoadResult saved = loadScene(scene.toStdString());
    QVERIFY(saved.ok());
    // Exactly the edit: the saved file plus the rename, nothing else.
    QVERIFY(window.editor()->document().sameContent(editedRoom(saved.document)));
    QVERIFY(!window.editor()->document().sameContent(saved.document));
    QCOMPARE(window.editor()->filePath(), QFileInfo(scene).absoluteFilePath());
    QVERIFY(!window.editor()->undoStack()->isClean());
    window.editor()->undoStack()->undo();
    QVERIFY(window.editor()->document().sameContent(saved.document));
    // Recovered once: the next start has nothing left to offer.
    QVERIFY(!window.offerRecovery(MainWindow::RecoveryAnswer::Recover));
    window.editor()->undoStack()->setClean();
}

void RecoveryTest::cleanExit_LeavesNothingToRecover() {
    const QString scene = files_.filePath(QStringLiteral("clean.scene.json"));
    QFile::remove(scene);
    QVERIFY(QFile::copy(roomPath(), scene));
    QFile::setPermissions(scene, QFile::ReadOwner | QFile::WriteOwner);
    QProcess child;
    QByteArray line;
    QVERIFY(startChild(child, {QStringLiteral("--child-edit-quit"), scene}, &line));
    QVERIFY2(line.startsWith("autosaved "), line.constData());
    QVERIFY(child.waitForFinished(30000));
    QCOMPARE(child.exitStatus(), QProcess::NormalExit);
    QCOMPARE(child.exitCode(), 0);
    QVERIFY(Autosave::orphans().empty());
    QVERIFY(QDir(Autosave::folder()).entryList(QDir::Files).isEmpty());
}

void RecoveryTest::discard_RemovesTheAutosave() {
    const QString scene = files_.filePath(QStringLiteral("discard.scene.json"));
    QFile::remove(scene);
    QVERIFY(QFile::copy(roomPath(), scene));
    QProcess child;
    QVERIFY(startChild(child, {QStringLiteral("--child-edit"), scene}));
    killHard(child);
    QCOMPARE(Autosave::orphans().size(), std::size_t(1));
    MainWindow window;
    QVERIFY(!window.offerRecovery(MainWindow::RecoveryAnswer::Discard));
    QVERIFY(Autosave::orphans().empty());
    QVERIFY(!window.offerRecovery(MainWindow::RecoveryAnswer::Recover));
}

void RecoveryTest::killDuringSave_LeavesOldOrNewFile() {
    const QString path = files_.filePath(QStringLiteral("big.scene.json"));
    constexpr int kSpheres = 20000;
    QRandomGenerator random(12);
    for (int round = 0; round < 12; ++round) {
        QProcess child;
        QVERIFY(startChild(child,
                           {QStringLiteral("--child-save-loop"), path, QString::number(kSpheres)}));
        QThread::msleep(random.bounded(5, 120));
        killHard(child);
        const SceneLoadResult r = loadScene(path.toStdString());
        QVERIFY2(r.ok(), r.errorText().c_str());
        QVERIFY(r.document.objects.size() == kSpheres || r.document.objects.size() == kSpheres + 1);
    }
}

int main(int argc, char** argv) {
    // Parent and children share a state and settings folder of their own (never the user's):
    // the children inherit these variables.
    if (qEnvironmentVariableIsEmpty("RAYSTUDIO_RECOVERY_TEST_HOME")) {
        static QTemporaryDir home;
        qputenv("RAYSTUDIO_RECOVERY_TEST_HOME", home.path().toUtf8());
        qputenv("XDG_DATA_HOME", (home.path() + QStringLiteral("/data")).toUtf8());
        qputenv("XDG_CONFIG_HOME", (home.path() + QStringLiteral("/config")).toUtf8());
        qputenv("XDG_STATE_HOME", (home.path() + QStringLiteral("/state")).toUtf8());
    }
    if (argc >= 3 && std::strcmp(argv[1], "--child-edit") == 0)
        return childEdit(1, argv, QString::fromLocal8Bit(argv[2]), false);
    if (argc >= 3 && std::strcmp(argv[1], "--child-edit-quit") == 0)
        return childEdit(1, argv, QString::fromLocal8Bit(argv[2]), true);
    if (argc >= 4 && std::strcmp(argv[1], "--child-save-loop") == 0)
        return childSaveLoop(QString::fromLocal8Bit(argv[2]), std::atoi(argv[3]));
    QApplication app(argc, argv);
    useTestNames();
    RecoveryTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "recovery_test.moc"
