// The outliner tree: shows OutlinerModel and keeps its selection in step with the editor's.
#pragma once

#include <QTreeView>

#include "scene/document.h"

class QSortFilterProxyModel;

namespace rs::ui {

class OutlinerModel;
class SceneEditor;

/// Tree view with two-way selection sync (Ctrl/Shift-click select several) and a context
/// menu of the given actions.
class OutlinerView : public QTreeView {
    Q_OBJECT
public:
    OutlinerView(SceneEditor* editor, QList<QAction*> contextActions, QWidget* parent = nullptr);
    /// The model shown (through the name filter).
    OutlinerModel* outlinerModel() const { return model_; }
    /// Shows only the lights and objects whose name contains `text` (any case), and the
    /// groups holding them; empty shows all. The editor's selection is kept as it is.
    void setNameFilter(const QString& text);
    /// The view's row of a light, object or the camera; invalid when absent or filtered out.
    QModelIndex indexOf(ObjectId id) const;
    /// The id a row of this view stands for (OutlinerModel::idOf).
    ObjectId idOf(const QModelIndex& viewIndex) const;

private:
    /// Opens the Lights and Objects groups.
    void expandGroups();
    void selectFromEditor();
    void onSelectionChanged();

    SceneEditor* editor_;
    OutlinerModel* model_;
    QSortFilterProxyModel* filter_;
    bool syncing_ = false;
};

}  // namespace rs::ui
