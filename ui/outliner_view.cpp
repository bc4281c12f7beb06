// OutlinerView: selection sync both ways, rename in place, context menu.
#include "outliner_view.h"

#include "outliner_model.h"
#include "scene_editor.h"

#include <QHeaderView>

namespace rs::ui {

OutlinerView::OutlinerView(SceneEditor* editor, QList<QAction*> contextActions, QWidget* parent)
    : QTreeView(parent), editor_(editor), model_(new OutlinerModel(editor, this)) {
    setModel(model_);
    header()->hide();
    setSelectionMode(QAbstractItemView::SingleSelection);
    setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    setContextMenuPolicy(Qt::ActionsContextMenu);
    addActions(contextActions);
    expandAll();
    connect(model_, &QAbstractItemModel::modelReset, this, [this] {
        expandAll();
        selectFromEditor();
    });
    connect(selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& current) { onCurrentChanged(current); });
    connect(editor_, &SceneEditor::selectionChanged, this, &OutlinerView::selectFromEditor);
}

void OutlinerView::selectFromEditor() {
    if (syncing_) return;
    syncing_ = true;
    const QModelIndex i = model_->indexOf(editor_->selection());
    if (i.isValid()) {
        selectionModel()->setCurrentIndex(i, QItemSelectionModel::ClearAndSelect);
        scrollTo(i);
    } else {
        selectionModel()->clearSelection();
        selectionModel()->setCurrentIndex({}, QItemSelectionModel::Clear);
    }
    syncing_ = false;
}

void OutlinerView::onCurrentChanged(const QModelIndex& current) {
    if (syncing_) return;
    syncing_ = true;
    editor_->setSelection(model_->idOf(current));
    syncing_ = false;
}

}  // namespace rs::ui
