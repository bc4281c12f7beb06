// OutlinerModel: ids are cached per row so edits that keep the structure only Q_EMIT dataChanged.
#include "outliner_model.h"

#include "scene_editor.h"
#include "scene_edits.h"

namespace rs::ui {

namespace {
// internalId of top-level rows; children carry the row's group + 1 so parent() can find it.
enum Group : quintptr { kCameraRow = 0, kLightsRow = 1, kObjectsRow = 2, kTopLevel = 100 };

std::vector<ObjectId> idsOf(const auto& list) {
    std::vector<ObjectId> ids;
    for (const auto& e : list) ids.push_back(e.id);
    return ids;
}
}  // namespace

OutlinerModel::OutlinerModel(SceneEditor* editor, QObject* parent)
    : QAbstractItemModel(parent), editor_(editor) {
    lightIds_ = idsOf(editor_->document().lights);
    objectIds_ = idsOf(editor_->document().objects);
    connect(editor_, &SceneEditor::documentChanged, this, &OutlinerModel::onDocumentChanged);
}

void OutlinerModel::onDocumentChanged() {
    auto lights = idsOf(editor_->document().lights);
    auto objects = idsOf(editor_->document().objects);
    if (lights != lightIds_ || objects != objectIds_) {
        beginResetModel();
        lightIds_ = std::move(lights);
        objectIds_ = std::move(objects);
        endResetModel();
        return;
    }
    for (int g : {kLightsRow, kObjectsRow}) {
        const QModelIndex p = index(g, 0);
        const int n = rowCount(p);
        if (n > 0) Q_EMIT dataChanged(index(0, 0, p), index(n - 1, 0, p));
    }
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
    if (parent.row() == kLightsRow) return int(lightIds_.size());
    if (parent.row() == kObjectsRow) return int(objectIds_.size());
    return 0;
}

int OutlinerModel::columnCount(const QModelIndex&) const {
    return 1;
}

ObjectId OutlinerModel::idOf(const QModelIndex& i) const {
    if (!i.isValid()) return kNoObject;
    if (i.internalId() == kTopLevel)
        return i.row() == kCameraRow ? SceneEditor::kCameraSelection : kNoObject;
    const auto& ids = i.internalId() == kLightsRow ? lightIds_ : objectIds_;
    return i.row() < int(ids.size()) ? ids[std::size_t(i.row())] : kNoObject;
}

QModelIndex OutlinerModel::indexOf(ObjectId id) const {
    if (id == SceneEditor::kCameraSelection) return index(kCameraRow, 0);
    for (int g : {kLightsRow, kObjectsRow}) {
        const auto& ids = g == kLightsRow ? lightIds_ : objectIds_;
        for (std::size_t r = 0; r < ids.size(); ++r)
            if (ids[r] == id) return index(int(r), 0, index(g, 0));
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
        if (role == Qt::ToolTipRole)
            return l->type == LightType::Sphere ? tr("Sphere light") : tr("Point light");
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
