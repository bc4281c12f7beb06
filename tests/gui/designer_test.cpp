// The designer under QT_QPA_PLATFORM=offscreen (raster viewport): open, pick, drag, undo,
// property edits, save/reopen, preferences and error handling.
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEventLoop>
#include <QLabel>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolBar>
#include <QtTest>

#include "document/transform_edits.h"
#include "drag_geometry.h"
#include "gui_test_support.h"
#include "io/scene_io.h"
#include "panels/outliner_model.h"
#include "panels/outliner_view.h"
#include "panels/property_panel.h"
#include "scene/parameters.h"
#include "session/governor.h"
#include "shell/error_reporter.h"
#include "shell/preferences.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class DesignerTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void openScene_ShowsFrameAndOutliner();
    void clickOnSphere_SelectsItInOutliner_AndOutlinerSelectsInViewport();
    void clickOnNothing_ClearsSelection();
    void dragSphere_MovesItInDocument_AndUndoRestores();
    void dragWithAxisLock_MovesAlongThatAxisOnly_AndEscapeCancels();
    void updateRate_FallsToZeroInTheStatusBarOnceTheUserStops();
    void governorLabel_SaysAsSetOnceTheFrameRefines();
    void statusFields_StayInPlace_AndShowTheirWholeText();
    void propertyEdit_ReRendersFrame_AndSharedMaterialIsShown();
    void outOfRangeProperty_IsRejectedWithMessage();
    void saveAndReopen_GiveTheSameScene();
    void preferences_ChangeSessionPolicy();
    void preferences_RayEngine_RebuildsTheViewportWithIt();
    void aboutDialog_NamesVersionEngineAndLibraryLicences();
    void toolbarAndMenus_HaveIcons_AndTheWindowItsIcon();
    void badSceneFile_ShowsErrorAndKeepsDocument();
    void badMeshImport_ErrorShowsWithTheProgressDialogGone();
    void addSphereLight_UndoRedo();
    void debugViews_ProduceImages();

private:
    std::unique_ptr<MainWindow> window_;
    QStringList errors_;
};

void DesignerTest::init() {
    errors_.clear();
    setErrorHandler(
        [this](const QString& title, const QString& text) { errors_ << title + ": " + text; });
    QVERIFY(openRoomWindow(window_));
}

void DesignerTest::cleanup() {
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
    setErrorHandler({});
}

void DesignerTest::openScene_ShowsFrameAndOutliner() {
    const auto frame = window_->viewport()->frame();
    QVERIFY(frame);
    QCOMPARE(frame->width, 160);
    QCOMPARE(frame->height, 90);
    OutlinerModel* model = window_->outliner()->outlinerModel();
    QCOMPARE(model->rowCount(model->index(2, 0)), 14);
    QCOMPARE(model->rowCount(model->index(1, 0)), 1);
    QVERIFY(!window_->viewport()->frameView()->usesOpenGL());
    QVERIFY(window_->windowTitle().contains(QStringLiteral("reference-room")));
}

void DesignerTest::clickOnSphere_SelectsItInOutliner_AndOutlinerSelectsInViewport() {
    const ObjectId blue = idOf(*window_, "blue ball");
    const auto frame = window_->viewport()->frame();
    const auto [x, y] = pixelOf(*frame, blue);
    QCOMPARE(frame->idAt(x, y), blue);
    QTest::mouseClick(window_->viewport(), Qt::LeftButton, {},
                      window_->viewport()->widgetPointOf(x, y));
    QCOMPARE(window_->editor()->selection(), blue);
    QCOMPARE(window_->outliner()->idOf(window_->outliner()->currentIndex()), blue);

    // The raster view draws the outline around the selection.
    const QImage shown =
        window_->viewport()->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    bool outline = false;
    for (int j = 0; j < shown.height() && !outline; ++j)
        for (int i = 0; i < shown.width() && !outline; ++i)
            outline =
                shown.pixelColor(i, j) == QColor(kOutlineRgb[0], kOutlineRgb[1], kOutlineRgb[2]);
    QVERIFY(outline);

    const ObjectId glass = idOf(*window_, "glass ball");
    window_->outliner()->setCurrentIndex(window_->outliner()->indexOf(glass));
    QCOMPARE(window_->editor()->selection(), glass);
}

void DesignerTest::clickOnNothing_ClearsSelection() {
    // The frame fills the viewport (no letterbox to click on); with every object hidden the
    // viewport shows nothing but the background.
    SceneDocument doc = window_->editor()->document();
    for (Object& o : doc.objects.editable()) o.visible = false;
    window_->editor()->edit(QStringLiteral("Hide all"), std::move(doc));
    QVERIFY(settle(*window_));
    Viewport* v = window_->viewport();
    const QPoint centre = v->rect().center();
    QVERIFY(v->pixelAt(centre));
    QCOMPARE(v->frame()->idAt(v->pixelAt(centre)->x(), v->pixelAt(centre)->y()), kNoObject);
    window_->editor()->setSelection(idOf(*window_, "blue ball"));
    QTest::mouseClick(v, Qt::LeftButton, {}, centre);
    QCOMPARE(window_->editor()->selection(), kNoObject);
}

// A drag moves the ball in the plane through its centre parallel to the image, as far as the
// drag's 40 pixels span at that depth (acrossView: similar triangles, exact but for rounding).
void DesignerTest::dragSphere_MovesItInDocument_AndUndoRestores() {
    const SceneDocument before = window_->editor()->document();
    const ObjectId blue = idOf(*window_, "blue ball");
    const auto [x, y] = pixelOf(*window_->viewport()->frame(), blue);
    Viewport* v = window_->viewport();
    QCOMPARE(v->projection().imageRect(), v->rect());  // the image fills the viewport
    const Vec3 expected =
        acrossView(v->viewCamera(), v->height(), *entityCentre(before, blue), QPointF(40, 0));
    const QPoint start = v->widgetPointOf(x, y);
    const int stepsBefore = window_->editor()->undoStack()->count();
    QTest::mousePress(v, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(v, start + QPoint(4 * i, 0));
    QTest::mouseRelease(v, Qt::LeftButton, {}, start + QPoint(40, 0));
    const Vec3 moved = window_->editor()->document().findObject(blue)->transform.translate;
    const Vec3 delta = moved - before.findObject(blue)->transform.translate;
    QVERIFY2(expected.x > 0.1f && glm::length(delta - expected) <= 1e-3f * glm::length(expected),
             qPrintable(QStringLiteral("(%1, %2, %3), expected (%4, %5, %6)")
                            .arg(delta.x)
                            .arg(delta.y)
                            .arg(delta.z)
                            .arg(expected.x)
                            .arg(expected.y)
                            .arg(expected.z)));
    QCOMPARE(window_->editor()->undoStack()->count(), stepsBefore + 1);  // One drag, one step.
    QVERIFY(settle(*window_));

    window_->editor()->undoStack()->undo();
    QVERIFY(window_->editor()->document().sameContent(before));
    window_->editor()->undoStack()->redo();
    QVERIFY(window_->editor()->document().findObject(blue)->transform.translate == moved);
}

void DesignerTest::updateRate_FallsToZeroInTheStatusBarOnceTheUserStops() {
    QLabel* rate = nullptr;
    for (QLabel* l : window_->statusBar()->findChildren<QLabel*>())
        if (l->toolTip() == QStringLiteral("Document updates sent to the renderer per second"))
            rate = l;
    QVERIFY(rate);
    double highest = 0.0;
    connect(window_->session(), &SessionController::updateRateChanged, this,
            [&highest](double r) { highest = std::max(highest, r); });
    const ObjectId blue = idOf(*window_, "blue ball");
    const auto [x, y] = pixelOf(*window_->viewport()->frame(), blue);
    Viewport* v = window_->viewport();
    const QPoint start = v->widgetPointOf(x, y);
    QTest::mousePress(v, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 60; ++i) {  // About 1.5 s of dragging: at least one rate tick sees it.
        QTest::mouseMove(v, start + QPoint(i % 20, 0));
        QTest::qWait(25);
    }
    QTest::mouseRelease(v, Qt::LeftButton, {}, start);
    QVERIFY(highest > 0.0);
    // Idle: the session stops passing and the label must still come down.
    QTRY_COMPARE_WITH_TIMEOUT(rate->text(), QStringLiteral("0 upd/s"), 5000);
}

void DesignerTest::statusFields_StayInPlace_AndShowTheirWholeText() {
    // Passes whose numbers and words differ most in length: every field keeps its place and
    // width, and shows its whole text.
    QList<QLabel*> fields;
    for (QLabel* l : window_->statusBar()->findChildren<QLabel*>())
        if (!l->toolTip().isEmpty() && l->isVisible()) fields << l;
    QVERIFY(fields.size() >= 6);
    PassInfo small;
    small.kind = PassKind::Base;
    small.ms = 0.5;
    small.rays = 10;
    small.tracedPixels = 1;
    small.totalPixels = 1000;
    PassInfo big;
    big.kind = PassKind::Interactive;
    big.cancelled = true;
    big.governorLevel = 3;  // diffuse mirrors and glass
    big.ms = 2345.6;
    big.rays = 900000000;
    big.tracedPixels = big.totalPixels = 1000;
    QList<QRect> where;
    for (const PassInfo& pass : {small, big, small}) {
        Q_EMIT window_->session()->passFinished(pass);
        QApplication::processEvents();
        QList<QRect> now;
        for (QLabel* l : fields) {
            now << l->geometry();
            QVERIFY2(l->fontMetrics().horizontalAdvance(l->text()) <= l->contentsRect().width(),
                     qPrintable(l->text()));
        }
        if (!where.isEmpty()) QCOMPARE(now, where);
        where = now;
    }
}

void DesignerTest::governorLabel_SaysAsSetOnceTheFrameRefines() {
    auto* label = window_->statusBar()->findChild<QLabel*>(QStringLiteral("statusGovernor"));
    QVERIFY(label);
    // The passes the session reports, through the controller's signal as the session sends
    // them: the window has settled, so no pass of its own comes in between.
    PassInfo drag;
    drag.kind = PassKind::Interactive;
    drag.governorLevel = Governor::kLevels - 1;
    Q_EMIT window_->session()->passFinished(drag);
    QCOMPARE(label->text(), QStringLiteral("governor: box proxy"));
    PassInfo base;  // After the release: refining at the scene's settings, governor level -1.
    base.kind = PassKind::Base;
    base.cancelled = true;  // Cut short by the next edit, still not the drag's level.
    Q_EMIT window_->session()->passFinished(base);
    QCOMPARE(label->text(), QStringLiteral("governor: as set"));
    Q_EMIT window_->session()->passFinished(drag);
    PassInfo supersample;
    supersample.kind = PassKind::Supersample;
    Q_EMIT window_->session()->passFinished(supersample);
    QCOMPARE(label->text(), QStringLiteral("governor: as set"));
    drag.governorLevel = -1;  // The governor switched off in Preferences.
    Q_EMIT window_->session()->passFinished(drag);
    QCOMPARE(label->text(), QStringLiteral("governor: off"));
}

// Locked to Y, the ball's centre goes to the point of its vertical line under the cursor: with
// the cursor on that line's image, as far up as alongAxis says (within 2 %: whole pixels).
void DesignerTest::dragWithAxisLock_MovesAlongThatAxisOnly_AndEscapeCancels() {
    const SceneDocument before = window_->editor()->document();
    const ObjectId orange = idOf(*window_, "floating ball");
    const auto [x, y] = pixelOf(*window_->viewport()->frame(), orange);
    QCOMPARE(window_->viewport()->frame()->idAt(x, y), orange);
    Viewport* v = window_->viewport();
    const ViewProjection view = v->projection();
    const Vec3 centre = *entityCentre(before, orange);
    const QPointF image = *view.project(centre);
    const QPoint to = (image + 36.0 * screenDirection(view, centre, Vec3(0, 1, 0))).toPoint();
    const QPoint start = v->widgetPointOf(x, y);
    QTest::mousePress(v, Qt::LeftButton, {}, start);
    QTest::mouseMove(v, start + QPoint(5, 5));
    QTest::keyClick(v, Qt::Key_Y);
    QTest::mouseMove(v, to);
    const Vec3 t = window_->editor()->document().findObject(orange)->transform.translate;
    QCOMPARE(t.x, 0.0f);
    QCOMPARE(t.z, 0.0f);
    const double expected = alongAxis(view, centre, Vec3(0, 1, 0), image, to);
    QVERIFY2(
        expected > 0.1 && std::abs(t.y - expected) <= 0.02 * expected,
        qPrintable(
            QStringLiteral("%1 %2 %3, expected y %4").arg(t.x).arg(t.y).arg(t.z).arg(expected)));
    QTest::keyClick(v, Qt::Key_Escape);
    QTest::mouseRelease(v, Qt::LeftButton, {}, to);
    QVERIFY(window_->editor()->document().sameContent(before));
    QVERIFY(!window_->editor()->undoStack()->canUndo());
}

void DesignerTest::propertyEdit_ReRendersFrame_AndSharedMaterialIsShown() {
    const ObjectId blue = idOf(*window_, "blue ball");
    window_->editor()->setSelection(blue);
    const auto [x, y] = pixelOf(*window_->viewport()->frame(), blue);
    const Color beforeColor = window_->viewport()->frame()->color[std::size_t(y) * 160 + x];
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("material"), "color",
                                                Vec3(1.0f, 0.0f, 0.0f)));
    QCOMPARE(window_->editor()->document().findMaterial("blue plastic")->color,
             Vec3(1.0f, 0.0f, 0.0f));
    QVERIFY(settle(*window_));
    const Color afterColor = window_->viewport()->frame()->color[std::size_t(y) * 160 + x];
    QVERIFY(afterColor.x > beforeColor.x + 0.05f);
    QVERIFY(afterColor.z < beforeColor.z);

    // The mirror material is shared by two balls: the panel says so and offers make-unique.
    window_->editor()->setSelection(idOf(*window_, "chrome ball"));
    auto* usage = window_->propertyPanel()->findChild<QLabel*>(QStringLiteral("materialUsage"));
    QVERIFY(usage);
    QVERIFY(usage->text().contains(QStringLiteral("2 objects")));
}

void DesignerTest::outOfRangeProperty_IsRejectedWithMessage() {
    const ObjectId blue = idOf(*window_, "blue ball");
    window_->editor()->setSelection(blue);
    QVERIFY(!window_->propertyPanel()->applyEdit(QStringLiteral("geometry"), "radius", -1.0f));
    QVERIFY(window_->propertyPanel()->lastError().contains(QStringLiteral("radius")));
    QVERIFY(!window_->editor()->undoStack()->canUndo());
    // Glass in one edit: transparency up, and the sphere keeps its place: same geometry and
    // transform in the document, and the frame shows it at the same pixels.
    const Object before = *window_->editor()->document().findObject(blue);
    const DisplayFrame frameBefore =
        *window_->viewport()->frame();  // a copy: the view updates its own
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("material"), "transparency", 0.9f));
    QCOMPARE(window_->editor()->document().findMaterial("blue plastic")->transparency, 0.9f);
    QVERIFY(settle(*window_));
    const Object& after = *window_->editor()->document().findObject(blue);
    QVERIFY(after.geometry == before.geometry);
    QVERIFY(after.transform == before.transform);
    const auto frameAfter = window_->viewport()->frame();
    int moved = 0, pixels = 0;
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160; ++x) {
            pixels += frameBefore.idAt(x, y) == blue;
            moved += (frameBefore.idAt(x, y) == blue) != (frameAfter->idAt(x, y) == blue);
        }
    QVERIFY(pixels > 50);
    QCOMPARE(moved, 0);
    // ...and it is glass now: its centre shows what lies behind it, not blue plastic.
    const auto [x, y] = pixelOf(*frameAfter, blue);
    const Color c0 = frameBefore.color[std::size_t(y) * 160 + x];
    const Color c1 = frameAfter->color[std::size_t(y) * 160 + x];
    QVERIFY2(c0.z > c0.x && glm::length(c1 - c0) > 0.05f,
             qPrintable(QStringLiteral("%1 %2 %3 -> %4 %5 %6")
                            .arg(c0.x)
                            .arg(c0.y)
                            .arg(c0.z)
                            .arg(c1.x)
                            .arg(c1.y)
                            .arg(c1.z)));
}

void DesignerTest::saveAndReopen_GiveTheSameScene() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("saved.scene.json"));
    SceneDocument doc = window_->editor()->document();
    moveBy(doc, idOf(*window_, "green ball"), Vec3(0.5f, 0.0f, 0.0f));
    window_->editor()->edit(QStringLiteral("move"), doc);
    QVERIFY(window_->isWindowModified());
    QVERIFY(window_->saveFile(path));
    QVERIFY(!window_->isWindowModified());
    const SceneDocument saved = window_->editor()->document();
    MainWindow other;
    QVERIFY(other.openFile(path));
    QVERIFY(other.editor()->document().sameContent(saved));
}

void DesignerTest::preferences_ChangeSessionPolicy() {
    PreferencesDialog* dialog = window_->showPreferences();
    auto* shadows = dialog->findChild<QComboBox*>(QStringLiteral("shadows"));
    auto* resolution = dialog->findChild<QComboBox*>(QStringLiteral("resolution"));
    QVERIFY(shadows && resolution);
    auto* whole = dialog->findChild<QCheckBox*>(QStringLiteral("whole_frames_while_moving"));
    QVERIFY(whole && whole->isChecked());  // Whole frames while moving, by default.
    shadows->setCurrentIndex(int(MovingShadows::Off));
    resolution->setCurrentIndex(int(MovingResolution::Quarter));
    whole->setChecked(false);
    const InteractionPolicy p = renderSession(*window_).policy();
    QCOMPARE(p.shadows, MovingShadows::Off);
    QCOMPARE(p.resolution, MovingResolution::Quarter);
    QVERIFY(!p.wholeFramesWhileMoving);
    QCOMPARE(loadPreferences().policy, p);  // Stored for the next start.
    dialog->close();
    window_->applyPreferences(Preferences{});
}

void DesignerTest::preferences_RayEngine_RebuildsTheViewportWithIt() {
    QCOMPARE(renderSession(*window_).snapshot()->engineKind(), EngineKind::Embree);
    PreferencesDialog* dialog = window_->showPreferences();
    auto* engine = dialog->findChild<QComboBox*>(QStringLiteral("engine"));
    QVERIFY(engine);
    engine->setCurrentIndex(int(EngineKind::Builtin));
    window_->session()->flushUpdate();
    QVERIFY(renderSession(*window_).waitUntilComplete(std::chrono::seconds(60)));
    QCOMPARE(renderSession(*window_).snapshot()->engineKind(), EngineKind::Builtin);
    QCOMPARE(loadPreferences().engine, EngineKind::Builtin);  // Stored for the next start.
    auto* renderThreads = dialog->findChild<QSpinBox*>(QStringLiteral("renderThreads"));
    QVERIFY(renderThreads);
    renderThreads->setValue(1);  // Render Image leaves the other core to the viewport.
    QCOMPARE(loadPreferences().renderThreads, 1);
    dialog->close();
    window_->applyPreferences(Preferences{});
    window_->session()->flushUpdate();
    QVERIFY(renderSession(*window_).waitUntilComplete(std::chrono::seconds(60)));
    QCOMPARE(renderSession(*window_).snapshot()->engineKind(), EngineKind::Embree);
}

void DesignerTest::aboutDialog_NamesVersionEngineAndLibraryLicences() {
    QString text;
    QTimer::singleShot(200, [&] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        QVERIFY(box);
        text = box->text();
        box->accept();
    });
    QAction* about = nullptr;
    for (QAction* a : window_->findChildren<QAction*>())
        if (a->text() == QStringLiteral("&About RayStudio")) about = a;
    QVERIFY(about);
    about->trigger();
    QVERIFY2(text.contains(QApplication::applicationVersion()), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("embree")), qPrintable(text));
    for (const char* licence : {"LGPL", "Apache 2.0", "BSD", "MIT"})
        QVERIFY2(text.contains(QLatin1String(licence)), licence);
}

void DesignerTest::toolbarAndMenus_HaveIcons_AndTheWindowItsIcon() {
    // Every toolbar button and the file, edit and render actions show an icon (the theme's or
    // the bundled SVG, which needs Qt's SVG icon engine: packaging/setup.sh installs it).
    auto* tools = window_->findChild<QToolBar*>(QStringLiteral("addToolBar"));
    QVERIFY(tools);
    int buttons = 0;
    for (QAction* a : tools->actions()) {
        if (a->isSeparator()) continue;
        ++buttons;
        QVERIFY2(!a->icon().pixmap(24, 24).isNull(), qPrintable(a->text()));
    }
    QCOMPARE(buttons, 12);  // Four shapes, Mesh, four lights, Undo, Redo, Render Image.
    for (const QString& text :
         {QStringLiteral("&New"), QStringLiteral("&Open..."), QStringLiteral("&Save"),
          QStringLiteral("&Delete"), QStringLiteral("&Render Image...")}) {
        QAction* found = nullptr;
        for (QAction* a : window_->findChildren<QAction*>())
            if (a->text() == text) found = a;
        QVERIFY2(found && !found->icon().pixmap(16, 16).isNull(), qPrintable(text));
    }
    // The bundled fallback itself draws (not only a theme that happens to be installed).
    QVERIFY(!QIcon(QStringLiteral(":/icons/actions/add-sphere.svg")).pixmap(24, 24).isNull());
    for (const char* light : {"add-spot-light", "add-sun-light"})
        QVERIFY2(!QIcon(QStringLiteral(":/icons/actions/%1.svg").arg(QLatin1String(light)))
                      .pixmap(24, 24)
                      .isNull(),
                 light);
}

void DesignerTest::badSceneFile_ShowsErrorAndKeepsDocument() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.scene.json"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(
        "{\n  \"format\": \"raystudio-scene\", \"version\": 1,\n"
        "  \"objects\": [ { \"name\": \"s\", \"type\": \"sphere\", \"radius\": 0 } ]\n}\n");
    f.close();
    const SceneDocument before = window_->editor()->document();
    const QString fileBefore = window_->editor()->filePath();
    QVERIFY(!window_->openFile(path));
    QCOMPARE(errors_.size(), 1);
    QVERIFY2(errors_.first().contains(QStringLiteral("/objects/0")), qPrintable(errors_.first()));
    QVERIFY(errors_.first().contains(QStringLiteral(":3:")));
    QVERIFY(window_->editor()->document().sameContent(before));
    QCOMPARE(window_->editor()->filePath(), fileBefore);
}

/// Sum of the frame's linear colour: more light, more energy.
static double frameEnergy(const DisplayFrame& f) {
    double e = 0.0;
    for (const Color& c : f.color) e += double(c.x + c.y + c.z);
    return e;
}

void DesignerTest::badMeshImport_ErrorShowsWithTheProgressDialogGone() {
    // The error box is modal: its own event loop runs while the user reads it. The import's
    // progress dialog must be gone for all of that time: neither left on top (a deferred
    // delete waits for the outer loop) nor shown by its minimum-duration timer.
    int visibleDialogs = -1;
    setErrorHandler([&](const QString& title, const QString& text) {
        errors_ << title + ": " + text;
        // A nested loop, as a modal box runs, past the dialog's 300 ms (not QTest::qWait,
        // which also runs the deferred deletes a modal box's loop leaves alone).
        QEventLoop modal;
        QTimer::singleShot(600, &modal, &QEventLoop::quit);
        modal.exec();
        visibleDialogs = 0;
        for (QProgressDialog* d : window_->findChildren<QProgressDialog*>())
            visibleDialogs += d->isVisible() ? 1 : 0;
    });
    const std::size_t objects = window_->editor()->document().objects.size();
    window_->importMesh(QStringLiteral("/nonexistent/raystudio/no-such-mesh.obj"));
    // Shown, as a slow import shows it; the result is posted to this thread, so it cannot
    // have arrived yet.
    const auto dialogs = window_->findChildren<QProgressDialog*>();
    QCOMPARE(dialogs.size(), 1);
    dialogs.first()->show();
    QTRY_VERIFY_WITH_TIMEOUT(visibleDialogs >= 0, 20000);
    QCOMPARE(visibleDialogs, 0);
    QCOMPARE(errors_.size(), 1);
    QVERIFY2(errors_.first().contains(QStringLiteral("no-such-mesh.obj")),
             qPrintable(errors_.first()));
    QCOMPARE(window_->editor()->document().objects.size(), objects);  // Nothing added.
}

void DesignerTest::addSphereLight_UndoRedo() {
    QAction* add = window_->findChild<QAction*>(QStringLiteral("add Sphere light"));
    QVERIFY(add);
    const std::size_t lights = window_->editor()->document().lights.size();
    const DisplayFrame dark = *window_->viewport()->frame();  // a copy: the view updates its own
    const double energyBefore = frameEnergy(dark);
    add->trigger();
    QCOMPARE(window_->editor()->document().lights.size(), lights + 1);
    const ObjectId id = window_->editor()->selection();
    QVERIFY(window_->editor()->document().findLight(id));
    QCOMPARE(window_->editor()->document().findLight(id)->type, LightType::Sphere);
    // The frame shows the new light: the room gets brighter.
    QVERIFY(settle(*window_));
    const double energyLit = frameEnergy(*window_->viewport()->frame());
    QVERIFY2(energyLit > 1.05 * energyBefore,
             qPrintable(QStringLiteral("%1 -> %2").arg(energyBefore).arg(energyLit)));
    // Undo takes the light out of the picture again: the frame is the one before, pixel for pixel.
    window_->editor()->undoStack()->undo();
    QCOMPARE(window_->editor()->document().lights.size(), lights);
    QVERIFY(settle(*window_));
    const auto undone = window_->viewport()->frame();
    float worst = 0.0f;
    for (std::size_t i = 0; i < undone->color.size(); ++i) {
        const Color d = glm::abs(undone->color[i] - dark.color[i]);
        worst = std::max({worst, d.x, d.y, d.z});
    }
    QVERIFY2(worst <= 1e-5f, qPrintable(QString::number(worst)));
    window_->editor()->undoStack()->redo();
    QCOMPARE(window_->editor()->document().lights.size(), lights + 1);
    QVERIFY(settle(*window_));
    QVERIFY(std::abs(frameEnergy(*window_->viewport()->frame()) - energyLit) <= 1e-3 * energyLit);
}

void DesignerTest::debugViews_ProduceImages() {
    // Normals and ray costs are handed over only while a view shows them.
    QVERIFY(window_->viewport()->frame()->normal.empty());
    window_->viewport()->setViewMode(ViewMode::Normals);
    const DisplayFrame shown = *window_->viewport()->frame();  // a copy: the view updates its own
    window_->viewport()->setViewMode(ViewMode::Color);
    QCOMPARE(shown.normal.size(), shown.color.size());
    const DisplayFrame* frame = &shown;
    const ObjectId blue = idOf(*window_, "blue ball"), glass = idOf(*window_, "glass ball");
    const ObjectId floor = idOf(*window_, "floor"), back = idOf(*window_, "back wall");
    const ObjectId left = idOf(*window_, "left wall");
    const auto [bx, by] = pixelOf(*frame, blue);
    const auto [gx, gy] = pixelOf(*frame, glass);
    const auto [lx, ly] = pixelOf(*frame, left);
    // Pixels with known content: the floor at the bottom centre, the back wall in the middle.
    const int fx = 80, fy = 88, wx = 80, wy = 25;
    QCOMPARE(frame->idAt(fx, fy), floor);
    QCOMPARE(frame->idAt(wx, wy), back);
    auto rgb = [](const QImage& img, int x, int y) { return img.pixelColor(x, y); };
    for (ViewMode m : {ViewMode::Color, ViewMode::ObjectIds, ViewMode::Normals, ViewMode::Depth,
                       ViewMode::Cost, ViewMode::Retraced})
        QCOMPARE(viewportImage(*frame, m, {}).size(), QSize(160, 90));

    // Colour: the red wall is red, the blue ball blue.
    const QImage color = viewportImage(*frame, ViewMode::Color, {});
    QVERIFY(rgb(color, lx, ly).red() > 2 * rgb(color, lx, ly).green());
    QVERIFY(rgb(color, bx, by).blue() > rgb(color, bx, by).red());
    // Object ids: one colour per object, different objects different colours.
    const QImage ids = viewportImage(*frame, ViewMode::ObjectIds, {});
    QCOMPARE(rgb(ids, fx, fy), rgb(ids, fx + 3, fy));
    QVERIFY(rgb(ids, fx, fy) != rgb(ids, wx, wy));
    QVERIFY(rgb(ids, bx, by) != rgb(ids, gx, gy));
    // Normals: the floor faces +y (green full, red and blue half), the back wall +z.
    const QImage normals = viewportImage(*frame, ViewMode::Normals, {});
    QVERIFY(std::abs(rgb(normals, fx, fy).red() - 127) <= 1 &&
            rgb(normals, fx, fy).green() >= 254 &&
            std::abs(rgb(normals, fx, fy).blue() - 127) <= 1);
    QVERIFY(std::abs(rgb(normals, wx, wy).red() - 127) <= 1 && rgb(normals, wx, wy).blue() >= 254);
    // Depth: near is bright, far is dark; the floor in front is nearer than the back wall.
    const QImage depth = viewportImage(*frame, ViewMode::Depth, {});
    QVERIFY(rgb(depth, fx, fy).red() > rgb(depth, wx, wy).red() + 30);
    QCOMPARE(rgb(depth, fx, fy).red(), rgb(depth, fx, fy).blue());  // grey
    // Cost: the glass ball's ray trees are deeper than the back wall's single hit.
    QVERIFY(frame->cost[std::size_t(gy) * 160 + gx] > frame->cost[std::size_t(wy) * 160 + wx]);
    const QImage cost = viewportImage(*frame, ViewMode::Cost, {});
    QVERIFY(rgb(cost, gx, gy) != rgb(cost, wx, wy));
    // Re-traced pixels: after retinting the blue ball, its pixels are marked re-traced (red
    // tint) and the left wall, which cannot see it, is not.
    window_->editor()->setSelection(blue);
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("material"), "color",
                                                Vec3(0.2f, 0.9f, 0.2f)));
    QVERIFY(settle(*window_));
    const QImage retraced = viewportImage(*window_->viewport()->frame(), ViewMode::Retraced, {});
    QVERIFY(rgb(retraced, bx, by).red() >= 127);
    QVERIFY(rgb(retraced, 2, 45).red() < 127);
}

QTEST_MAIN(DesignerTest)
#include "designer_test.moc"
