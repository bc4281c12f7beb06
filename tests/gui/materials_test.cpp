// Placement and materials (issue 11), with real events: new objects land on the surface
// under the view centre (or on the floor below), a large imported mesh is scaled to the view,
// the material list's edits are undo steps, HDR colours reach the frame, and the colour
// dialog previews live (Cancel restores, OK is one undo step).
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

#include "document/placement.h"
#include "document/transform_edits.h"
#include "gui_test_support.h"
#include "panels/material_list.h"
#include "panels/property_panel.h"
#include "shell/imported_images.h"
#include "snapshot/compiled_scene.h"
#include "viewport/transform_gizmo.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

namespace {

QString str(const Vec3& v) {
    return QStringLiteral("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z);
}

/// Mean linear colour of the pixels showing `id`.
Vec3 meanColourOf(const DisplayFrame& f, ObjectId id) {
    Vec3 sum(0.0f);
    int n = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            if (f.idAt(x, y) == id) sum += f.color[std::size_t(y) * f.width + x], ++n;
    return n ? sum / float(n) : Vec3(-1.0f);
}

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

class MaterialsTest : public QObject {
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
    void importedImagesOfAnUnsavedScene_GoNextToItOnSave();
    void newAndDuplicateMaterial_EachOneUndoStep();
    void renameMaterial_InPlace_RenamesItsUsers_AndRefusesTakenOrEmptyNames();
    void deleteMaterial_UsedIsRefusedWithTheReason_UnusedIsOneUndoStep();
    void assignToSelection_IsOneUndoStep_AndReachesTheFrame();
    void hdrValueBeyondOne_ReachesTheDocumentAndTheFrame();
    void colourDialog_PreviewsLive_OkIsOneUndoStep();
    void colourDialog_Cancel_RestoresAndLeavesNoUndoStep();

private:
    const SceneDocument& doc() { return window_->editor()->document(); }
    int undoCount() { return window_->editor()->undoStack()->count(); }
    /// Clicks the Add toolbar's button of action `name` ("add Sphere").
    void clickAdd(const QString& name);
    /// Clicks `name` in the viewport (a real press and release on its pixels).
    void clickObject(const std::string& name);
    QPushButton* materialButton(const char* name);
    /// The widget of row `label` in the property panel's group titled `group`.
    QWidget* propertyField(const QString& group, const QString& label);
    /// Replaces the text of `spin` by typing `text` and Enter.
    static void typeInto(QDoubleSpinBox* spin, const QString& text);
    /// Opens the colour dialog of the selection's material, runs `inDialog` in it, then
    /// clicks `button` (Ok or Cancel).
    void withColourDialog(const std::function<void(QColorDialog*)>& inDialog,
                          QDialogButtonBox::StandardButton button);

    std::unique_ptr<MainWindow> window_;
};

void MaterialsTest::init() {
    QSettings().remove(QStringLiteral("placement/snapToFloor"));
    QVERIFY(openRoomWindow(window_));
}

void MaterialsTest::cleanup() {
    QSettings().remove(QStringLiteral("placement/snapToFloor"));
    if (!window_) return;
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

void MaterialsTest::clickAdd(const QString& name) {
    auto* tools = window_->findChild<QToolBar*>(QStringLiteral("addToolBar"));
    QVERIFY(tools);
    QAction* action = window_->findChild<QAction*>(name);
    QVERIFY2(action, qPrintable(name));
    QWidget* button = tools->widgetForAction(action);
    QVERIFY(button);
    QTest::mouseClick(button, Qt::LeftButton);
}

void MaterialsTest::clickObject(const std::string& name) {
    // A pixel of the object that no handle of the gizmo shown now covers (a click there
    // would grab the handle, as in Blender).
    const ObjectId id = idOf(*window_, name);
    const DisplayFrame& f = *window_->viewport()->frame();
    const auto gizmo = window_->viewport()->gizmo();
    QPoint at(-1, -1);
    for (int y = 0; y < f.height && at.x() < 0; ++y)
        for (int x = 0; x < f.width && at.x() < 0; ++x) {
            if (f.idAt(x, y) != id) continue;
            const QPoint p = window_->viewport()->widgetPointOf(x, y);
            if (!gizmo || !gizmo->handleAt(QPointF(p))) at = p;
        }
    QVERIFY2(at.x() >= 0, name.c_str());
    QTest::mouseClick(window_->viewport(), Qt::LeftButton, {}, at);
    QCOMPARE(window_->editor()->selection(), id);
}

QPushButton* MaterialsTest::materialButton(const char* name) {
    return window_->materialList()->findChild<QPushButton*>(QString::fromLatin1(name));
}

QWidget* MaterialsTest::propertyField(const QString& group, const QString& label) {
    for (QGroupBox* box : window_->propertyPanel()->findChildren<QGroupBox*>()) {
        if (!box->title().startsWith(group)) continue;
        auto* form = qobject_cast<QFormLayout*>(box->layout());
        for (int row = 0; form && row < form->rowCount(); ++row) {
            auto* l = form->itemAt(row, QFormLayout::LabelRole);
            auto* f = form->itemAt(row, QFormLayout::FieldRole);
            if (l && f && qobject_cast<QLabel*>(l->widget()) &&
                qobject_cast<QLabel*>(l->widget())->text() == label)
                return f->widget();
        }
    }
    return nullptr;
}

void MaterialsTest::typeInto(QDoubleSpinBox* spin, const QString& text) {
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, text);
    QTest::keyClick(spin, Qt::Key_Return);
}

void MaterialsTest::withColourDialog(const std::function<void(QColorDialog*)>& inDialog,
                                     QDialogButtonBox::StandardButton button) {
    QWidget* field = propertyField(QStringLiteral("Material \""), QStringLiteral("Colour"));
    QVERIFY(field);
    auto* open = field->findChild<QPushButton*>(QStringLiteral("colorButton"));
    QVERIFY(open);
    bool ran = false;
    QTimer::singleShot(0, this, [&] {
        auto* dialog = qobject_cast<QColorDialog*>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        ran = true;
        inDialog(dialog);
        QPushButton* b = dialog->findChild<QDialogButtonBox*>()->button(button);
        QTest::mouseClick(b, Qt::LeftButton);
        if (dialog->isVisible()) dialog->reject();  // Never leave the test stuck in exec().
    });
    QTest::mouseClick(open, Qt::LeftButton);  // Returns when the dialog closes.
    QVERIFY(ran);
}

void MaterialsTest::newSphere_RestsOnTheFloorInFront_ClearOfTheOthers() {
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

void MaterialsTest::snapToFloor_AMeshDroppedOnTheBackWallRestsOnTheFloorBelow() {
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

void MaterialsTest::largeMeshImport_IsScaledToFitTheView_AndTheFactorIsEditable() {
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
    QWidget* scale = propertyField(QStringLiteral("Transform"), QStringLiteral("Scale"));
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

void MaterialsTest::meshImportedAtTheCursor_LandsOnTheSurfaceUnderIt_Unscaled() {
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

void MaterialsTest::importedAsset_BringsItsPartsMaterials_AsOneUndoStep() {
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
    QVERIFY(!materialButton("deleteMaterial")->isEnabled());
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

// An asset imported before the scene has a file writes its embedded images into the data
// folder; saving the scene copies them next to it and the file refers to the copies.
void MaterialsTest::importedImagesOfAnUnsavedScene_GoNextToItOnSave() {
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

void MaterialsTest::newAndDuplicateMaterial_EachOneUndoStep() {
    MaterialList* list = window_->materialList();
    const std::size_t before = doc().materials.size();
    QTest::mouseClick(materialButton("newMaterial"), Qt::LeftButton);
    QCOMPARE(doc().materials.size(), before + 1);
    QCOMPARE(doc().materials.back().name, std::string("material"));
    QCOMPARE(list->current(), std::string("material"));
    QCOMPARE(list->list()->count(), int(before + 1));
    QCOMPARE(undoCount(), 1);
    // The Edit menu reads "Undo Add material "material"", not "Undo New material material".
    QCOMPARE(window_->editor()->undoStack()->undoText(),
             QStringLiteral("Add material \"material\""));

    QVERIFY(list->setCurrent("orange plastic"));
    QTest::mouseClick(materialButton("duplicateMaterial"), Qt::LeftButton);
    QCOMPARE(window_->editor()->undoStack()->undoText(),
             QStringLiteral("Duplicate material \"orange plastic\""));
    QCOMPARE(doc().materials.size(), before + 2);
    const Material& copy = doc().materials.back();
    QCOMPARE(copy.name, std::string("orange plastic 2"));
    Material renamed = *doc().findMaterial("orange plastic");
    renamed.name = copy.name;
    QVERIFY(copy == renamed);
    QCOMPARE(undoCount(), 2);

    window_->editor()->undoStack()->undo();
    QCOMPARE(doc().materials.size(), before + 1);
    window_->editor()->undoStack()->undo();
    QCOMPARE(doc().materials.size(), before);
    QCOMPARE(list->list()->count(), int(before));
}

void MaterialsTest::renameMaterial_InPlace_RenamesItsUsers_AndRefusesTakenOrEmptyNames() {
    MaterialList* list = window_->materialList();
    QVERIFY(list->setCurrent("blue plastic"));
    auto rename = [&](const QString& text) {
        QTest::mouseClick(materialButton("renameMaterial"), Qt::LeftButton);
        auto* editor = list->list()->findChild<QLineEdit*>();
        QVERIFY(editor);
        editor->selectAll();
        if (!text.isEmpty())
            QTest::keyClicks(editor, text);
        else
            QTest::keyClick(editor, Qt::Key_Delete);
        QTest::keyClick(editor, Qt::Key_Return);
    };
    rename(QStringLiteral("cobalt"));
    QTRY_VERIFY(doc().findMaterial("cobalt"));
    QVERIFY(!doc().findMaterial("blue plastic"));
    QCOMPARE(doc().findObject(idOf(*window_, "blue ball"))->material, std::string("cobalt"));
    QCOMPARE(undoCount(), 1);
    QCOMPARE(list->current(), std::string("cobalt"));

    // Names are unique among the materials and non-empty (scenes/FORMAT.md).
    rename(QStringLiteral("glass"));
    QTRY_VERIFY(list->message().contains(QStringLiteral("already named")));
    QVERIFY(doc().findMaterial("cobalt"));
    QCOMPARE(list->list()->currentItem()->text(), QStringLiteral("cobalt"));
    rename(QString());
    QTRY_VERIFY(list->message().contains(QStringLiteral("must not be empty")));
    QVERIFY(doc().findMaterial("cobalt"));
    QCOMPARE(undoCount(), 1);

    window_->editor()->undoStack()->undo();
    QVERIFY(doc().findMaterial("blue plastic"));
    QCOMPARE(doc().findObject(idOf(*window_, "blue ball"))->material, std::string("blue plastic"));
}

void MaterialsTest::deleteMaterial_UsedIsRefusedWithTheReason_UnusedIsOneUndoStep() {
    MaterialList* list = window_->materialList();
    QPushButton* del = materialButton("deleteMaterial");
    const std::size_t before = doc().materials.size();
    QVERIFY(list->setCurrent("mirror"));
    QVERIFY(!del->isEnabled());
    QVERIFY2(list->message().contains(QStringLiteral("\"mirror ball\"")),
             qPrintable(list->message()));
    QVERIFY(del->toolTip().contains(QStringLiteral("is used by")));
    QTest::mouseClick(del, Qt::LeftButton);
    list->deleteMaterial();  // Refused even when called directly.
    QCOMPARE(doc().materials.size(), before);
    QCOMPARE(undoCount(), 0);

    QTest::mouseClick(materialButton("newMaterial"), Qt::LeftButton);
    QVERIFY(del->isEnabled());
    QTest::mouseClick(del, Qt::LeftButton);
    QCOMPARE(doc().materials.size(), before);
    QVERIFY(!doc().findMaterial("material"));
    QCOMPARE(undoCount(), 2);
    window_->editor()->undoStack()->undo();
    QVERIFY(doc().findMaterial("material"));
}

void MaterialsTest::assignToSelection_IsOneUndoStep_AndReachesTheFrame() {
    MaterialList* list = window_->materialList();
    QPushButton* assign = materialButton("assignMaterial");
    QVERIFY(list->setCurrent("red wall"));
    QVERIFY(!assign->isEnabled());  // Nothing selected.
    // Picking an object shows its material in the list, as Blender's slots do...
    clickObject("chalk ball");
    QCOMPARE(list->current(), std::string("chalk"));
    clickObject("blue ball");
    QCOMPARE(list->current(), std::string("blue plastic"));
    clickObject("chalk ball");
    QCOMPARE(list->current(), std::string("chalk"));
    // ...then picking another material and Assign gives it to the selection.
    QVERIFY(list->setCurrent("red wall"));
    QVERIFY(assign->isEnabled());
    const ObjectId id = idOf(*window_, "chalk ball");
    const Vec3 chalk = meanColourOf(*window_->viewport()->frame(), id);
    QTest::mouseClick(assign, Qt::LeftButton);
    QCOMPARE(doc().findObject(id)->material, std::string("red wall"));
    QCOMPARE(undoCount(), 1);
    QVERIFY(settle(*window_));
    const Vec3 red = meanColourOf(*window_->viewport()->frame(), id);
    QVERIFY2(red.x > 2.0f * red.z && !(chalk.x > 2.0f * chalk.z),
             qPrintable(str(chalk) + str(red)));
    window_->editor()->undoStack()->undo();
    QCOMPARE(doc().findObject(id)->material, std::string("chalk"));
}

void MaterialsTest::hdrValueBeyondOne_ReachesTheDocumentAndTheFrame() {
    clickObject("blue ball");
    const ObjectId id = idOf(*window_, "blue ball");
    const Vec3 colour = doc().findMaterial("blue plastic")->color;
    const float value = std::max({colour.x, colour.y, colour.z});
    QVERIFY(value <= 1.0f);
    const Vec3 before = meanColourOf(*window_->viewport()->frame(), id);
    QWidget* field = propertyField(QStringLiteral("Material \""), QStringLiteral("Colour"));
    QVERIFY(field);
    auto* spin = field->findChild<QDoubleSpinBox*>(QStringLiteral("colorValue"));
    QVERIFY(spin);
    QCOMPARE(float(spin->value()), value);
    typeInto(spin, QStringLiteral("%1").arg(double(value) * 4.0));
    const Vec3 now = doc().findMaterial("blue plastic")->color;
    QVERIFY2(glm::length(now - colour * 4.0f) < 1e-3f, qPrintable(str(now)));
    QVERIFY(std::max({now.x, now.y, now.z}) > 1.0f);
    QCOMPARE(undoCount(), 1);
    QVERIFY(settle(*window_));
    const Vec3 after = meanColourOf(*window_->viewport()->frame(), id);
    // The ball's colour scales its shading: brighter than an LDR colour can make it.
    QVERIFY2(after.z > 2.5f * before.z, qPrintable(str(before) + " -> " + str(after)));
}

void MaterialsTest::colourDialog_PreviewsLive_OkIsOneUndoStep() {
    clickObject("chalk ball");
    const ObjectId id = idOf(*window_, "chalk ball");
    const Vec3 chalk = doc().findMaterial("chalk")->color;
    Vec3 previewed(0.0f);
    withColourDialog(
        [&](QColorDialog* dialog) {
            QLineEdit* html = nullptr;
            for (QLineEdit* e : dialog->findChildren<QLineEdit*>())
                if (e->text().startsWith(QLatin1Char('#'))) html = e;
            QVERIFY(html);
            html->setFocus();
            html->selectAll();
            QTest::keyClicks(html, QStringLiteral("#ff0000"));
            // While the dialog is open: the document and the frame show red, no undo step.
            QVERIFY(doc().findMaterial("chalk")->color == Vec3(1.0f, 0.0f, 0.0f));
            QCOMPARE(undoCount(), 0);
            QVERIFY(settle(*window_));
            previewed = meanColourOf(*window_->viewport()->frame(), id);
        },
        QDialogButtonBox::Ok);
    QVERIFY2(previewed.x > 5.0f * std::max(previewed.y, 1e-4f), qPrintable(str(previewed)));
    QVERIFY(doc().findMaterial("chalk")->color == Vec3(1.0f, 0.0f, 0.0f));
    QCOMPARE(undoCount(), 1);
    window_->editor()->undoStack()->undo();
    QVERIFY(doc().findMaterial("chalk")->color == chalk);
}

void MaterialsTest::colourDialog_Cancel_RestoresAndLeavesNoUndoStep() {
    clickObject("chalk ball");
    const ObjectId id = idOf(*window_, "chalk ball");
    const Vec3 chalk = doc().findMaterial("chalk")->color;
    const Vec3 before = meanColourOf(*window_->viewport()->frame(), id);
    Vec3 previewed(0.0f);
    withColourDialog(
        [&](QColorDialog* dialog) {
            for (QLineEdit* e : dialog->findChildren<QLineEdit*>())
                if (e->text().startsWith(QLatin1Char('#'))) {
                    e->setFocus();
                    e->selectAll();
                    QTest::keyClicks(e, QStringLiteral("#00ff00"));
                }
            QVERIFY(settle(*window_));
            previewed = meanColourOf(*window_->viewport()->frame(), id);
        },
        QDialogButtonBox::Cancel);
    QVERIFY2(previewed.y > 5.0f * std::max(previewed.x, 1e-4f), qPrintable(str(previewed)));
    QVERIFY(doc().findMaterial("chalk")->color == chalk);
    QCOMPARE(undoCount(), 0);
    QVERIFY(window_->editor()->undoStack()->isClean());
    QVERIFY(settle(*window_));
    const Vec3 after = meanColourOf(*window_->viewport()->frame(), id);
    QVERIFY2(glm::length(after - before) < 1e-3f, qPrintable(str(before) + " vs " + str(after)));
}

QTEST_MAIN(MaterialsTest)
#include "materials_test.moc"
