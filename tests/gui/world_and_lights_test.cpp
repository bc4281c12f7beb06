// The World panel (the environment's image, intensity and rotation, each one undoable edit)
// and the spot and sun lights: Add, their glyphs, the outliner's labels, and G / R on them.
#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>
#include <cmath>

#include "gui_test_support.h"
#include "panels/dialog_folders.h"
#include "panels/outliner_model.h"
#include "panels/outliner_view.h"
#include "panels/world_panel.h"
#include "viewport/light_overlay.h"
#include "viewport/transform_gizmo.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

namespace {

bool near(const Vec3& a, const Vec3& b, float tol = 1e-4f) {
    return glm::length(a - b) <= tol;
}

/// Angle in degrees between two non-zero vectors.
double angleBetween(const Vec3& a, const Vec3& b) {
    const double c = glm::dot(glm::normalize(a), glm::normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

QString skyPath() {
    return QFileInfo(scenePath("textures/sky.hdr")).absoluteFilePath();
}

}  // namespace

class WorldAndLightsTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void addSpot_InFrontAboveTheFloorAimedDown_UndoRemovesIt();
    void addSun_SlantsDown_UndoRemovesIt();
    void outliner_NamesSpotAndSunLights();
    void glyphs_ShowTheSpotsConeAndTheSunsArrows();
    void rotateSpot_TurnsItsTargetAboutItsPosition();
    void moveSpot_MovesPositionAndTargetTogether();
    void localAxes_OfASpotAndASun_PutTheirBeamAlongMinusZ();
    void sun_RotateTurnsItsDirection_MoveSaysItHasNoPosition();
    void worldPanel_SetImage_UndoRestores_RemoveClears();
    void worldPanel_IntensityAndRotation_OneUndoStepPerDrag();
    void worldPanel_UnreadableImage_ShowsTheErrorInsteadOfTheStrip();
    void worldPanel_ImageSavedAgain_ReloadImagesRedrawsTheStrip_WithoutAnUndoStep();
    void worldPanel_Choose_StartsInTheLastImageFolder_CancelKeepsTheDocument();

private:
    const SceneDocument& doc() const { return window_->editor()->document(); }
    Viewport* viewport() const { return window_->viewport(); }
    /// Triggers Add -> `text`; the new light's id (the selection), or kNoObject.
    ObjectId add(const char* text);
    QDoubleSpinBox* spinOf(const char* key) const;

    std::unique_ptr<MainWindow> window_;
};

void WorldAndLightsTest::init() {
    QVERIFY(openRoomWindow(window_));
    viewport()->setFocus();
}

void WorldAndLightsTest::cleanup() {
    if (!window_) return;
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

ObjectId WorldAndLightsTest::add(const char* text) {
    QAction* a = window_->findChild<QAction*>(QStringLiteral("add ") + QLatin1String(text));
    if (!a) return kNoObject;
    a->trigger();
    return window_->editor()->selection();
}

QDoubleSpinBox* WorldAndLightsTest::spinOf(const char* key) const {
    QWidget* editor = window_->worldPanel()->findChild<QWidget*>(QLatin1String(key));
    return editor ? editor->findChild<QDoubleSpinBox*>() : nullptr;
}

void WorldAndLightsTest::addSpot_InFrontAboveTheFloorAimedDown_UndoRemovesIt() {
    const std::size_t lights = doc().lights.size();
    const ObjectId id = add("Spot light");
    QVERIFY(id != kNoObject);
    QCOMPARE(doc().lights.size(), lights + 1);
    const Light* l = doc().findLight(id);
    QVERIFY(l);
    QCOMPARE(l->type, LightType::Spot);
    QVERIFY(QString::fromStdString(l->name).startsWith(QStringLiteral("spot light")));
    // A valid spot: its target apart from its position, straight below it (the room's up is +Y).
    const Vec3 axis = l->target - l->position;
    QVERIFY2(glm::length(axis) > 0.5f, qPrintable(str(axis)));
    QVERIFY2(angleBetween(axis, Vec3(0, -1, 0)) < 1e-3, qPrintable(str(axis)));
    // Hung in front of the view, below the ceiling (y = 6), aimed at what is below it; both
    // the lamp and the lit spot in sight.
    QVERIFY2(l->position.y < 6.0f && l->position.y > l->target.y, qPrintable(str(l->position)));
    const QRectF shown(viewport()->rect());
    for (const Vec3& p : {l->position, l->target}) {
        const auto at = viewport()->projection().project(p);
        QVERIFY2(at && shown.contains(*at), qPrintable(str(p)));
    }
    window_->editor()->undoStack()->undo();
    QCOMPARE(doc().lights.size(), lights);
    QVERIFY(!doc().findLight(id));
    // A second one gets a name of its own.
    const ObjectId first = add("Spot light");
    const ObjectId second = add("Spot light");
    QVERIFY(doc().findLight(first)->name != doc().findLight(second)->name);
}

void WorldAndLightsTest::addSun_SlantsDown_UndoRemovesIt() {
    const std::size_t lights = doc().lights.size();
    const ObjectId id = add("Sun light");
    QVERIFY(id != kNoObject);
    const Light* l = doc().findLight(id);
    QVERIFY(l);
    QCOMPARE(l->type, LightType::Directional);
    QVERIFY(QString::fromStdString(l->name).startsWith(QStringLiteral("sun light")));
    const float s = 1.0f / std::sqrt(6.0f);
    QVERIFY2(near(l->direction, Vec3(-s, -2.0f * s, -s)), qPrintable(str(l->direction)));
    window_->editor()->undoStack()->undo();
    QCOMPARE(doc().lights.size(), lights);
    QVERIFY(!doc().findLight(id));
}

void WorldAndLightsTest::outliner_NamesSpotAndSunLights() {
    const ObjectId spot = add("Spot light");
    const ObjectId sun = add("Sun light");
    QVERIFY(spot != kNoObject && sun != kNoObject);
    OutlinerModel* model = window_->outliner()->outlinerModel();
    QCOMPARE(model->data(model->indexOf(spot), Qt::ToolTipRole).toString(),
             QStringLiteral("Spot light"));
    QCOMPARE(model->data(model->indexOf(sun), Qt::ToolTipRole).toString(),
             QStringLiteral("Sun light"));
    QCOMPARE(model->data(model->indexOf(sun), Qt::DisplayRole).toString(),
             QString::fromStdString(doc().findLight(sun)->name));
}

void WorldAndLightsTest::glyphs_ShowTheSpotsConeAndTheSunsArrows() {
    const ObjectId spot = add("Spot light");
    const ObjectId sun = add("Sun light");
    const ViewProjection view = viewport()->projection();
    const std::vector<LightGlyph> glyphs = lightGlyphs(doc(), view);
    const auto glyphOf = [&](ObjectId id) -> const LightGlyph* {
        for (const LightGlyph& g : glyphs)
            if (g.id == id) return &g;
        return nullptr;
    };
    const LightGlyph* s = glyphOf(spot);
    QVERIFY(s);
    // The axis and four rays along the falloff edge; circles at the radius and falloff angles.
    QCOMPARE(int(s->lines.size()), 5);
    QCOMPARE(int(s->loops.size()), 2);
    const Light& l = *doc().findLight(spot);
    const QPointF target = *view.project(l.target);
    QVERIFY(QLineF(s->lines[0].p2(), target).length() < 0.5);
    // What the raster view repaints for it reaches the cone's far end, not only the disc.
    QVERIFY(glyphRegion(*s, 4).contains(target.toPoint()));
    QVERIFY(QLineF(s->centre, target).length() > 20.0);
    // The falloff circle is wider than the radius circle, by tan 45 / tan 30 across the view
    // (give or take perspective: the circles lie on the floor a few units in front).
    const double r0 = s->loops[0].boundingRect().width(), r1 = s->loops[1].boundingRect().width();
    const double ratio = std::tan(45.0 * M_PI / 180.0) / std::tan(30.0 * M_PI / 180.0);
    QVERIFY2(std::abs(r1 / r0 - ratio) < 0.1 * ratio, qPrintable(QString::number(r1 / r0)));
    // The sun: three parallel arrows, each with a two-stroke head, pointing the way its light
    // goes on screen.
    const LightGlyph* g = glyphOf(sun);
    QVERIFY(g);
    QCOMPARE(int(g->lines.size()), 9);
    const Light& sl = *doc().findLight(sun);
    const QPointF a = *view.project(sl.position),
                  b = *view.project(sl.position + sl.direction * 0.01f);
    const QLineF screenDir(a, b);
    // Parallel in the scene, so converging a little on screen (perspective); the heads point
    // back at about 155 degrees.
    int along = 0;
    for (const QLineF& line : g->lines) {
        const double turn = line.angleTo(screenDir);
        if (std::min(turn, 360.0 - turn) < 15.0) ++along;
    }
    QCOMPARE(along, 3);
}

void WorldAndLightsTest::rotateSpot_TurnsItsTargetAboutItsPosition() {
    const ObjectId id = add("Spot light");
    QVERIFY(id != kNoObject);
    const Light before = *doc().findLight(id);
    const int steps = window_->editor()->undoStack()->count();
    viewport()->setFocus();
    QTest::keyClicks(viewport(), QStringLiteral("rx30"));
    QVERIFY(viewport()->transforming());
    QTest::keyClick(viewport(), Qt::Key_Return);
    const Light& after = *doc().findLight(id);
    QVERIFY(near(after.position, before.position));
    const Vec3 was = before.target - before.position, now = after.target - after.position;
    QVERIFY2(std::abs(glm::length(now) - glm::length(was)) < 1e-4f, qPrintable(str(now)));
    // The axis points straight down and X is across it: the turn is the whole angle.
    const double angle = angleBetween(was, now);
    QVERIFY2(std::abs(angle - 30.0) < 0.01, qPrintable(QString::number(angle)));
    // About +X by 30 degrees: down (0, -1, 0) goes to (0, -cos 30, -sin 30).
    const float c = std::cos(30.0f * float(M_PI) / 180.0f),
                s = std::sin(30.0f * float(M_PI) / 180.0f);
    QVERIFY2(near(glm::normalize(now), Vec3(0, -c, -s)), qPrintable(str(glm::normalize(now))));
    QCOMPARE(window_->editor()->undoStack()->count(), steps + 1);
    window_->editor()->undoStack()->undo();
    QVERIFY(*doc().findLight(id) == before);
}

void WorldAndLightsTest::moveSpot_MovesPositionAndTargetTogether() {
    const ObjectId id = add("Spot light");
    QVERIFY(id != kNoObject);
    const Light before = *doc().findLight(id);
    viewport()->setFocus();
    QTest::keyClicks(viewport(), QStringLiteral("gx1.5"));
    QTest::keyClick(viewport(), Qt::Key_Return);
    const Light& after = *doc().findLight(id);
    QVERIFY2(near(after.position, before.position + Vec3(1.5f, 0, 0)),
             qPrintable(str(after.position)));
    QVERIFY2(near(after.target, before.target + Vec3(1.5f, 0, 0)), qPrintable(str(after.target)));
    window_->editor()->undoStack()->undo();
    QVERIFY(*doc().findLight(id) == before);
}

void WorldAndLightsTest::localAxes_OfASpotAndASun_PutTheirBeamAlongMinusZ() {
    const ObjectId spot = add("Spot light");
    const ObjectId sun = add("Sun light");
    const Light& s = *doc().findLight(spot);
    const float k = 1.0f / std::sqrt(6.0f);
    for (const auto& [id, beam] : {std::pair{spot, glm::normalize(s.target - s.position)},
                                   std::pair{sun, Vec3(-k, -2.0f * k, -k)}}) {
        const Mat3 axes = gizmoAxes(doc(), id, true);
        QVERIFY2(near(axes[2], -beam), qPrintable(str(axes[2])));
        // Orthonormal and right-handed.
        QVERIFY(std::abs(glm::dot(axes[0], axes[1])) < 1e-5f);
        QVERIFY(std::abs(glm::dot(axes[0], axes[2])) < 1e-5f);
        QVERIFY(near(glm::cross(axes[0], axes[1]), axes[2]));
        QVERIFY(near(gizmoAxes(doc(), id, false)[2], Vec3(0, 0, 1)));  // World axes.
    }
}

void WorldAndLightsTest::sun_RotateTurnsItsDirection_MoveSaysItHasNoPosition() {
    const ObjectId id = add("Sun light");
    QVERIFY(id != kNoObject);
    const Light before = *doc().findLight(id);
    viewport()->setFocus();
    QTest::keyClicks(viewport(), QStringLiteral("rx90"));
    QTest::keyClick(viewport(), Qt::Key_Return);
    // About +X by 90 degrees: (x, y, z) -> (x, -z, y); (-1, -2, -1) / sqrt 6 -> (-1, 1, -2) /
    // sqrt 6.
    const float s = 1.0f / std::sqrt(6.0f);
    const Vec3 dir = doc().findLight(id)->direction;
    QVERIFY2(near(dir, Vec3(-s, s, -2.0f * s)), qPrintable(str(dir)));
    window_->editor()->undoStack()->undo();
    QVERIFY(near(doc().findLight(id)->direction, before.direction));
    // G on a sun says what it does: only the glyph moves; the light itself does not change.
    QTest::keyClicks(viewport(), QStringLiteral("gx1"));
    QVERIFY2(window_->statusBar()->currentMessage().contains(QStringLiteral("no position")),
             qPrintable(window_->statusBar()->currentMessage()));
    QTest::keyClick(viewport(), Qt::Key_Return);
    QVERIFY(near(doc().findLight(id)->direction, before.direction));
}

void WorldAndLightsTest::worldPanel_SetImage_UndoRestores_RemoveClears() {
    WorldPanel* world = window_->worldPanel();
    QVERIFY(world);
    QVERIFY(!doc().environment.present());
    QVERIFY(!world->hasPreview());
    const int steps = window_->editor()->undoStack()->count();
    world->setImageFile(skyPath());
    QVERIFY(doc().environment.present());
    QCOMPARE(QString::fromStdString(doc().environment.image.file), skyPath());
    QCOMPARE(QString::fromStdString(doc().environment.image.resolvedPath), skyPath());
    QCOMPARE(window_->editor()->undoStack()->count(), steps + 1);
    QVERIFY(previewsRead(*world));
    QVERIFY2(world->hasPreview(), qPrintable(world->previewError()));
    QVERIFY(world->previewError().isEmpty());
    window_->editor()->undoStack()->undo();
    QVERIFY(!doc().environment.present());
    QVERIFY(!world->hasPreview());
    window_->editor()->undoStack()->redo();
    QVERIFY(doc().environment.present());
    // Remove, through its button: no environment, one step; undo brings the image back.
    auto* remove = world->findChild<QPushButton*>(QStringLiteral("environmentRemove"));
    QVERIFY(remove && remove->isEnabled());
    remove->click();
    QVERIFY(!doc().environment.present());
    QVERIFY(!remove->isEnabled());
    QCOMPARE(window_->editor()->undoStack()->count(), steps + 2);
    window_->editor()->undoStack()->undo();
    QCOMPARE(QString::fromStdString(doc().environment.image.source()), skyPath());
}

void WorldAndLightsTest::worldPanel_IntensityAndRotation_OneUndoStepPerDrag() {
    WorldPanel* world = window_->worldPanel();
    QVERIFY(world);
    world->setImageFile(skyPath());
    QDoubleSpinBox* intensity = spinOf("intensity");
    QDoubleSpinBox* rotation = spinOf("rotation");
    QVERIFY(intensity && rotation);
    // The descriptors' ranges, not the spin box's defaults.
    const ParamDescriptor* d = findParameter(ParamKind::Environment, "rotation");
    QCOMPARE(rotation->maximum(), d->softMax);
    QCOMPARE(rotation->minimum(), d->softMin);
    const int steps = window_->editor()->undoStack()->count();
    // A sweep of the spin box is one step.
    intensity->setValue(1.5);
    intensity->setValue(2.5);
    QCOMPARE(doc().environment.intensity, 2.5f);
    QCOMPARE(window_->editor()->undoStack()->count(), steps + 1);
    rotation->setValue(45.0);
    rotation->setValue(90.0);
    QCOMPARE(doc().environment.rotation, 90.0f);
    QCOMPARE(window_->editor()->undoStack()->count(), steps + 2);
    window_->editor()->undoStack()->undo();
    QCOMPARE(doc().environment.rotation, 0.0f);
    QCOMPARE(rotation->value(), 0.0);  // The panel shows the document's value again.
    window_->editor()->undoStack()->undo();
    QCOMPARE(doc().environment.intensity, 1.0f);
    QVERIFY(doc().environment.present());  // The image is its own step.
}

void WorldAndLightsTest::worldPanel_UnreadableImage_ShowsTheErrorInsteadOfTheStrip() {
    WorldPanel* world = window_->worldPanel();
    QVERIFY(world);
    // A scene file is no image.
    const QString bad = QFileInfo(scenePath("reference-room.scene.json")).absoluteFilePath();
    world->setImageFile(bad);
    QCOMPARE(QString::fromStdString(doc().environment.image.source()), bad);
    QVERIFY(previewsRead(*world));
    QVERIFY(!world->hasPreview());
    QVERIFY2(world->previewError().contains(QStringLiteral("reference-room.scene.json")),
             qPrintable(world->previewError()));
    world->setImageFile(skyPath());
    QVERIFY(previewsRead(*world));
    QVERIFY(world->hasPreview());
    QVERIFY(world->previewError().isEmpty());
}

void WorldAndLightsTest::
    worldPanel_ImageSavedAgain_ReloadImagesRedrawsTheStrip_WithoutAnUndoStep() {
    WorldPanel* world = window_->worldPanel();
    QVERIFY(world);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("sky.png"));
    QVERIFY(writeFlat(path, Qt::red, -20));
    world->setImageFile(path);
    auto* strip = world->findChild<QLabel*>(QStringLiteral("environmentStrip"));
    QVERIFY(strip);
    const auto stripColor = [&] {
        if (!previewsRead(*world)) return QColor();
        const QImage shown = strip->pixmap().toImage();
        return shown.isNull() ? QColor() : shown.pixelColor(shown.width() / 2, shown.height() / 2);
    };
    QCOMPARE(stripColor(), QColor(Qt::red));
    const int steps = window_->editor()->undoStack()->count();

    // Saved again in green while the designer is open: the strip shows it after Reload Images.
    QVERIFY(writeFlat(path, Qt::green, -10));
    QCOMPARE(stripColor(), QColor(Qt::red));  // Nothing is read until asked.
    auto* reload = window_->findChild<QAction*>(QStringLiteral("reloadImages"));
    QVERIFY(reload);
    reload->trigger();
    QCOMPARE(stripColor(), QColor(Qt::green));
    QCOMPARE(window_->editor()->undoStack()->count(), steps);
    QCOMPARE(QString::fromStdString(doc().environment.image.source()), path);
}

void WorldAndLightsTest::worldPanel_Choose_StartsInTheLastImageFolder_CancelKeepsTheDocument() {
    WorldPanel* world = window_->worldPanel();
    QVERIFY(world);
    // An image was last chosen in scenes/textures: the dialog opens there, offering HDR and EXR.
    rememberDialogFolder(FileKind::Image, skyPath());
    const QString folder = QFileInfo(skyPath()).absolutePath();
    const auto answer = [&](bool accept) {
        bool ran = false;
        QTimer::singleShot(0, this, [&, accept] {
            auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            ran = true;
            QCOMPARE(dialog->objectName(), QStringLiteral("environmentFileDialog"));
            QCOMPARE(QFileInfo(dialog->directory().absolutePath()).canonicalFilePath(),
                     QFileInfo(folder).canonicalFilePath());
            const QString filters = dialog->nameFilters().join(' ');
            for (const char* ext : {"*.hdr", "*.exr", "*.png", "*.jpg", "*.tif", "*.tiff"})
                QVERIFY2(filters.contains(QLatin1String(ext)), qPrintable(filters));
            if (accept) {
                dialog->selectFile(skyPath());
                static_cast<QDialog*>(dialog)->accept();  // Protected in QFileDialog.
            } else {
                static_cast<QDialog*>(dialog)->reject();
            }
        });
        const bool chosen = world->chooseImage();  // Returns when the dialog closes.
        return ran ? int(chosen) : -1;
    };
    const int steps = window_->editor()->undoStack()->count();
    QCOMPARE(answer(false), 0);
    QVERIFY(!doc().environment.present());
    QCOMPARE(window_->editor()->undoStack()->count(), steps);
    QCOMPARE(answer(true), 1);
    QCOMPARE(QString::fromStdString(doc().environment.image.source()), skyPath());
    QCOMPARE(window_->editor()->undoStack()->count(), steps + 1);
}

QTEST_MAIN(WorldAndLightsTest)
#include "world_and_lights_test.moc"
