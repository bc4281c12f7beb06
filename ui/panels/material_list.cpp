// MaterialList: list widget, buttons and the edits of scene_edits.h they push.
#include "panels/material_list.h"

#include <QAbstractItemDelegate>
#include <QGridLayout>
#include <QIcon>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <set>
#include <unordered_map>
#include <utility>

#include "document/scene_editor.h"
#include "document/scene_edits.h"
#include "panels/material_preview.h"

namespace rs::ui {

namespace {
/// The material name an item stands for (its text is edited in place, so kept apart).
constexpr int kNameRole = Qt::UserRole;

QIcon iconOf(const QImage& image, int side) {
    QPixmap pixmap = QPixmap::fromImage(image);
    pixmap.setDevicePixelRatio(double(image.width()) / double(side));
    return QIcon(pixmap);
}
}  // namespace

std::vector<ObjectId> materialTargets(const SceneEditor& editor) {
    // Every selected object (lights have no material).
    std::vector<ObjectId> ids;
    for (ObjectId id : editor.selectedIds())
        if (editor.document().findObject(id)) ids.push_back(id);
    return ids;
}

MaterialList::MaterialList(SceneEditor* editor, QWidget* parent)
    : QWidget(parent), editor_(editor), previews_(new MaterialPreviews(this)) {
    auto* layout = new QVBoxLayout(this);
    list_ = new QListWidget(this);
    list_->setObjectName(QStringLiteral("materialList"));
    list_->setIconSize(QSize(kIconSide, kIconSide));
    list_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    layout->addWidget(list_, 1);
    auto* buttons = new QGridLayout;
    auto button = [this](const QString& text, const char* name, const QString& tip) {
        auto* b = new QPushButton(text, this);
        b->setObjectName(QString::fromLatin1(name));
        b->setToolTip(tip);
        return b;
    };
    new_ = button(tr("New"), "newMaterial", tr("Add a default material"));
    duplicate_ = button(tr("Duplicate"), "duplicateMaterial", tr("Add a copy of this material"));
    rename_ = button(tr("Rename"), "renameMaterial", tr("Rename this material (F2)"));
    delete_ = button(tr("Delete"), "deleteMaterial", tr("Delete this material"));
    assign_ = button(tr("Assign to Selection"), "assignMaterial",
                     tr("Give the selected object this material"));
    buttons->addWidget(new_, 0, 0);
    buttons->addWidget(duplicate_, 0, 1);
    buttons->addWidget(rename_, 1, 0);
    buttons->addWidget(delete_, 1, 1);
    buttons->addWidget(assign_, 2, 0, 1, 2);
    layout->addLayout(buttons);
    message_ = new QLabel(this);
    message_->setObjectName(QStringLiteral("materialMessage"));
    message_->setWordWrap(true);
    layout->addWidget(message_);

    connect(new_, &QPushButton::clicked, this, &MaterialList::newMaterial);
    connect(duplicate_, &QPushButton::clicked, this, &MaterialList::duplicateMaterial);
    connect(rename_, &QPushButton::clicked, this, &MaterialList::renameMaterial);
    connect(delete_, &QPushButton::clicked, this, &MaterialList::deleteMaterial);
    connect(assign_, &QPushButton::clicked, this, &MaterialList::assignToSelection);
    connect(list_, &QListWidget::itemChanged, this, &MaterialList::onItemChanged);
    connect(list_, &QListWidget::currentItemChanged, this, [this] {
        refused_.clear();
        updateButtons();
    });
    connect(editor_, &SceneEditor::documentChanged, this, &MaterialList::onDocumentChanged);
    // A preview's key has its texture's stamp: an image saved again is a new picture.
    connect(editor_, &SceneEditor::imagesReloaded, this, [this] { refreshPreviews(true); });
    connect(previews_, &MaterialPreviews::previewReady, this, &MaterialList::onPreviewReady);
    // Queued: the view leaves its editing state after the delegate has signalled.
    connect(
        list_->itemDelegate(), &QAbstractItemDelegate::closeEditor, this,
        [this] {
            if (!std::exchange(iconsDeferred_, false)) return;
            refreshPreviews(true);  // The deferred pictures are cached: nothing is rendered.
        },
        Qt::QueuedConnection);
    // The list follows the active object's material, as Blender's material slots do: pick an
    // object, then (to give it another) a material, then Assign to Selection.
    connect(editor_, &SceneEditor::selectionChanged, this, [this] {
        followActiveMaterial();
        updateButtons();
    });
    rebuild();
}

std::string MaterialList::current() const {
    const QListWidgetItem* item = list_->currentItem();
    return item ? item->data(kNameRole).toString().toStdString() : std::string();
}

bool MaterialList::setCurrent(const std::string& name) {
    for (int i = 0; i < list_->count(); ++i)
        if (list_->item(i)->data(kNameRole).toString().toStdString() == name) {
            list_->setCurrentRow(i);
            return true;
        }
    return false;
}

QString MaterialList::message() const {
    return message_->text();
}

void MaterialList::showMessage(const QString& text) {
    message_->setText(text);
    message_->setVisible(!text.isEmpty());
}

void MaterialList::followActiveMaterial() {
    const ObjectId id = editor_->selection();
    const Object* o = editor_->document().findObject(id);
    const std::string material = o ? o->material : std::string();
    if (id == followedObject_ && material == followedMaterial_) return;
    followedObject_ = id;
    followedMaterial_ = material;
    if (!material.empty()) setCurrent(material);
}

void MaterialList::onDocumentChanged() {
    const DocumentChange& change = editor_->lastChange();
    const uint8_t users = DocumentChange::kMaterial | DocumentChange::kName;
    if (change.materials || change.environment || change.objectsRestructured ||
        (change.objectFields() & users)) {
        rebuild();
        followActiveMaterial();  // "New material", Make Unique, another one picked for it
        return;
    }
    if (!refused_.isEmpty()) {  // Any change ends a refused rename's message.
        refused_.clear();
        updateButtons();
    }
}

void MaterialList::rebuild() {
    refused_.clear();
    deleteErrorValid_ = false;
    // A drag edits the document many times a second without touching the list: keep it.
    const SceneDocument& doc = editor_->document();
    std::unordered_map<std::string, int> users;  // One pass: a scene may have many of both.
    for (const Object& o : doc.objects) ++users[o.material];
    QStringList shown;
    for (const Material& m : doc.materials)
        shown << QString::fromStdString(m.name) + QLatin1Char('/') + QString::number(users[m.name]);
    if (shown == shown_) {
        refreshPreviews(false);  // A drag leaves the materials alone: nothing is asked for.
        updateButtons();
        return;
    }
    shown_ = shown;
    const std::string keep = current();
    {
        const QSignalBlocker block(list_);
        list_->clear();
        for (const Material& m : doc.materials) {
            const QString name = QString::fromStdString(m.name);
            auto* item = new QListWidgetItem(name, list_);
            item->setData(kNameRole, name);
            item->setFlags(item->flags() | Qt::ItemIsEditable);
            const int n = users[m.name];
            item->setToolTip(n ? tr("Used by %n object(s)", nullptr, n) : tr("Unused"));
        }
    }
    if (!setCurrent(keep) && list_->count() > 0) list_->setCurrentRow(0);
    refreshPreviews(true);
    updateButtons();
}

void MaterialList::refreshPreviews(bool force) {
    const SceneDocument& doc = editor_->document();
    const int side = qRound(kIconSide * list_->devicePixelRatioF());
    if (!force && side == previewedSide_ && doc.environment == previewedEnvironment_ &&
        doc.materials == previewed_)
        return;
    previewed_ = doc.materials;
    previewedEnvironment_ = doc.environment;
    previewedSide_ = side;
    std::set<std::string> names;
    for (const Material& m : doc.materials) names.insert(m.name);
    previews_->retain(names);
    // The items are the document's materials in order (rebuild).
    if (std::size_t(list_->count()) != doc.materials.size()) return;
    if (force || iconKeys_.size() != doc.materials.size())
        iconKeys_.assign(doc.materials.size(), QString());
    for (int i = 0; i < list_->count(); ++i) {
        QListWidgetItem* item = list_->item(i);
        const Material& m = doc.materials[std::size_t(i)];
        const QString key = QString::fromStdString(materialPreviewKey(m, doc.environment, side));
        if (iconKeys_[std::size_t(i)] == key) continue;
        iconKeys_[std::size_t(i)] = key;
        const QImage preview = previews_->request(m, doc.environment, side);
        setPreviewIcon(item, preview.isNull() ? materialSwatch(m, side) : preview);
    }
}

void MaterialList::onPreviewReady(const QString& name, const QString& key, const QImage& image) {
    for (int i = 0; i < list_->count(); ++i) {
        QListWidgetItem* item = list_->item(i);
        if (iconKeys_.size() > std::size_t(i) && iconKeys_[std::size_t(i)] == key &&
            item->data(kNameRole).toString() == name)
            setPreviewIcon(item, image);
    }
}

void MaterialList::setPreviewIcon(QListWidgetItem* item, const QImage& image) {
    // itemWidget() is indexWidget(): an open editor too.
    if (list_->itemWidget(item)) {
        iconsDeferred_ = true;
        return;
    }
    item->setIcon(iconOf(image, kIconSide));
}

void MaterialList::updateButtons() {
    const SceneDocument& doc = editor_->document();
    const std::string name = current();
    const bool has = !name.empty() && doc.findMaterial(name);
    duplicate_->setEnabled(has);
    rename_->setEnabled(has);
    if (!deleteErrorValid_ || deleteError_.first != name) {
        deleteError_ = {name, has ? materialDeleteError(doc, name) : std::string()};
        deleteErrorValid_ = true;
    }
    const std::string& deleteError = deleteError_.second;
    delete_->setEnabled(has && deleteError.empty());
    delete_->setToolTip(deleteError.empty() ? tr("Delete this material")
                                            : QString::fromStdString(deleteError));
    const std::vector<ObjectId> targets = materialTargets(*editor_);
    assign_->setEnabled(has && !targets.empty());
    QString reason = refused_;
    if (reason.isEmpty() && !deleteError.empty())
        reason = tr("Cannot delete: %1").arg(QString::fromStdString(deleteError));
    showMessage(reason);
}

void MaterialList::newMaterial() {
    SceneDocument doc = editor_->document();
    const std::string name = addMaterial(doc);
    editor_->edit(tr("Add material \"%1\"").arg(QString::fromStdString(name)), std::move(doc));
    setCurrent(name);
}

void MaterialList::duplicateMaterial() {
    SceneDocument doc = editor_->document();
    const std::string name = rs::ui::duplicateMaterial(doc, current());
    if (name.empty()) return;
    editor_->edit(tr("Duplicate material \"%1\"").arg(QString::fromStdString(current())),
                  std::move(doc));
    setCurrent(name);
}

void MaterialList::renameMaterial() {
    if (QListWidgetItem* item = list_->currentItem()) list_->editItem(item);
}

void MaterialList::onItemChanged(QListWidgetItem* item) {
    const std::string from = item->data(kNameRole).toString().toStdString();
    const std::string to = item->text().toStdString();
    if (from == to) return;
    // After the in-place editor has finished with the item: the edit rebuilds the list.
    QMetaObject::invokeMethod(
        this, [this, from, to] { applyRename(from, to); }, Qt::QueuedConnection);
}

void MaterialList::applyRename(const std::string& from, const std::string& to) {
    SceneDocument doc = editor_->document();
    const std::string error = rs::ui::renameMaterial(doc, from, to);
    if (!error.empty()) {
        shown_.clear();
        rebuild();  // Back to the names the document has.
        setCurrent(from);
        refused_ = tr("Cannot rename \"%1\": %2")
                       .arg(QString::fromStdString(from), QString::fromStdString(error));
        updateButtons();
        return;
    }
    const QString text = tr("Rename material %1 to %2")
                             .arg(QString::fromStdString(from), QString::fromStdString(to));
    editor_->edit(text, std::move(doc));
    setCurrent(to);
}

void MaterialList::deleteMaterial() {
    SceneDocument doc = editor_->document();
    const std::string name = current();
    const std::string error = rs::ui::deleteMaterial(doc, name);
    if (!error.empty()) {
        refused_ = tr("Cannot delete: %1").arg(QString::fromStdString(error));
        updateButtons();
        return;
    }
    editor_->edit(tr("Delete material \"%1\"").arg(QString::fromStdString(name)), std::move(doc));
}

void MaterialList::assignToSelection() {
    SceneDocument doc = editor_->document();
    const std::string name = current();
    if (name.empty() || assignMaterial(doc, materialTargets(*editor_), name) == 0) return;
    editor_->edit(tr("Assign material \"%1\"").arg(QString::fromStdString(name)), std::move(doc));
}

}  // namespace rs::ui
