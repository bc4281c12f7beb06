// The designer's Qt-free-ish logic without a window: names for duplicates, the default scene.
#include "default_scene.h"
#include "scene_edits.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

using namespace rs;
using namespace rs::ui;

namespace {

ObjectId addBall(SceneDocument& doc, const std::string& name) {
    Object o;
    o.name = name;
    o.geometry = SphereGeometry{};
    return doc.addObject(std::move(o));
}

std::string nameOf(const SceneDocument& doc, ObjectId id) {
    if (const Object* o = doc.findObject(id)) return o->name;
    if (const Light* l = doc.findLight(id)) return l->name;
    return {};
}

}  // namespace

class UiLogicTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void duplicate_CountsOnFromTheCopysNumber();
    void duplicate_NamesWithoutAPlainNumberGetOneAppended();
    void defaultScene_BuildTree_FoundFromAnyExecutableFolder();
    void defaultScene_Installed_PrefersShareNextToTheExecutable();
};

void UiLogicTest::duplicate_CountsOnFromTheCopysNumber() {
    SceneDocument doc;
    const ObjectId wall = addBall(doc, "right wall");
    const ObjectId wall2 = duplicate(doc, wall);
    QCOMPARE(nameOf(doc, wall2), std::string("right wall 2"));
    QCOMPARE(nameOf(doc, duplicate(doc, wall2)), std::string("right wall 3"));
    // Not "right wall 2 2", and not a number already taken.
    QCOMPARE(nameOf(doc, duplicate(doc, wall2)), std::string("right wall 4"));
    QCOMPARE(nameOf(doc, duplicate(doc, wall)), std::string("right wall 5"));

    // The copy of "ball 9" alone is "ball 10"; lights count the same way.
    const ObjectId ball9 = addBall(doc, "ball 9");
    QCOMPARE(nameOf(doc, duplicate(doc, ball9)), std::string("ball 10"));
    Light l;
    l.name = "key 2";
    const ObjectId key2 = doc.addLight(l);
    QCOMPARE(nameOf(doc, duplicate(doc, key2)), std::string("key 3"));
}

void UiLogicTest::duplicate_NamesWithoutAPlainNumberGetOneAppended() {
    SceneDocument doc;
    for (const char* name : {"sphere", "pi 3.14", "take 02", "room -1", "7"}) {
        const ObjectId id = addBall(doc, name);
        QCOMPARE(nameOf(doc, duplicate(doc, id)), std::string(name) + " 2");
    }
    QCOMPARE(uniqueName(doc, "fresh"), std::string("fresh"));
}

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
