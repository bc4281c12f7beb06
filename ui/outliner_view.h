// The outliner tree: shows OutlinerModel and keeps its selection in step with the editor's.
#pragma once

#include <QTreeView>

namespace rs::ui {

class OutlinerModel;
class SceneEditor;

/// Tree view with two-way selection sync (Ctrl/Shift-click select several) and a context
/// menu of the given actions.
class OutlinerView : public QTreeView {
    Q_OBJECT
public:
    OutlinerView(SceneEditor* editor, QList<QAction*> contextActions, QWidget* parent = nullptr);
    /// The model shown.
    OutlinerModel* outlinerModel() const { return model_; }

private:
    void selectFromEditor();
    void onSelectionChanged();

    SceneEditor* editor_;
    OutlinerModel* model_;
    bool syncing_ = false;
};

}  // namespace rs::ui
