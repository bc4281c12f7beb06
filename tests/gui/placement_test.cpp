// Placement and import (issue 11, issue 30), with real events: new objects land on the surface
// under the view centre (or on the floor below), a large imported mesh is scaled to the view,
// a mesh dropped at the cursor lands there, an imported asset brings its parts' materials as
// one undo step, and images an import wrote for an unsaved scene go next to it on save.
#include "document/placement.h"

#include <QAction>
#include <QApplication>
#include <QColorDialog>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFormLayout>
#include <QGroupBox>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>
#include <cmath>
#include <functional>

#include "document/transform_edits.h"
#include "gui_test_support.h"
#include "panel_fields.h"
#include "panels/material_list.h"
#include "panels/property_panel.h"
#include "shell/imported_images.h"
#include "snapshot/compiled_scene.h"
#include "viewport/transform_gizmo.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

namespace {

/// A cube of side `size` centred at the origin, as an OBJ file.
bool writeCube(const QString& path, float size) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return false;
    const float h = size / 2;
    QByteArray text;
    for (int i = 0; i < 8; ++i)
        text += QStringLiteral("v %1 %2 %3\n")
                    .arg(i & 1 ? h : -h)
                    .arg(i & 2 ? h : -h)
                    .arg(i & 4 ? h : -h)
                    .toLatin1();
    text += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    return f.write(text) == text.size();
}

}  // namespace

class PlacementTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void newSphere_RestsOnTheFloorInFront_ClearOfTheOthers();
    void snapToFloor_AMeshDroppedOnTheBackWallRestsOnTheFloorBelow();
    void largeMeshImport_IsScaledToFitTheView_AndTheFactorIsEditable();
    void meshImportedAtTheCursor_LandsOnTheSurfaceUnderIt_Unscaled();
    void importedAsset_BringsItsPartsMaterials_AsOneUndoStep();
    void importedAssetOfOneMaterial_PanelEditsThatMaterial_AssignTakesItWhole();
    void importedImagesOfAnUnsavedScene_GoNextToItOnSave();

private:
    const SceneDocument& doc() { return window_->editor()->document(); }
    int undoCount() { return window_->editor()->undoStack()->count(); }
    /// Clicks the Add toolbar's button of action `name` ("add Sphere").
    void clickAdd(const QString& name);

    std::unique_ptr<MainWindow> window_;
};

void PlacementTest::init() {
    QSettings().remove(QStringLiteral("placement/snapToFloor"));
    QVERIFY(openRoomWindow(window_));
}

void PlacementTest::cleanup() {
    QSettings().remove(QStringLiteral("placement/snapToFloor"));
    if (!window_) return;
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

void PlacementTest::clickAdd(const QString& name) {
    auto* tools = window_->findChild<QToolBar*>(QStringLiteral("addToolBar"));
    QVERIFY(tools);
    QAction* action = window_->findChild<QAction*>(name);
    QVERIFY2(action, qPrintable(name));
    QWidget* button = tools->widgetForAction(action);
    QVERIFY(button);
    QTest::mouseClick(button, Qt::LeftButton);
}

void PlacementTest::newSphere_RestsOnTheFloorInFront_ClearOfTheOthers() {
    // Two adds in a row: each on the floor (y = 0) in front of the view, in sight, and
    // neither inside nor on top of another object (the room's balls, or each other).
    for (const char* kind : {"Sphere", "Box"}) {
        clickAdd(QStringLiteral("add %1").arg(QString::fromLatin1(kind)));
        const ObjectId id = window_->editor()->selection();
        QVERIFY(id != kNoObject);
        const Aabb b = worldBounds(doc(), id);
        QVERIFY2(std::abs(b.min.y) < 1e-3f, qPrintable(str(b.min)));
        for (const Object& o : doc().objects)
            if (o.id != id && !std::holds_alternative<PlaneGeometry>(o.geometry))
                QVERIFY2(!worldBounds(doc(), o.id).overlaps(b), o.name.c_str());
        QVERIFY(settle(*window_));
        QVERIFY2(pixelOf(*window_->viewport()->frame(), id).first >= 0, kind);  // In sight.
    }
    QCOMPARE(undoCount(), 2);
}

void PlacementTest::snapToFloor_AMeshDroppedOnTheBackWallRestsOnTheFloorBelow() {
    QAction* snap = window_->findChild<QAction*>(QStringLiteral("snapToFloor"));
    QVERIFY(snap && snap->isCheckable() && !snap->isChecked());
    snap->trigger();
    QVERIFY(snap->isChecked());
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("crate.obj"));
    QVERIFY(writeCube(path, 0.6f));
    // A pixel of the back wall with back wall all round it, up the middle of the frame.
    const DisplayFrame& f = *window_->viewport()->frame();
    const ObjectId wall = idOf(*window_, "back wall");
    const int x = f.width / 2;
    int y = -1;
    for (int row = 4; row < f.height - 4 && y < 0; ++row) {
        bool all = true;
        for (int dy = -3; dy <= 3; ++dy)
            for (int dx = -3; dx <= 3; ++dx) all = all && f.idAt(x + dx, row + dy) == wall;
        if (all) y = row;
    }
    QVERIFY(y >= 0);
    window_->importMesh(path, window_->viewport()->widgetPointOf(x, y));
    QTRY_VERIFY_WITH_TIMEOUT(idOf(*window_, "crate") != kNoObject, 20000);
    const Aabb b = worldBounds(doc(), idOf(*window_, "crate"));
    // Against the wall where it was dropped (z = -12), and down on the floor (y = 0).
    QVERIFY2(std::abs(b.min.y) < 1e-3f, qPrintable(str(b.min)));
    QVERIFY2(std::abs(b.min.z - -12.0f) < 1e-3f, qPrintable(str(b.min)));
    QCOMPARE(undoCount(), 1);
}

void PlacementTest::largeMeshImport_IsScaledToFitTheView_AndTheFactorIsEditable() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("spider.obj"));
    QVERIFY(writeCube(path, 150.0f));
    window_->importMesh(path);
    QTRY_VERIFY_WITH_TIMEOUT(idOf(*window_, "spider") != kNoObject, 20000);
    const ObjectId id = idOf(*window_, "spider");
    QCOMPARE(undoCount(), 1);
    const float factor = doc().findObject(id)->transform.scale.x;
    QVERIFY2(factor > 0.0f && factor < 0.1f, qPrintable(QString::number(factor)));
    QVERIFY(doc().findObject(id)->transform.scale == Vec3(factor));
    QVERIFY2(
        window_->statusBar()->currentMessage().contains(QString::number(double(factor), 'g', 3)),
        qPrintable(window_->statusBar()->currentMessage()));
    // It fits the view: every corner of its bounds projects inside the image, and the view
    // camera stands outside it.
    const Aabb b = worldBounds(doc(), id);
    const Camera& view = window_->viewport()->viewCamera();
    QVERIFY(!(glm::all(glm::greaterThan(view.position, b.min)) &&
              glm::all(glm::lessThan(view.position, b.max))));
    const ViewProjection projection = window_->viewport()->projection();
    const QRect shown = window_->viewport()->rect();
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner(b[i & 1].x, b[(i >> 1) & 1].y, b[(i >> 2) & 1].z);
        const auto p = projection.project(corner);
        QVERIFY2(p && shown.contains(p->toPoint()), qPrintable(str(corner)));
    }
    QVERIFY(settle(*window_));
    QVERIFY(pixelOf(*window_->viewport()->frame(), id).first >= 0);

    // The factor is the Transform's Scale in the property panel: typing one is an undo step.
    QWidget* scale = panelField(*window_, QStringLiteral("Transform"), QStringLiteral("Scale"));
    QVERIFY(scale);
    const auto spins = scale->findChildren<QDoubleSpinBox*>();
    QCOMPARE(spins.size(), 3);
    QCOMPARE(float(spins[0]->value()), factor);
    typeInto(spins[0], QStringLiteral("0.004"));
    QCOMPARE(doc().findObject(id)->transform.scale.x, 0.004f);
    QCOMPARE(undoCount(), 2);
    window_->editor()->undoStack()->undo();
    QCOMPARE(doc().findObject(id)->transform.scale.x, factor);
}

void PlacementTest::meshImportedAtTheCursor_LandsOnTheSurfaceUnderIt_Unscaled() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("crate.obj"));
    QVERIFY(writeCube(path, 0.6f));
    // A floor pixel low in the frame, away from the view centre (the back wall).
    const DisplayFrame& f = *window_->viewport()->frame();
    const ObjectId floor = idOf(*window_, "floor");
    const int x = f.width / 2 + f.width / 8, y = f.height - 4;
    QCOMPARE(f.idAt(x, y), floor);
    const QPoint at = window_->viewport()->widgetPointOf(x, y);
    // What a drop on the viewport does: import onto the surface under the cursor.
    window_->importMesh(path, at);
    QTRY_VERIFY_WITH_TIMEOUT(idOf(*window_, "crate") != kNoObject, 20000);
    const ObjectId id = idOf(*window_, "crate");
    QVERIFY(doc().findObject(id)->transform.scale == Vec3(1.0f));  // It fits: not rescaled.
    const Aabb b = worldBounds(doc(), id);
    QVERIFY2(std::abs(b.min.y) < 1e-3f, qPrintable(str(b.min)));  // On the floor.
    QVERIFY(settle(*window_));
    const ViewProjection view = window_->viewport()->projection();
    const auto shown = view.project(b.center());
    QVERIFY(shown);
    // Its centre appears above the drop point (it stands on the floor there).
    QVERIFY2(std::abs(shown->x() - at.x()) < 0.05 * window_->viewport()->width(),
             qPrintable(QStringLiteral("%1 vs %2").arg(shown->x()).arg(at.x())));
    QVERIFY(shown->y() < at.y());
}

void PlacementTest::importedAsset_BringsItsPartsMaterials_AsOneUndoStep() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    for (const char* name : {"two-tone-box.obj", "two-tone-box.mtl"})
        QVERIFY(QFile::copy(QStringLiteral(RAYSTUDIO_SCENES_DIR "/meshes/") + name,
                            dir.filePath(QString::fromLatin1(name))));
    const std::size_t before = doc().materials.size();
    window_->importMesh(dir.filePath(QStringLiteral("two-tone-box.obj")));
    QTRY_VERIFY_WITH_TIMEOUT(idOf(*window_, "two-tone-box") != kNoObject, 20000);
    const ObjectId id = idOf(*window_, "two-tone-box");
    QCOMPARE(undoCount(), 1);
    // The MTL's two materials, as ordinary ones of the scene, named by the parts.
    QCOMPARE(doc().materials.size(), before + 2);
    const Material* lid = doc().findMaterial("lid");
    QVERIFY(lid && doc().findMaterial("body"));
    QCOMPARE(lid->color, Color(0.2f, 0.45f, 0.7f));
    const auto& parts = std::get<MeshGeometry>(doc().findObject(id)->geometry).partMaterials;
    QCOMPARE(parts, (std::vector<std::string>{"", "body", "lid"}));
    QVERIFY2(window_->statusBar()->currentMessage().contains(QStringLiteral("2 materials")),
             qPrintable(window_->statusBar()->currentMessage()));
    MaterialList* list = window_->materialList();
    QVERIFY(list->setCurrent("lid"));
    // Used by a part: it cannot be deleted, and the reason names the object.
    QVERIFY(!window_->materialList()
                 ->findChild<QPushButton*>(QStringLiteral("deleteMaterial"))
                 ->isEnabled());
    QVERIFY2(list->message().contains(QStringLiteral("\"two-tone-box\"")),
             qPrintable(list->message()));
    // It shows in the frame.
    QVERIFY(settle(*window_));
    const auto [x, y] = pixelOf(*window_->viewport()->frame(), id);
    QVERIFY(x >= 0);
    // Properties list its parts, each with its material; choosing one is an undo step.
    auto* partsBox = window_->findChild<QGroupBox*>(QStringLiteral("parts"));
    QVERIFY(partsBox);
    const auto combos = partsBox->findChildren<QComboBox*>();
    QCOMPARE(combos.size(), 2);
    QCOMPARE(combos[1]->currentText(), QStringLiteral("lid"));
    const int body = combos[1]->findText(QStringLiteral("body"));
    QVERIFY(body > 0);
    combos[1]->setCurrentIndex(body);
    Q_EMIT combos[1]->activated(body);
    QCOMPARE(std::get<MeshGeometry>(doc().findObject(id)->geometry).partMaterials[2],
             std::string("body"));
    QCOMPARE(undoCount(), 2);
    window_->editor()->undoStack()->undo();
    // Undo takes the object and its materials away together.
    window_->editor()->undoStack()->undo();
    QCOMPARE(idOf(*window_, "two-tone-box"), kNoObject);
    QCOMPARE(doc().materials.size(), before);
}
void PlacementTest::importedAssetOfOneMaterial_PanelEditsThatMaterial_AssignTakesItWhole() {
    // An OBJ of one material: its only part has its own, so the panel shows and edits that
    // one, not the object's (which none of its triangles use).
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(writeCube(dir.filePath(QStringLiteral("crate.obj")), 0.6f));
    QFile obj(dir.filePath(QStringLiteral("crate.obj")));
    QVERIFY(obj.open(QIODevice::ReadOnly));
    const QByteArray faces = obj.readAll();
    obj.close();
    QVERIFY(obj.open(QIODevice::WriteOnly));
    obj.write("mtllib crate.mtl\nusemtl paint\n" + faces);
    obj.close();
    QFile mtl(dir.filePath(QStringLiteral("crate.mtl")));
    QVERIFY(mtl.open(QIODevice::WriteOnly));
    mtl.write("newmtl paint\nKd 0.8 0.2 0.1\n");
    mtl.close();
    window_->importMesh(dir.filePath(QStringLiteral("crate.obj")));
    QTRY_VERIFY_WITH_TIMEOUT(idOf(*window_, "crate") != kNoObject, 20000);
    const ObjectId id = idOf(*window_, "crate");
    QCOMPARE(window_->editor()->selection(), id);
    const std::vector<std::string> parts =
        std::get<MeshGeometry>(doc().findObject(id)->geometry).partMaterials;
    QVERIFY(std::count(parts.begin(), parts.end(), std::string("paint")) == 1);

    auto* partsBox = window_->findChild<QGroupBox*>(QStringLiteral("parts"));
    QVERIFY(partsBox);
    const auto combos = partsBox->findChildren<QComboBox*>();
    QCOMPARE(combos.size(), 1);
    QCOMPARE(combos[0]->currentText(), QStringLiteral("paint"));
    auto* usage = window_->propertyPanel()->findChild<QLabel*>(QStringLiteral("materialUsage"));
    QVERIFY(usage);
    QVERIFY2(usage->text().contains(QStringLiteral("own material")), qPrintable(usage->text()));
    // The editable section is the part's material: changing its colour there changes it.
    QVERIFY(panelField(*window_, QStringLiteral("Material \"paint\""), QStringLiteral("Colour")));

    // Assign to Selection gives the whole asset the material: its parts give theirs up.
    const int before = undoCount();
    QVERIFY(window_->materialList()->setCurrent("glass"));
    QTest::mouseClick(
        window_->materialList()->findChild<QPushButton*>(QStringLiteral("assignMaterial")),
        Qt::LeftButton);
    QCOMPARE(undoCount(), before + 1);
    const Object* o = doc().findObject(id);
    QCOMPARE(o->material, std::string("glass"));
    QVERIFY(std::get<MeshGeometry>(o->geometry).partMaterials.empty());
    QVERIFY(!window_->findChild<QGroupBox*>(QStringLiteral("parts")));
    window_->editor()->undoStack()->undo();
    QCOMPARE(std::get<MeshGeometry>(doc().findObject(id)->geometry).partMaterials, parts);
}

// An asset imported before the scene has a file writes its embedded images into the data
// folder; saving the scene copies them next to it and the file refers to the copies.
void PlacementTest::importedImagesOfAnUnsavedScene_GoNextToItOnSave() {
    const QString data = importedImageFolder(QString());
    QVERIFY(QDir().mkpath(data));
    const QString image = data + QStringLiteral("/asset-0.png");
    QImage red(4, 4, QImage::Format_RGB32);
    red.fill(Qt::red);
    QVERIFY(red.save(image));
    SceneDocument edited = doc();
    for (const char* name : {"painted", "painted too"}) {
        Material m;
        m.name = name;
        ImageTexture t;
        t.image.file = t.image.resolvedPath = image.toStdString();
        m.pattern = t;
        edited.materials.push_back(m);
    }
    window_->editor()->edit(QStringLiteral("paint"), std::move(edited));

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // A file of that name is there already: the copy takes the next free name.
    QImage blue(2, 2, QImage::Format_RGB32);
    blue.fill(Qt::blue);
    QVERIFY(blue.save(dir.filePath(QStringLiteral("asset-0.png"))));
    const QString scene = dir.filePath(QStringLiteral("painted.scene.json"));
    QVERIFY(window_->saveFile(scene));
    const QString copy =
        QFileInfo(dir.filePath(QStringLiteral("asset-0-2.png"))).absoluteFilePath();
    QVERIFY(QFileInfo::exists(copy));
    QCOMPARE(QImage(copy).pixelColor(0, 0), QColor(Qt::red));
    for (const char* name : {"painted", "painted too"}) {
        const auto& t = std::get<ImageTexture>(doc().findMaterial(name)->pattern);
        QCOMPARE(QString::fromStdString(t.image.resolvedPath), copy);
    }
    QFile saved(scene);
    QVERIFY(saved.open(QIODevice::ReadOnly));
    const QByteArray text = saved.readAll();
    QVERIFY2(text.contains("\"texture\": \"asset-0-2.png\""), text.constData());
    QVERIFY(!text.contains("imported-images"));
    QVERIFY(window_->editor()->undoStack()->isClean());
    QFile::remove(image);
}

QTEST_MAIN(PlacementTest)
#include "placement_test.moc"
