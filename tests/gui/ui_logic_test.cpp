// The designer's logic that needs no window: where the default scene is found.
#include "default_scene.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

using namespace rs;
using namespace rs::ui;

class UiLogicTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void defaultScene_BuildTree_FoundFromAnyExecutableFolder();
    void defaultScene_Installed_PrefersShareNextToTheExecutable();
};

void UiLogicTest::defaultScene_BuildTree_FoundFromAnyExecutableFolder() {
    // No installed copy beside a temporary folder: the source tree the build came from.
    QTemporaryDir dir;
    const QString expected =
        QFileInfo(QStringLiteral(RAYSTUDIO_SCENES_DIR "/reference-room.scene.json")).canonicalFilePath();
    QVERIFY(!expected.isEmpty());
    QCOMPARE(defaultScenePath(dir.path()), expected);
    QCOMPARE(defaultScenePath(QCoreApplication::applicationDirPath()), expected);
}

void UiLogicTest::defaultScene_Installed_PrefersShareNextToTheExecutable() {
    QTemporaryDir prefix;
    QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("bin")));
    QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("share/raystudio/scenes")));
    const QString installed = prefix.filePath(QStringLiteral("share/raystudio/scenes/reference-room.scene.json"));
    QVERIFY(QFile::copy(QStringLiteral(RAYSTUDIO_SCENES_DIR "/reference-room.scene.json"), installed));
    QCOMPARE(defaultScenePath(prefix.filePath(QStringLiteral("bin"))), QFileInfo(installed).canonicalFilePath());
}

QTEST_GUILESS_MAIN(UiLogicTest)
#include "ui_logic_test.moc"
