// The designer's main window: viewport in the centre, outliner and properties docked,
// actions, menus, toolbar, status bar, file handling and settings.
#pragma once

#include <QMainWindow>
#include <QPoint>
#include <memory>
#include <optional>
#include <utility>

#include "document/placement.h"
#include "document/scene_edits.h"
#include "shell/preferences.h"

class QAction;
class QDialog;
class QMenu;

namespace rs {
struct AssetContent;
struct PassInfo;
}  // namespace rs

namespace rs::ui {

class Autosave;
class DockedPanels;
class MaterialList;
class ClusterSubmitDialog;
class OutlinerView;
class PassStatus;
class ViewBookmarks;
class PropertyPanel;
class RenderJobs;
class RenderQueue;
class RenderStatus;
class RenderWindow;
class SceneEditor;
class SessionController;
class SessionErrorRelay;
class Viewport;
class WorldPanel;

/// Top-level window of RayStudio.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Opens a scene file; on error reports it and keeps the current document.
    bool openFile(const QString& path);
    /// Saves to `path` (atomically); false and an error report on failure.
    bool saveFile(const QString& path);
    /// Imports a mesh file (worker thread + progress dialog) onto the surface under widget
    /// point `at` of the viewport (its centre when none), scaled to fit the view.
    void importMesh(const QString& path, std::optional<QPoint> at = std::nullopt);
    /// Exports the current viewport frame to an image file, at the viewport's traced size (not
    /// the output size: that is Render Image's); the status bar names the size written.
    bool exportFrame(const QString& path);
    /// Queues a full-quality render of the document as it is now at width x height into
    /// `path` (Render -> Render Image without its size and file dialogs): it runs in the
    /// background, one at a time, shown in the Render window with progress and Cancel in the
    /// status bar; closing the window cancels it. A render estimated over the cost budget
    /// (integrator/cost_estimate.h) is queued only if the user confirms; false when it is not.
    bool renderImage(const QString& path, int width, int height);
    /// Render -> Submit to Cluster...: once the scene is saved (the nodes read the file, so an
    /// unsaved or modified scene is saved first, if the user agrees), opens the non-modal
    /// farm-submit dialog and returns it; null when the scene was not saved.
    ClusterSubmitDialog* submitToClusterDialog();
    /// Overrides the render size of the open document without an undo step (tests).
    void setRenderSize(int width, int height);
    /// Opens the (non-modal) preferences dialog and returns it.
    PreferencesDialog* showPreferences();
    /// Opens Help -> Keyboard Shortcuts (every menu shortcut, read from the actions).
    QDialog* showShortcuts();
    /// Applies preferences to the session and stores them.
    void applyPreferences(const Preferences& prefs);

    /// How offerRecovery() answers: ask the user, or (tests, --recover) decide up front.
    enum class RecoveryAnswer { Ask, Recover, Discard };
    /// Offers the newest autosave a crashed session left (Recover, Discard or Not now);
    /// true when it replaced the document.
    bool offerRecovery(RecoveryAnswer answer = RecoveryAnswer::Ask);
    /// Overrides Preferences' autosave interval for this session (0: off).
    void setAutosaveIntervalMs(int ms);
    /// This session's autosave (its file exists only while there are unsaved changes).
    Autosave* autosave() const { return autosave_; }

    SceneEditor* editor() const { return editor_; }
    SessionController* session() const { return session_.get(); }
    Viewport* viewport() const { return viewport_; }
    OutlinerView* outliner() const;
    PropertyPanel* propertyPanel() const;
    MaterialList* materialList() const;
    WorldPanel* worldPanel() const;
    RenderQueue* renderQueue() const;
    RenderWindow* renderWindow() const;
    RenderStatus* renderStatus() const;
    ViewBookmarks* viewBookmarks() const { return bookmarks_; }

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createFileMenu();
    /// Returns the undo and redo actions (the toolbar shows them too).
    std::pair<QAction*, QAction*> createEditMenu();
    void createAddMenu();
    /// Returns the View menu (the docks' and toolbar's toggles go last).
    QMenu* createViewMenu();
    /// Returns Render Image (the toolbar shows it too).
    QAction* createRenderMenu();
    void createHelpMenu();
    void createStatusBar();
    void readSettings();
    void writeSettings();
    bool maybeSave();
    void newFile();
    void open();
    bool save();
    bool saveAs();
    void importMeshDialog();
    void exportImageDialog();
    void renderImageDialog();
    void about();
    void addRecentFile(const QString& path);
    void updateRecentFileActions();
    void updateTitle();
    /// Where a new object goes: the view ray through widget point `at` of the viewport (its
    /// centre when none), cast into the session's scene.
    Placement placementAt(std::optional<QPoint> at) const;
    /// Places new object or light `id` of `doc` at `at`: resting on the surface there, or
    /// on the floor below it with Add -> Snap to Floor.
    void placeNew(SceneDocument& doc, ObjectId id, const Placement& at) const;
    /// Places new `id` in front of the view, on the floor, clear of other objects
    /// (placeInView); returns the floor point under it.
    Vec3 placeNewInView(SceneDocument& doc, ObjectId id) const;
    void onSessionError(const QString& message);
    void addShapeAction(ShapeKind kind);
    void addLightAction(LightType type);
    /// Add -> Spot light (above the point the view looks at, aimed at it) or Sun light.
    void addAimedLightAction(LightType type);
    void deleteSelection();
    void duplicateSelection();
    /// Asks what becomes of the cameras an imported asset brings (mesh object `id` named
    /// `name`): the scene camera and view bookmarks, bookmarks only, or nothing. Returns the
    /// number of views added to `doc`.
    std::size_t adoptAssetCameras(SceneDocument& doc, ObjectId id, const AssetContent& asset,
                                  const QString& name);

    SceneEditor* editor_;
    Autosave* autosave_;
    std::unique_ptr<SessionErrorRelay> sessionErrors_;  ///< Outlives session_'s threads.
    std::unique_ptr<SessionController> session_;
    Viewport* viewport_;
    DockedPanels* panels_ = nullptr;
    RenderJobs* renders_ = nullptr;
    ViewBookmarks* bookmarks_ = nullptr;
    Preferences prefs_;

    QAction* deleteAct_ = nullptr;
    QAction* duplicateAct_ = nullptr;
    QAction* snapToFloorAct_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    PassStatus* passStatus_ = nullptr;
    QList<QAction*> addActions_;
};

}  // namespace rs::ui
