// MainWindow construction: actions, menus, toolbar, docks, status bar and settings.
#include "shell/main_window.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <algorithm>
#include <tuple>

#include "adapter/session_controller.h"
#include "adapter/session_error_relay.h"
#include "document/scene_editor.h"
#include "jobs/background_jobs.h"
#include "jobs/cluster_submit_dialog.h"
#include "jobs/render_queue.h"
#include "shell/action_icons.h"
#include "shell/autosave.h"
#include "shell/command_shortcut_filter.h"
#include "shell/docked_panels.h"
#include "shell/field_wheel_filter.h"
#include "shell/pass_status.h"
#include "shell/render_jobs.h"
#include "shell/shortcuts_dialog.h"
#include "shell/view_bookmarks.h"
#include "snapshot/compiled_scene.h"
#include "viewport/viewport.h"

namespace rs::ui {

namespace {
constexpr int kMaxRecentFiles = 8;

/// The platform's keys for `key`, or `fallback` where it defines none: Save As and Quit have
/// no standard keys on X11 without GNOME or KDE (and offscreen), which left them keyless.
QList<QKeySequence> standardOr(QKeySequence::StandardKey key, const QKeySequence& fallback) {
    const QList<QKeySequence> keys = QKeySequence::keyBindings(key);
    return keys.isEmpty() ? QList<QKeySequence>{fallback} : keys;
}
}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      editor_(new SceneEditor(this)),
      autosave_(new Autosave(editor_, this)),
      prefs_(loadPreferences()) {
    autosave_->setIntervalMs(prefs_.autosaveSeconds * 1000);
    session_ = std::make_unique<SessionController>(prefs_.threads);
    session_->session().setPolicy(prefs_.policy);
    session_->session().setEngine(prefs_.engine);
    sessionErrors_ = std::make_unique<SessionErrorRelay>(
        session_.get(), this, [this](const QString& message) { onSessionError(message); });
    session_->session().setObserver(sessionErrors_.get());
    viewport_ = new Viewport(editor_, session_.get(), this, prefs_.display);
    viewport_->setPreviewDivider(prefs_.previewDivider);
    setCentralWidget(viewport_);
    setAcceptDrops(true);

    // The viewport posts the document to the session itself, seen through its view camera.
    connect(viewport_, &Viewport::statusMessage, this, [this](const QString& text) {
        if (text.isEmpty())
            statusBar()->clearMessage();
        else
            statusBar()->showMessage(text);
    });
    connect(editor_->undoStack(), &QUndoStack::cleanChanged, this,
            [this](bool clean) { setWindowModified(!clean); });
    connect(editor_, &SceneEditor::filePathChanged, this, &MainWindow::updateTitle);
    // Back from another program (a paint program, say): show the images saved meanwhile.
    connect(qApp, &QGuiApplication::applicationStateChanged, editor_,
            [this](Qt::ApplicationState state) {
                if (state == Qt::ApplicationActive) editor_->reloadImages();
            });
    connect(session_.get(), &SessionController::passFinished, this, [this](const PassInfo& info) {
        passStatus_->showPass(info);
        if (const auto snapshot = session_->session().snapshot())
            passStatus_->showImageProblems(snapshot->problems());
    });
    connect(session_.get(), &SessionController::updateRateChanged, this,
            [this](double rate) { passStatus_->showUpdateRate(rate); });
    connect(autosave_, &Autosave::failed, this, [this](const QString& error) {
        statusBar()->showMessage(tr("Autosave failed: %1").arg(error), 10000);
    });

    renders_ = new RenderJobs(session_.get(), this);
    createActions();
    panels_ = new DockedPanels(editor_, {deleteAct_, duplicateAct_}, this);
    createMenus();
    createStatusBar();
    new CommandShortcutFilter(this);
    new FieldWheelFilter(this);
    readSettings();
    updateTitle();
    editor_->resetDocument(SceneDocument{}, {});
}

OutlinerView* MainWindow::outliner() const {
    return panels_->outliner();
}
PropertyPanel* MainWindow::propertyPanel() const {
    return panels_->properties();
}
MaterialList* MainWindow::materialList() const {
    return panels_->materials();
}
WorldPanel* MainWindow::worldPanel() const {
    return panels_->world();
}
RenderQueue* MainWindow::renderQueue() const {
    return renders_->queue();
}
RenderWindow* MainWindow::renderWindow() const {
    return renders_->window();
}
RenderStatus* MainWindow::renderStatus() const {
    return renders_->status();
}

MainWindow::~MainWindow() {
    // A gesture still running would end (focus lost) when the viewport goes, after the
    // session it edits through.
    viewport_->cancelInteraction();
    // Before the session and the widgets a job reports to go.
    renders_->queue()->cancelAll();
    cancelJobs(this);
}

void MainWindow::createActions() {
    deleteAct_ = new QAction(actionIcon("edit-delete", "edit-delete"), tr("&Delete"), this);
    deleteAct_->setShortcuts({QKeySequence::Delete, QKeySequence(Qt::Key_Backspace)});
    deleteAct_->setShortcutContext(Qt::WindowShortcut);
    connect(deleteAct_, &QAction::triggered, this, &MainWindow::deleteSelection);
    duplicateAct_ = new QAction(tr("D&uplicate"), this);
    duplicateAct_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    connect(duplicateAct_, &QAction::triggered, this, &MainWindow::duplicateSelection);

    auto shape = [this](const QString& text, ShapeKind kind, const char* icon) {
        auto* a = new QAction(actionIcon(nullptr, icon), text, this);
        a->setStatusTip(tr("Add a %1 in front of the camera").arg(text.toLower()));
        connect(a, &QAction::triggered, this, [this, kind] { addShapeAction(kind); });
        addActions_.append(a);
    };
    shape(tr("Sphere"), ShapeKind::Sphere, "add-sphere");
    shape(tr("Plane"), ShapeKind::Plane, "add-plane");
    shape(tr("Rectangle"), ShapeKind::Rectangle, "add-rectangle");
    shape(tr("Box"), ShapeKind::Box, "add-box");
    auto* mesh = new QAction(actionIcon(nullptr, "add-mesh"), tr("Mesh..."), this);
    connect(mesh, &QAction::triggered, this, &MainWindow::importMeshDialog);
    addActions_.append(mesh);
    auto light = [this](const QString& text, LightType type, const char* icon) {
        auto* a = new QAction(actionIcon(nullptr, icon), text, this);
        connect(a, &QAction::triggered, this, [this, type] {
            if (type == LightType::Spot || type == LightType::Directional)
                addAimedLightAction(type);
            else
                addLightAction(type);
        });
        addActions_.append(a);
    };
    light(tr("Point light"), LightType::Point, "add-point-light");
    light(tr("Sphere light"), LightType::Sphere, "add-sphere-light");
    light(tr("Spot light"), LightType::Spot, "add-spot-light");
    light(tr("Sun light"), LightType::Directional, "add-sun-light");
    for (QAction* a : addActions_) a->setObjectName(QStringLiteral("add ") + a->text());

    // Placement (issue 11): new objects rest on the surface under the view centre, or with
    // this on, on the floor below that point. Kept across sessions.
    snapToFloorAct_ = new QAction(tr("Snap Dropped Meshes to &Floor"), this);
    snapToFloorAct_->setObjectName(QStringLiteral("snapToFloor"));
    snapToFloorAct_->setCheckable(true);
    snapToFloorAct_->setStatusTip(
        tr("A mesh dropped on the viewport drops onto the surface below"));
    snapToFloorAct_->setChecked(
        QSettings().value(QStringLiteral("placement/snapToFloor")).toBool());
    connect(snapToFloorAct_, &QAction::toggled, this,
            [](bool on) { QSettings().setValue(QStringLiteral("placement/snapToFloor"), on); });
}

void MainWindow::addAimedLightAction(LightType type) {
    // A spot hangs in front of the view above the floor, aimed at the floor below it; a sun
    // (no position) has its glyph drawn there.
    SceneDocument doc = editor_->document();
    const ObjectId id = addLight(doc, type, Vec3(0.0f));
    const Vec3 ground = placeNewInView(doc, id);
    Light* l = doc.findLight(id);
    if (type == LightType::Spot) l->target = ground;  // Hung above the floor, aimed at it.
    const QString text = tr("Add %1").arg(QString::fromStdString(l->name));
    editor_->edit(text, std::move(doc));
    editor_->setSelection(id);
}

void MainWindow::createMenus() {
    createFileMenu();
    const std::pair<QAction*, QAction*> undoRedo = createEditMenu();
    createAddMenu();
    QMenu* view = createViewMenu();
    QAction* renderAct = createRenderMenu();
    createHelpMenu();

    QToolBar* tools = addToolBar(tr("Add"));
    tools->setObjectName(QStringLiteral("addToolBar"));
    // Icons with their names: a newcomer reads which shape each one adds.
    tools->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    tools->addActions(addActions_);
    tools->addSeparator();
    tools->addAction(undoRedo.first);
    tools->addAction(undoRedo.second);
    tools->addAction(renderAct);
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        view->addAction(dock->toggleViewAction());
    view->addAction(tools->toggleViewAction());
}

void MainWindow::createFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, this, &MainWindow::newFile)
        ->setIcon(actionIcon("document-new", "document-new"));
    file->addAction(tr("&Open..."), QKeySequence::Open, this, &MainWindow::open)
        ->setIcon(actionIcon("document-open", "document-open"));
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save)
        ->setIcon(actionIcon("document-save", "document-save"));
    file->addAction(tr("Save &As..."), this, &MainWindow::saveAs)
        ->setShortcuts(
            standardOr(QKeySequence::SaveAs, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)));
    file->addSeparator();
    file->addAction(tr("&Import..."), QKeySequence(Qt::CTRL | Qt::Key_I), this,
                    &MainWindow::importMeshDialog);
    file->addAction(tr("&Export Image..."), QKeySequence(Qt::CTRL | Qt::Key_E), this,
                    &MainWindow::exportImageDialog);
    file->addAction(tr("Re&load Images"), editor_, &SceneEditor::reloadImages)
        ->setObjectName(QStringLiteral("reloadImages"));
    file->addSeparator();
    file->addAction(tr("&Quit"), this, &QWidget::close)
        ->setShortcuts(standardOr(QKeySequence::Quit, QKeySequence(Qt::CTRL | Qt::Key_Q)));
    updateRecentFileActions();
}

std::pair<QAction*, QAction*> MainWindow::createEditMenu() {
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = editor_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcuts(QKeySequence::Undo);
    undo->setIcon(actionIcon("edit-undo", "edit-undo"));
    QAction* redo = editor_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcuts(QKeySequence::Redo);
    redo->setIcon(actionIcon("edit-redo", "edit-redo"));
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addAction(deleteAct_);
    edit->addAction(duplicateAct_);
    edit->addSeparator();
    // Blender's modal transforms; while one runs the viewport takes every key.
    const std::pair<QString, TransformKind> gestures[] = {{tr("&Move"), TransformKind::Move},
                                                          {tr("R&otate"), TransformKind::Rotate},
                                                          {tr("&Scale"), TransformKind::Scale}};
    const Qt::Key gestureKeys[] = {Qt::Key_G, Qt::Key_R, Qt::Key_S};
    for (int i = 0; i < 3; ++i)
        edit->addAction(gestures[i].first, QKeySequence(gestureKeys[i]), viewport_,
                        [this, kind = gestures[i].second] { viewport_->beginTransform(kind); });
    // The gizmo's and G/R/S axis locks' orientation (Blender's Global / Local).
    QAction* local = edit->addAction(tr("&Local Axes"), viewport_, &Viewport::setLocalOrientation);
    local->setObjectName(QStringLiteral("localAxes"));
    local->setCheckable(true);
    local->setStatusTip(tr("Gizmo and axis locks along the active object's own axes"));
    edit->addSeparator();
    edit->addAction(tr("&Box Select"), QKeySequence(Qt::Key_B), viewport_,
                    &Viewport::beginBoxSelect);
    edit->addSeparator();
    edit->addAction(tr("&Preferences..."), QKeySequence::Preferences, this,
                    &MainWindow::showPreferences);

    return {undo, redo};
}

void MainWindow::createAddMenu() {
    QMenu* add = menuBar()->addMenu(tr("&Add"));
    add->addActions(addActions_.mid(0, 5));
    add->addSeparator();
    add->addActions(addActions_.mid(5));
    add->addSeparator();
    add->addAction(snapToFloorAct_);
}

QMenu* MainWindow::createViewMenu() {
    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("&Frame Selection"), QKeySequence(Qt::Key_F), viewport_,
                    &Viewport::frameSelection);
    QAction* gizmo = view->addAction(tr("Show &Gizmo"), viewport_, &Viewport::setGizmoVisible);
    gizmo->setObjectName(QStringLiteral("showGizmo"));
    gizmo->setCheckable(true);
    gizmo->setChecked(viewport_->gizmoVisible());
    view->addSeparator();
    // Navigation moves the view camera only; these two are the bridges to the scene camera
    // (Blender's Numpad 0 and Ctrl+Alt+Numpad 0).
    view->addAction(tr("&Through Scene Camera"), QKeySequence(Qt::Key_0), viewport_,
                    &Viewport::viewThroughSceneCamera);
    view->addAction(tr("Scene Camera from &View"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_0),
                    viewport_, &Viewport::sceneCameraFromView);
    bookmarks_ = new ViewBookmarks(editor_, viewport_, this);
    view->addMenu(bookmarks_->menu());
    QMenu* axes = view->addMenu(tr("&Axis Views"));
    const std::tuple<QString, AxisView, QKeySequence> axisViews[] = {
        {tr("&Front"), AxisView::Front, QKeySequence(Qt::Key_1)},
        {tr("&Back"), AxisView::Back, QKeySequence(Qt::CTRL | Qt::Key_1)},
        {tr("&Right"), AxisView::Right, QKeySequence(Qt::Key_3)},
        {tr("&Left"), AxisView::Left, QKeySequence(Qt::CTRL | Qt::Key_3)},
        {tr("&Top"), AxisView::Top, QKeySequence(Qt::Key_7)},
        {tr("B&ottom"), AxisView::Bottom, QKeySequence(Qt::CTRL | Qt::Key_7)}};
    for (const auto& [text, axis, keys] : axisViews)
        axes->addAction(text, keys, viewport_, [this, a = axis] { viewport_->setAxisView(a); });
    view->addSeparator();
    auto* modes = new QActionGroup(this);
    const std::pair<QString, ViewMode> entries[] = {
        {tr("&Colour"), ViewMode::Color},          {tr("Object &ids"), ViewMode::ObjectIds},
        {tr("&Normals"), ViewMode::Normals},       {tr("&Depth"), ViewMode::Depth},
        {tr("Ray &cost heatmap"), ViewMode::Cost}, {tr("&Re-traced pixels"), ViewMode::Retraced}};
    int n = 1;
    for (const auto& [text, mode] : entries) {
        QAction* a = view->addAction(text, QKeySequence(Qt::ALT | Qt::Key(Qt::Key_0 + n++)),
                                     viewport_, [this, m = mode] { viewport_->setViewMode(m); });
        a->setCheckable(true);
        a->setChecked(mode == ViewMode::Color);
        modes->addAction(a);
    }
    view->addSeparator();

    return view;
}

QAction* MainWindow::createRenderMenu() {
    QMenu* render = menuBar()->addMenu(tr("&Render"));
    QAction* renderAct = render->addAction(tr("&Render Image..."), QKeySequence(Qt::Key_F12), this,
                                           &MainWindow::renderImageDialog);
    renderAct->setIcon(actionIcon(nullptr, "render-image"));
    if (clusterSubmitAvailable())  // only where Slurm's client is installed
        render->addAction(tr("Submit to &Cluster..."), this, &MainWindow::submitToClusterDialog);
    render->addAction(tr("&Export Current Frame..."), this, &MainWindow::exportImageDialog);
    render->addAction(tr("Show Render &Window"), renders_, &RenderJobs::showWindow);

    return renderAct;
}

void MainWindow::createHelpMenu() {
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showShortcuts)
        ->setObjectName(QStringLiteral("keyboardShortcuts"));
    help->addAction(tr("&About RayStudio"), this, &MainWindow::about);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

void MainWindow::createStatusBar() {
    passStatus_ = new PassStatus(statusBar(), this);
    renders_->addStatusField(statusBar());
    statusBar()->showMessage(tr("Ready"), 2000);
}

void MainWindow::onSessionError(const QString& message) {
    // The status bar, not a dialog: a failure while dragging must not grab the mouse. The
    // session keeps the document and tries again at the next edit.
    passStatus_->showFailed();
    statusBar()->showMessage(
        tr("The viewport could not render: %1. The scene is unchanged; edit it (e.g. a smaller "
           "render size) to try again.")
            .arg(message));
}

void MainWindow::readSettings() {
    QSettings s;
    if (!restoreGeometry(s.value(QStringLiteral("window/geometry")).toByteArray()))
        resize(1400, 850);
    restoreState(s.value(QStringLiteral("window/state")).toByteArray());
}

void MainWindow::writeSettings() {
    QSettings s;
    s.setValue(QStringLiteral("window/geometry"), saveGeometry());
    s.setValue(QStringLiteral("window/state"), saveState());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (renders_->maybeCancel() && maybeSave()) {
        writeSettings();
        renders_->closeAll();
        cancelJobs(this);
        autosave_->discard();  // A clean exit: nothing to recover next time.
        event->accept();
    } else {
        event->ignore();
    }
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings s;
    QStringList files = s.value(QStringLiteral("recentFiles")).toStringList();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    s.setValue(QStringLiteral("recentFiles"), files);
    updateRecentFileActions();
}

void MainWindow::updateRecentFileActions() {
    recentMenu_->clear();
    const QStringList files = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (const QString& f : files)
        recentMenu_->addAction(f, this, [this, f] {
            if (maybeSave()) openFile(f);
        });
    recentMenu_->setEnabled(!files.isEmpty());
}

void MainWindow::updateTitle() {
    const QString path = editor_->filePath();
    setWindowFilePath(path.isEmpty() ? tr("untitled.scene.json") : path);
    setWindowTitle(QStringLiteral("%1[*] - RayStudio")
                       .arg(path.isEmpty() ? tr("untitled") : QFileInfo(path).fileName()));
}

PreferencesDialog* MainWindow::showPreferences() {
    auto* dialog = new PreferencesDialog(prefs_, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &PreferencesDialog::changed, this, &MainWindow::applyPreferences);
    dialog->show();
    return dialog;
}

void MainWindow::applyPreferences(const Preferences& prefs) {
    if (prefs.threads != prefs_.threads) session_->session().setThreads(prefs.threads);
    const bool engineChanged = prefs.engine != prefs_.engine;
    if (prefs.autosaveSeconds != prefs_.autosaveSeconds)
        autosave_->setIntervalMs(prefs.autosaveSeconds * 1000);
    prefs_ = prefs;
    session_->session().setPolicy(prefs.policy);
    viewport_->setPreviewDivider(prefs.previewDivider);
    viewport_->setDisplay(prefs.display);
    if (engineChanged) {
        // The next update rebuilds the snapshot with the other engine; post one now.
        session_->session().setEngine(prefs.engine);
        session_->requestUpdate(viewport_->viewDocument());
    }
    savePreferences(prefs);
}

QDialog* MainWindow::showShortcuts() {
    return showShortcutsDialog(this, menuShortcuts(menuBar()));
}

void MainWindow::about() {
    // The libraries RayStudio is built on, with the licence each is distributed under.
    QMessageBox::about(
        this, tr("About RayStudio"),
        tr("<b>RayStudio</b> %1<br>An interactive Whitted ray-traced scene designer.<br>"
           "Ray engine in use: %2<br><br>Built with:<ul>"
           "<li>Qt %3 (LGPL 3)</li><li>Embree 3 (Apache 2.0)</li><li>oneTBB (Apache 2.0)</li>"
           "<li>OpenImageIO (Apache 2.0)</li><li>Open Asset Import Library (BSD 3-clause)</li>"
           "<li>GLM (MIT)</li><li>JSON for Modern C++ (MIT)</li></ul>")
            .arg(QApplication::applicationVersion(), QString::fromLatin1(engineName(prefs_.engine)),
                 QString::fromLatin1(qVersion())));
}

}  // namespace rs::ui
