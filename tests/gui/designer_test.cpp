// The designer under QT_QPA_PLATFORM=offscreen (raster viewport): open, pick, drag, undo,
// property edits, save/reopen, preferences and error handling.
#include "gui_test_support.h"

#include "error_reporter.h"
#include "io/scene_io.h"
#include "outliner_model.h"
#include "outliner_view.h"
#include "preferences.h"
#include "property_panel.h"

#include <QAction>
#include <QComboBox>
#include <QToolBar>
#include <QApplication>
#include <QTimer>
#include <QMessageBox>
#include <QSpinBox>
#include <QLabel>
#include <QTemporaryDir>
#include <QtTest>

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
    void clickOutsideImage_ClearsSelection();
    void dragSphere_MovesItInDocument_AndUndoRestores();
    void dragWithAxisLock_MovesAlongThatAxisOnly_AndEscapeCancels();
    void propertyEdit_ReRendersFrame_AndSharedMaterialIsShown();
    void outOfRangeProperty_IsRejectedWithMessage();
    void saveAndReopen_GiveTheSameScene();
    void preferences_ChangeSessionPolicy();
    void preferences_RayEngine_RebuildsTheViewportWithIt();
    void aboutDialog_NamesVersionEngineAndLibraryLicences();
    void toolbarAndMenus_HaveIcons_AndTheWindowItsIcon();
    void badSceneFile_ShowsErrorAndKeepsDocument();
    void addSphereLight_UndoRedo();
    void debugViews_ProduceImages();

private:
    std::unique_ptr<MainWindow> window_;
    QStringList errors_;
};

void DesignerTest::init() {
    errors_.clear();
    setErrorHandler([this](const QString& title, const QString& text) { errors_ << title + ": " + text; });
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
    QTest::mouseClick(window_->viewport(), Qt::LeftButton, {}, window_->viewport()->widgetPointOf(x, y));
    QCOMPARE(window_->editor()->selection(), blue);
    OutlinerModel* model = window_->outliner()->outlinerModel();
    QCOMPARE(model->idOf(window_->outliner()->currentIndex()), blue);

    // The raster view draws the outline around the selection.
    const QImage shown = window_->viewport()->frameView()->grabImage().convertToFormat(QImage::Format_RGB888);
    bool outline = false;
    for (int j = 0; j < shown.height() && !outline; ++j)
        for (int i = 0; i < shown.width() && !outline; ++i)
            outline = shown.pixelColor(i, j) == QColor(kOutlineRgb[0], kOutlineRgb[1], kOutlineRgb[2]);
    QVERIFY(outline);

    const ObjectId glass = idOf(*window_, "glass ball");
    window_->outliner()->setCurrentIndex(model->indexOf(glass));
    QCOMPARE(window_->editor()->selection(), glass);
}

void DesignerTest::clickOutsideImage_ClearsSelection() {
    window_->editor()->setSelection(idOf(*window_, "blue ball"));
    // The frame is letterboxed: the viewport's top-left corner lies outside the image.
    Viewport* v = window_->viewport();
    QPoint outside(2, 2);
    if (v->pixelAt(outside)) outside = QPoint(v->width() - 2, v->height() - 2);
    QVERIFY(!v->pixelAt(outside));
    QTest::mouseClick(v, Qt::LeftButton, {}, outside);
    QCOMPARE(window_->editor()->selection(), kNoObject);
}

void DesignerTest::dragSphere_MovesItInDocument_AndUndoRestores() {
    const SceneDocument before = window_->editor()->document();
    const ObjectId blue = idOf(*window_, "blue ball");
    const auto [x, y] = pixelOf(*window_->viewport()->frame(), blue);
    Viewport* v = window_->viewport();
    const QPoint start = v->widgetPointOf(x, y);
    const int stepsBefore = window_->editor()->undoStack()->count();
    QTest::mousePress(v, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(v, start + QPoint(4 * i, 0));
    QTest::mouseRelease(v, Qt::LeftButton, {}, start + QPoint(40, 0));
    const Object* moved = window_->editor()->document().findObject(blue);
    QVERIFY(moved->transform.translate.x > 0.1f);
    QCOMPARE(window_->editor()->undoStack()->count(), stepsBefore + 1);  // One drag, one step.
    QVERIFY(settle(*window_));

    window_->editor()->undoStack()->undo();
    QVERIFY(window_->editor()->document().sameContent(before));
    window_->editor()->undoStack()->redo();
    QVERIFY(window_->editor()->document().findObject(blue)->transform.translate.x > 0.1f);
}

void DesignerTest::dragWithAxisLock_MovesAlongThatAxisOnly_AndEscapeCancels() {
    const SceneDocument before = window_->editor()->document();
    const ObjectId orange = idOf(*window_, "floating ball");
    const auto [x, y] = pixelOf(*window_->viewport()->frame(), orange);
    QCOMPARE(window_->viewport()->frame()->idAt(x, y), orange);
    Viewport* v = window_->viewport();
    const QPoint start = v->widgetPointOf(x, y);
    QTest::mousePress(v, Qt::LeftButton, {}, start);
    QTest::mouseMove(v, start + QPoint(5, 5));
    QTest::keyClick(v, Qt::Key_Y);
    QTest::mouseMove(v, start + QPoint(20, -30));
    const Vec3 t = window_->editor()->document().findObject(orange)->transform.translate;
    QCOMPARE(t.x, 0.0f);
    QCOMPARE(t.z, 0.0f);
    QVERIFY2(t.y > 0.05f, qPrintable(QStringLiteral("%1 %2 %3").arg(t.x).arg(t.y).arg(t.z)));
    QTest::keyClick(v, Qt::Key_Escape);
    QTest::mouseRelease(v, Qt::LeftButton, {}, start + QPoint(20, -30));
    QVERIFY(window_->editor()->document().sameContent(before));
    QVERIFY(!window_->editor()->undoStack()->canUndo());
}

void DesignerTest::propertyEdit_ReRendersFrame_AndSharedMaterialIsShown() {
    const ObjectId blue = idOf(*window_, "blue ball");
    window_->editor()->setSelection(blue);
    const auto [x, y] = pixelOf(*window_->viewport()->frame(), blue);
    const Color beforeColor = window_->viewport()->frame()->color[std::size_t(y) * 160 + x];
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("material"), "color", Vec3(1.0f, 0.0f, 0.0f)));
    QCOMPARE(window_->editor()->document().findMaterial("blue plastic")->color, Vec3(1.0f, 0.0f, 0.0f));
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
    // Glass in one edit: transparency up, and the sphere keeps its place.
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("material"), "transparency", 0.9f));
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
    shadows->setCurrentIndex(int(MovingShadows::Off));
    resolution->setCurrentIndex(int(MovingResolution::Quarter));
    const InteractionPolicy p = window_->session()->session().policy();
    QCOMPARE(p.shadows, MovingShadows::Off);
    QCOMPARE(p.resolution, MovingResolution::Quarter);
    QCOMPARE(loadPreferences().policy, p);  // Stored for the next start.
    dialog->close();
    window_->applyPreferences(Preferences{});
}

void DesignerTest::preferences_RayEngine_RebuildsTheViewportWithIt() {
    QCOMPARE(window_->session()->session().snapshot()->engineKind(), EngineKind::Embree);
    PreferencesDialog* dialog = window_->showPreferences();
    auto* engine = dialog->findChild<QComboBox*>(QStringLiteral("engine"));
    QVERIFY(engine);
    engine->setCurrentIndex(int(EngineKind::Builtin));
    window_->session()->flushUpdate();
    QVERIFY(window_->session()->session().waitUntilComplete(std::chrono::seconds(60)));
    QCOMPARE(window_->session()->session().snapshot()->engineKind(), EngineKind::Builtin);
    QCOMPARE(loadPreferences().engine, EngineKind::Builtin);  // Stored for the next start.
    auto* renderThreads = dialog->findChild<QSpinBox*>(QStringLiteral("renderThreads"));
    QVERIFY(renderThreads);
    renderThreads->setValue(1);  // Render Image leaves the other core to the viewport.
    QCOMPARE(loadPreferences().renderThreads, 1);
    dialog->close();
    window_->applyPreferences(Preferences{});
    window_->session()->flushUpdate();
    QVERIFY(window_->session()->session().waitUntilComplete(std::chrono::seconds(60)));
    QCOMPARE(window_->session()->session().snapshot()->engineKind(), EngineKind::Embree);
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
    QCOMPARE(buttons, 10);
    for (const QString& text : {QStringLiteral("&New"), QStringLiteral("&Open..."), QStringLiteral("&Save"),
                                QStringLiteral("&Delete"), QStringLiteral("&Render Image...")}) {
        QAction* found = nullptr;
        for (QAction* a : window_->findChildren<QAction*>())
            if (a->text() == text) found = a;
        QVERIFY2(found && !found->icon().pixmap(16, 16).isNull(), qPrintable(text));
    }
    // The bundled fallback itself draws (not only a theme that happens to be installed).
    QVERIFY(!QIcon(QStringLiteral(":/icons/actions/add-sphere.svg")).pixmap(24, 24).isNull());
}

void DesignerTest::badSceneFile_ShowsErrorAndKeepsDocument() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.scene.json"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{\n  \"format\": \"raystudio-scene\", \"version\": 1,\n"
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

void DesignerTest::addSphereLight_UndoRedo() {
    QAction* add = window_->findChild<QAction*>(QStringLiteral("add Sphere light"));
    QVERIFY(add);
    const std::size_t lights = window_->editor()->document().lights.size();
    add->trigger();
    QCOMPARE(window_->editor()->document().lights.size(), lights + 1);
    const ObjectId id = window_->editor()->selection();
    QVERIFY(window_->editor()->document().findLight(id));
    QCOMPARE(window_->editor()->document().findLight(id)->type, LightType::Sphere);
    window_->editor()->undoStack()->undo();
    QCOMPARE(window_->editor()->document().lights.size(), lights);
    window_->editor()->undoStack()->redo();
    QCOMPARE(window_->editor()->document().lights.size(), lights + 1);
    QVERIFY(settle(*window_));
}

void DesignerTest::debugViews_ProduceImages() {
    const auto frame = window_->viewport()->frame();
    for (ViewMode m : {ViewMode::Color, ViewMode::ObjectIds, ViewMode::Normals, ViewMode::Depth,
                       ViewMode::Cost, ViewMode::Retraced}) {
        window_->viewport()->setViewMode(m);
        const QImage img = viewportImage(*frame, m, {});
        QCOMPARE(img.size(), QSize(160, 90));
    }
    // Hashed id colours tell neighbouring objects apart.
    uint8_t a[3], b[3];
    idColor(1, a);
    idColor(2, b);
    QVERIFY(a[0] != b[0] || a[1] != b[1] || a[2] != b[2]);
}

QTEST_MAIN(DesignerTest)
#include "designer_test.moc"
