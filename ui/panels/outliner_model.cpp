// OutlinerModel: rows are cached (id, name, visibility) so an edit signals only what it changed.
#include "panels/outliner_model.h"

#include <algorithm>

#include "core/id_search.h"
#include "document/scene_editor.h"
#include "document/scene_edits.h"

namespace rs::ui {

namespace {
// internalId of top-level rows; children carry the row's group + 1 so parent() can find it.
enum Group : quintptr { kCameraRow = 0, kLightsRow = 1, kObjectsRow = 2, kTopLevel = 100 };

template <class Row>
std::vector<Row> rowsFor(const std::vector<Light>& lights) {
    std::vector<Row> rows;
    rows.reserve(lights.size());
    for (const Light& l : lights) rows.push_back({l.id, l.name, true});
    return rows;
}
template <class Row>
std::vector<Row> rowsFor(const SharedList<Object>& objects) {
    std::vector<Row> rows;
    rows.reserve(objects.size());
    for (const Object& o : objects) rows.push_back({o.id, o.name, o.visible});
    return rows;
}

/// Rows a and b agree on ids in [0, n).
template <class Row>
std::size_t commonPrefix(const std::vector<Row>& a, const std::vector<Row>& b) {
    std::size_t n = 0;
    while (n < a.size() && n < b.size() && a[n].id == b[n].id) ++n;
    return n;
}
template <class Row>
std::size_t commonSuffix(const std::vector<Row>& a, const std::vector<Row>& b, std::size_t skip) {
    std::size_t n = 0;
    while (n + skip < a.size() && n + skip < b.size() &&
           a[a.size() - 1 - n].id == b[b.size() - 1 - n].id)
        ++n;
    return n;
}
}  // namespace

OutlinerModel::OutlinerModel(SceneEditor* editor, QObject* parent)
    : QAbstractItemModel(parent), editor_(editor) {
    lightRows_ = rowsFor<Row>(editor_->document().lights);
    objectRows_ = rowsFor<Row>(editor_->document().objects);
    connect(editor_, &SceneEditor::documentChanged, this, &OutlinerModel::onDocumentChanged);
}

const std::vector<OutlinerModel::Row>& OutlinerModel::rowsOf(int group) const {
    return group == kLightsRow ? lightRows_ : objectRows_;
}

bool OutlinerModel::update(int group, std::vector<Row>& cached, const std::vector<Row>& rows) {
    const QModelIndex parent = index(group, 0);
    const std::size_t head = commonPrefix(cached, rows);
    const std::size_t tail = commonSuffix(cached, rows, head);
    const std::size_t removed = cached.size() - head - tail;
    const std::size_t added = rows.size() - head - tail;
    if (removed > 0 && added > 0) return false;  // ids replaced or reordered
    if (removed > 0) {
        beginRemoveRows(parent, int(head), int(head + removed - 1));
        cached.erase(cached.begin() + std::ptrdiff_t(head),
                     cached.begin() + std::ptrdiff_t(head + removed));
        endRemoveRows();
    } else if (added > 0) {
        beginInsertRows(parent, int(head), int(head + added - 1));
        cached.insert(cached.begin() + std::ptrdiff_t(head), rows.begin() + std::ptrdiff_t(head),
                      rows.begin() + std::ptrdiff_t(head + added));
        endInsertRows();
    }
    // Same ids now: signal each run of rows whose text or check changed, and only those.
    for (std::size_t r = 0; r < rows.size();) {
        if (cached[r] == rows[r]) {
            ++r;
            continue;
        }
        const std::size_t first = r;
        while (r < rows.size() && !(cached[r] == rows[r])) {
            cached[r] = rows[r];
            ++r;
        }
        Q_EMIT dataChanged(index(int(first), 0, parent), index(int(r - 1), 0, parent));
    }
    return true;
}

void OutlinerModel::onDocumentChanged() {
    const SceneDocument& doc = editor_->document();
    const DocumentChange& change = editor_->lastChange();
    if (!change.lights && !change.objectsRestructured && objectRows_.size() == doc.objects.size()) {
        // Objects kept their places: only the rows the edit renamed, hid or showed change.
        const QModelIndex parent = index(kObjectsRow, 0);
        for (const DocumentChange::ObjectEdit& e : change.objects) {
            if (!(e.fields & (DocumentChange::kName | DocumentChange::kVisible))) continue;
            const Object& o = doc.objects[e.index];
            objectRows_[e.index] = {o.id, o.name, o.visible};
            const QModelIndex row = index(int(e.index), 0, parent);
            Q_EMIT dataChanged(row, row);
        }
        return;
    }
    auto lights = rowsFor<Row>(doc.lights);
    auto objects = rowsFor<Row>(doc.objects);
    if (update(kLightsRow, lightRows_, lights) && update(kObjectsRow, objectRows_, objects)) return;
    beginResetModel();
    lightRows_ = std::move(lights);
    objectRows_ = std::move(objects);
    endResetModel();
}

QModelIndex OutlinerModel::index(int row, int column, const QModelIndex& parent) const {
    if (!hasIndex(row, column, parent)) return {};
    if (!parent.isValid()) return createIndex(row, column, quintptr(kTopLevel));
    return createIndex(row, column, quintptr(parent.row()));
}

QModelIndex OutlinerModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || child.internalId() == kTopLevel) return {};
    return createIndex(int(child.internalId()), 0, quintptr(kTopLevel));
}

int OutlinerModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid()) return 3;
    if (parent.internalId() != kTopLevel || parent.column() != 0) return 0;
    if (parent.row() == kLightsRow || parent.row() == kObjectsRow)
        return int(rowsOf(parent.row()).size());
    return 0;
}

int OutlinerModel::columnCount(const QModelIndex&) const {
    return 1;
}

ObjectId OutlinerModel::idOf(const QModelIndex& i) const {
    if (!i.isValid()) return kNoObject;
    if (i.internalId() == kTopLevel)
        return i.row() == kCameraRow ? SceneEditor::kCameraSelection : kNoObject;
    const auto& rows = rowsOf(int(i.internalId()));
    return i.row() < int(rows.size()) ? rows[std::size_t(i.row())].id : kNoObject;
}

QModelIndex OutlinerModel::indexOf(ObjectId id) const {
    if (id == SceneEditor::kCameraSelection) return index(kCameraRow, 0);
    for (int g : {kLightsRow, kObjectsRow}) {
        // Rows follow the document's order, which is by id.
        const std::ptrdiff_t r = indexById(rowsOf(g), id, [](const Row& row) { return row.id; });
        if (r >= 0) return index(int(r), 0, index(g, 0));
    }
    return {};
}

QVariant OutlinerModel::data(const QModelIndex& i, int role) const {
    if (!i.isValid()) return {};
    const SceneDocument& doc = editor_->document();
    if (i.internalId() == kTopLevel) {
        if (role != Qt::DisplayRole) return {};
        static const char* const names[] = {"Camera", "Lights", "Objects"};
        return tr(names[i.row()]);
    }
    const ObjectId id = idOf(i);
    if (const Light* l = doc.findLight(id)) {
        if (role == Qt::DisplayRole || role == Qt::EditRole) return QString::fromStdString(l->name);
        if (role == Qt::ToolTipRole) {
            switch (l->type) {
                case LightType::Point:
                    return tr("Point light");
                case LightType::Sphere:
                    return tr("Sphere light");
                case LightType::Directional:
                    return tr("Sun light");
                case LightType::Spot:
                    return tr("Spot light");
            }
        }
    } else if (const Object* o = doc.findObject(id)) {
        if (role == Qt::DisplayRole || role == Qt::EditRole) return QString::fromStdString(o->name);
        if (role == Qt::CheckStateRole) return o->visible ? Qt::Checked : Qt::Unchecked;
        if (role == Qt::ToolTipRole) return QString::fromLatin1(geometryTypeName(o->geometry));
    }
    return {};
}

bool OutlinerModel::setData(const QModelIndex& i, const QVariant& value, int role) {
    const ObjectId id = idOf(i);
    if (id == kNoObject || id == SceneEditor::kCameraSelection) return false;
    SceneDocument doc = editor_->document();
    if (role == Qt::EditRole) {
        if (!rename(doc, id, value.toString().trimmed().toStdString())) return false;
        editor_->edit(tr("Rename"), std::move(doc));
        return true;
    }
    if (role == Qt::CheckStateRole) {
        Object* o = doc.findObject(id);
        if (!o) return false;
        o->visible = value.toInt() == Qt::Checked;
        editor_->edit(o->visible ? tr("Show object") : tr("Hide object"), std::move(doc));
        return true;
    }
    return false;
}

Qt::ItemFlags OutlinerModel::flags(const QModelIndex& i) const {
    if (!i.isValid()) return {};
    if (i.internalId() == kTopLevel)
        return i.row() == kCameraRow ? Qt::ItemIsEnabled | Qt::ItemIsSelectable : Qt::ItemIsEnabled;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable;
    if (i.internalId() == kObjectsRow) f |= Qt::ItemIsUserCheckable;
    return f;
}

}  // namespace rs::ui
