// OutlinerView: selection sync both ways (several rows: Qt's extended selection), rename in
// place, context menu.
#include "panels/outliner_view.h"

#include <QHeaderView>
#include <QSortFilterProxyModel>

#include "document/scene_editor.h"
#include "panels/outliner_model.h"

namespace rs::ui {

OutlinerView::OutlinerView(SceneEditor* editor, QList<QAction*> contextActions, QWidget* parent)
    : QTreeView(parent),
      editor_(editor),
      model_(new OutlinerModel(editor, this)),
      filter_(new QSortFilterProxyModel(this)) {
    filter_->setSourceModel(model_);
    // A group row shows while one of its rows matches; an edit re-tests only its rows.
    filter_->setRecursiveFilteringEnabled(true);
    filter_->setFilterCaseSensitivity(Qt::CaseInsensitive);
    setModel(filter_);
    // Every row is one line: the view need not measure 100,000 rows to lay them out.
    setUniformRowHeights(true);
    header()->hide();
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    setContextMenuPolicy(Qt::ActionsContextMenu);
    addActions(contextActions);
    expandGroups();
    connect(filter_, &QAbstractItemModel::modelReset, this, [this] {
        expandGroups();
        selectFromEditor();
    });
    connect(filter_, &QAbstractItemModel::rowsInserted, this, [this](const QModelIndex& parent) {
        expand(parent);  // a group that was empty was never expanded
        selectFromEditor();
    });
    // The current row is the active entity, so it is read with the selection: selecting
    // moves the current index first, then changes the selection.
    connect(selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &OutlinerView::onSelectionChanged);
    connect(editor_, &SceneEditor::selectionChanged, this, &OutlinerView::selectFromEditor);
}

void OutlinerView::expandGroups() {
    // The groups only: expandAll() asks each of 100,000 rows whether it has children.
    for (int r = 0; r < filter_->rowCount(); ++r) expand(filter_->index(r, 0));
}

void OutlinerView::setNameFilter(const QString& text) {
    // Rows the filter hides leave the view's selection, not the editor's.
    syncing_ = true;
    filter_->setFilterFixedString(text);
    syncing_ = false;
    expandGroups();
    selectFromEditor();
}

QModelIndex OutlinerView::indexOf(ObjectId id) const {
    return filter_->mapFromSource(model_->indexOf(id));
}

ObjectId OutlinerView::idOf(const QModelIndex& viewIndex) const {
    return model_->idOf(filter_->mapToSource(viewIndex));
}

void OutlinerView::selectFromEditor() {
    if (syncing_) return;
    syncing_ = true;
    QItemSelection rows;
    const ObjectId active = editor_->selection();
    if (active == SceneEditor::kCameraSelection) {
        const QModelIndex i = indexOf(active);
        rows.select(i, i);
    }
    for (ObjectId id : editor_->selectedIds()) {
        const QModelIndex i = indexOf(id);
        if (i.isValid()) rows.select(i, i);
    }
    selectionModel()->select(rows, QItemSelectionModel::ClearAndSelect);
    const QModelIndex current = indexOf(active);
    if (current.isValid()) {
        selectionModel()->setCurrentIndex(current, QItemSelectionModel::NoUpdate);
        scrollTo(current);
    } else {
        selectionModel()->setCurrentIndex({}, QItemSelectionModel::NoUpdate);
    }
    syncing_ = false;
}

void OutlinerView::onSelectionChanged() {
    if (syncing_) return;
    syncing_ = true;
    std::vector<ObjectId> ids;
    bool camera = false;
    const ObjectId current = idOf(currentIndex());
    for (const QModelIndex& i : selectionModel()->selectedRows()) {
        const ObjectId id = idOf(i);
        if (id == SceneEditor::kCameraSelection)
            camera = true;
        else if (id != kNoObject && id != current)
            ids.push_back(id);
    }
    // The current row, when selected, is the active one: last.
    if (current != kNoObject && current != SceneEditor::kCameraSelection &&
        selectionModel()->isSelected(currentIndex()))
        ids.push_back(current);
    if (camera && ids.empty())
        editor_->setSelection(SceneEditor::kCameraSelection);
    else
        editor_->setSelection(ids);
    syncing_ = false;
}

}  // namespace rs::ui
