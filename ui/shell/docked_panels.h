// The panels docked around the viewport: the outliner with its name filter on the left, the
// properties on the right, and below them the materials tabbed with the world.
#pragma once

#include <QList>
#include <QObject>

class QAction;
class QMainWindow;

namespace rs::ui {

class MaterialList;
class OutlinerView;
class PropertyPanel;
class SceneEditor;
class WorldPanel;

/// Makes the panels and docks them in `window` (which owns them). Each dock has an object
/// name, so the window's saved state puts it back where the user left it.
class DockedPanels : public QObject {
    Q_OBJECT
public:
    /// `outlinerActions`: the outliner's context menu (Delete, Duplicate).
    DockedPanels(SceneEditor* editor, const QList<QAction*>& outlinerActions, QMainWindow* window);

    OutlinerView* outliner() const { return outliner_; }
    PropertyPanel* properties() const { return properties_; }
    MaterialList* materials() const { return materials_; }
    WorldPanel* world() const { return world_; }

private:
    /// The outliner under a name filter, docked on the left.
    void dockOutliner(SceneEditor* editor, const QList<QAction*>& actions, QMainWindow* window);

    OutlinerView* outliner_ = nullptr;
    PropertyPanel* properties_ = nullptr;
    MaterialList* materials_ = nullptr;
    WorldPanel* world_ = nullptr;
};

}  // namespace rs::ui
