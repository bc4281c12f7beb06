// Materials (issue 11), with real events: the material list's edits are undo steps, HDR
// colours reach the frame, and the colour dialog previews live (Cancel restores, OK is one
// undo step). Placement and imports are in placement_test.cpp.
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

/// Mean linear colour of the pixels showing `id`.
Vec3 meanColourOf(const DisplayFrame& f, ObjectId id) {
    Vec3 sum(0.0f);
    int n = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            if (f.idAt(x, y) == id) sum += f.color[std::size_t(y) * f.width + x], ++n;
    return n ? sum / float(n) : Vec3(-1.0f);
}

}  // namespace

class MaterialsTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void newAndDuplicateMaterial_EachOneUndoStep();
    void renameMaterial_InPlace_RenamesItsUsers_AndRefusesTakenOrEmptyNames();
    void deleteMaterial_UsedIsRefusedWithTheReason_UnusedIsOneUndoStep();
    void assignToSelection_IsOneUndoStep_AndReachesTheFrame();
    void list_FollowsTheActiveObjectGivenANewMaterial_NotAPickedOne();
    void hdrValueBeyondOne_ReachesTheDocumentAndTheFrame();
    void colourDialog_PreviewsLive_OkIsOneUndoStep();
    void colourDialog_Cancel_RestoresAndLeavesNoUndoStep();

private:
    const SceneDocument& doc() { return window_->editor()->document(); }
    int undoCount() { return window_->editor()->undoStack()->count(); }
    /// Clicks `name` in the viewport (a real press and release on its pixels).
    void clickObject(const std::string& name);
    QPushButton* materialButton(const char* name);
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

void MaterialsTest::withColourDialog(const std::function<void(QColorDialog*)>& inDialog,
                                     QDialogButtonBox::StandardButton button) {
    QWidget* field = panelField(*window_, QStringLiteral("Material \""), QStringLiteral("Colour"));
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

void MaterialsTest::list_FollowsTheActiveObjectGivenANewMaterial_NotAPickedOne() {
    MaterialList* list = window_->materialList();
    clickObject("chalk ball");
    QCOMPARE(list->current(), std::string("chalk"));
    // A new sphere has the built-in grey, which the list does not hold: "chalk" stays.
    QAction* add = window_->findChild<QAction*>(QStringLiteral("add Sphere"));
    QVERIFY(add);
    add->trigger();
    const ObjectId id = window_->editor()->selection();
    QVERIFY(doc().findObject(id) && doc().findObject(id)->material.empty());
    QCOMPARE(list->current(), std::string("chalk"));
    // "New material" gives it a material of its own: the list shows that one, as it shows
    // the material of an object picked.
    auto* unique = window_->propertyPanel()->findChild<QPushButton*>(QStringLiteral("makeUnique"));
    QVERIFY(unique);
    QTest::mouseClick(unique, Qt::LeftButton);
    const std::string own = doc().findObject(id)->material;
    QVERIFY(!own.empty() && doc().findMaterial(own));
    QCOMPARE(list->current(), own);
    // A material picked in the list stays picked through edits that leave the sphere's alone.
    QVERIFY(list->setCurrent("red wall"));
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("material"), "diffuse", 0.25f));
    QCOMPARE(list->current(), std::string("red wall"));
    // Undone back to the built-in grey, the list keeps what was picked.
    window_->editor()->undoStack()->undo();
    window_->editor()->undoStack()->undo();
    QVERIFY(doc().findObject(id)->material.empty());
    QCOMPARE(list->current(), std::string("red wall"));
}

void MaterialsTest::hdrValueBeyondOne_ReachesTheDocumentAndTheFrame() {
    clickObject("blue ball");
    const ObjectId id = idOf(*window_, "blue ball");
    const Vec3 colour = doc().findMaterial("blue plastic")->color;
    const float value = std::max({colour.x, colour.y, colour.z});
    QVERIFY(value <= 1.0f);
    const Vec3 before = meanColourOf(*window_->viewport()->frame(), id);
    QWidget* field = panelField(*window_, QStringLiteral("Material \""), QStringLiteral("Colour"));
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
