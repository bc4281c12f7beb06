// PropertyPanel: generic sections over descriptors plus the material chooser.
#include "panels/property_panel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <algorithm>

#include "document/color_pattern_edits.h"
#include "document/scene_editor.h"
#include "document/scene_edits.h"
#include "io/mesh_io.h"
#include "panels/color_pattern_editor.h"
#include "panels/image_preview.h"
#include "panels/parameter_widgets.h"

namespace rs::ui {

namespace {
const QString kDefaultMaterial = QStringLiteral("(default grey)");

/// The material of `d` named `name` (const or not, as `d`), or null.
template <class Doc>
auto materialNamed(Doc& d, const std::string& name) -> decltype(&d.materials[0]) {
    for (auto& m : d.materials)
        if (m.name == name) return &m;
    return nullptr;
}

/// Changing smooth_normals changes the loaded triangles' normals: reload the mesh.
void reloadMeshIfNeeded(Geometry& g, const std::string& key) {
    auto* mesh = std::get_if<MeshGeometry>(&g);
    if (!mesh || key != "smooth_normals" || mesh->resolvedPath.empty()) return;
    MeshLoadResult r = loadMesh(mesh->resolvedPath, mesh->smoothNormals);
    if (r.ok()) mesh->data = r.mesh;
}

}  // namespace

PropertyPanel::PropertyPanel(SceneEditor* editor, QWidget* parent)
    : QScrollArea(parent), editor_(editor) {
    setWidgetResizable(true);
    setMinimumWidth(kMinimumWidth);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    connect(editor_, &SceneEditor::documentChanged, this, &PropertyPanel::onDocumentChanged);
    // The texture's thumbnail is read again when its file changed.
    connect(editor_, &SceneEditor::imagesReloaded, this, [this] { refresh(); });
    connect(editor_, &SceneEditor::selectionChanged, this, &PropertyPanel::rebuild);
    rebuild();
}

QString PropertyPanel::signature() const {
    const SceneDocument& doc = editor_->document();
    const ObjectId id = editor_->selection();
    QString s = QString::number(id) + QLatin1Char('/') + QString::number(doc.materials.size());
    if (const Object* o = doc.findObject(id)) {
        s += QStringLiteral("/o%1/%2")
                 .arg(o->geometry.index())
                 .arg(QString::fromStdString(o->material));
        // A mesh's parts each show their material.
        if (const auto* mesh = std::get_if<MeshGeometry>(&o->geometry))
            for (const std::string& part : mesh->partMaterials)
                s += QStringLiteral("/m") + QString::fromStdString(part);
        // Its material's colour form decides which sections are shown.
        if (const Material* m = doc.findMaterial(shownMaterial(*o)))
            s += QStringLiteral("/p%1").arg(m->pattern.index());
    }
    if (const Light* l = doc.findLight(id)) s += QStringLiteral("/l%1").arg(int(l->type));
    for (const Material& m : doc.materials) s += QLatin1Char('|') + QString::fromStdString(m.name);
    return s;
}

void PropertyPanel::onDocumentChanged() {
    if (signature() != signature_)
        rebuild();
    else
        refresh(&editor_->lastChange());
}

bool PropertyPanel::changed(Part part, const DocumentChange& change) const {
    switch (part) {
        case Part::Object: {
            if (change.objectsRestructured) return true;
            const ObjectId id = editor_->selection();
            return std::any_of(change.objects.begin(), change.objects.end(),
                               [id](const DocumentChange::ObjectEdit& e) { return e.id == id; });
        }
        case Part::Material:
            return change.materials;
        case Part::Light:
            return change.lights;
        case Part::Camera:
            return change.camera;
        case Part::Render:
            return change.render;
    }
    return true;
}

void PropertyPanel::refresh(const DocumentChange* change) {
    fieldsRefreshed_ = 0;
    for (const Refresher& r : refreshers_) {
        if (change && !changed(r.part, *change)) continue;
        r.set();
        ++fieldsRefreshed_;
    }
}

void PropertyPanel::showError(const QString& text) {
    lastError_ = text;
    errorLabel_->setText(text);
    errorLabel_->setVisible(!text.isEmpty());
}

bool PropertyPanel::applyEdit(const QString& section, const std::string& key,
                              const ParamValue& value) {
    for (const auto& [name, apply] : appliers_)
        if (name == section) return apply(key, value);
    return false;
}

template <class Locate>
QFormLayout* PropertyPanel::addSection(const QString& title, const QString& section, Part part,
                                       ParamKind kind, Locate locate) {
    auto* box = new QGroupBox(title, content_);
    auto* form = new QFormLayout(box);
    const QString mergePrefix = QString::number(editor_->selection()) + QLatin1Char(':') + title;
    auto apply = [this, locate, mergePrefix, kind](const std::string& key, const ParamValue& v) {
        SceneDocument doc = editor_->document();
        auto* target = locate(doc);
        if (!target) return false;
        const std::string error = setParameter(*target, key, v);
        if (!error.empty()) {
            showError(QString::fromStdString(error));
            refresh();  // Put the widget back to the document's value.
            return false;
        }
        if constexpr (std::is_same_v<std::remove_cvref_t<decltype(*target)>, Geometry>)
            reloadMeshIfNeeded(*target, key);
        showError({});
        const ParamDescriptor* d = findParameter(kind, key);
        editor_->edit(tr("Change %1").arg(QString::fromStdString(d ? d->label : key)),
                      std::move(doc), MergeKind::Property,
                      mergePrefix + QLatin1Char(':') + QString::fromStdString(key));
        return true;
    };
    appliers_.emplace_back(section, apply);
    // A dialog's live preview: the document shows the value tried, with no undo step; the
    // end puts it back, and its OK then comes as one edit through `apply`.
    auto preview = [this, locate](const std::string& key, const std::optional<ParamValue>& v) {
        if (!v) {
            editor_->endPreview();
            editor_->closeMerge();  // OK is a step of its own, not merged into earlier edits.
            return;
        }
        SceneDocument doc = editor_->document();
        auto* target = locate(doc);
        if (target && setParameter(*target, key, *v).empty()) editor_->preview(std::move(doc));
    };
    for (const ParamDescriptor& d : parameters(kind)) {
        const std::string key = d.key;
        ParamEditor pe = makeParamEditor(
            d, box, [apply, key](const ParamValue& v) { apply(key, v); },
            [preview, key](const std::optional<ParamValue>& v) { preview(key, v); });
        form->addRow(QString::fromStdString(d.label), pe.widget);
        refreshers_.push_back({part, [this, locate, key, set = pe.setValue] {
                                   const auto* target = locate(editor_->document());
                                   if (!target) return;
                                   if (auto v = getParameter(*target, key)) set(*v);
                               }});
    }
    layout_->addWidget(box);
    return form;
}

void PropertyPanel::addPartMaterials(ObjectId id) {
    const SceneDocument& doc = editor_->document();
    const Object* o = doc.findObject(id);
    const auto* mesh = o ? std::get_if<MeshGeometry>(&o->geometry) : nullptr;
    // One part shows its row too when it has its own material, else the panel would name the
    // object's material, which none of its triangles use.
    if (!mesh || mesh->partMaterials.empty() || !mesh->data || mesh->data->parts.empty() ||
        (mesh->data->parts.size() < 2 && !everyPartHasItsOwn(*o)))
        return;
    auto* box = new QGroupBox(tr("Parts"), content_);
    box->setObjectName(QStringLiteral("parts"));
    auto* form = new QFormLayout(box);
    for (std::size_t i = 0; i < mesh->data->parts.size(); ++i) {
        const MeshPart part = mesh->data->parts[i];
        auto* combo = new QComboBox(box);
        combo->addItem(tr("(the object's)"));
        for (const Material& m : doc.materials) combo->addItem(QString::fromStdString(m.name));
        const std::string& current =
            part.material < mesh->partMaterials.size() ? mesh->partMaterials[part.material] : "";
        combo->setCurrentIndex(
            current.empty() ? 0 : std::max(0, combo->findText(QString::fromStdString(current))));
        combo->setToolTip(tr("%1 triangles of the file's material %2")
                              .arg(part.triangleCount)
                              .arg(part.material));
        connect(combo, &QComboBox::activated, this, [this, id, part, combo](int index) {
            SceneDocument doc = editor_->document();
            Object* obj = doc.findObject(id);
            auto* g = obj ? std::get_if<MeshGeometry>(&obj->geometry) : nullptr;
            if (!g) return;
            if (g->partMaterials.size() <= part.material)
                g->partMaterials.resize(std::size_t(part.material) + 1);
            g->partMaterials[part.material] =
                index == 0 ? std::string() : combo->itemText(index).toStdString();
            editor_->edit(tr("Assign part material"), std::move(doc));
        });
        form->addRow(tr("Part %1").arg(i + 1), combo);
    }
    layout_->addWidget(box);
}

void PropertyPanel::addMaterialChooser(ObjectId id) {
    const SceneDocument& doc = editor_->document();
    const Object* o = doc.findObject(id);
    auto* box = new QGroupBox(tr("Material"), content_);
    auto* form = new QFormLayout(box);
    auto* combo = new QComboBox(box);
    combo->addItem(kDefaultMaterial);
    for (const Material& m : doc.materials) combo->addItem(QString::fromStdString(m.name));
    combo->setCurrentIndex(
        o->material.empty() ? 0 : combo->findText(QString::fromStdString(o->material)));
    connect(combo, &QComboBox::activated, this, [this, id, combo](int index) {
        SceneDocument doc = editor_->document();
        Object* obj = doc.findObject(id);
        if (!obj) return;
        obj->material = index == 0 ? std::string() : combo->itemText(index).toStdString();
        editor_->edit(tr("Assign material"), std::move(doc));
    });
    form->addRow(tr("Material"), combo);
    const int users = o->material.empty() ? 0 : materialUsers(doc, o->material);
    const bool unused = everyPartHasItsOwn(*o);
    auto* usage = new QLabel(
        unused      ? tr("Every part has its own material (Parts); this one shows on none of them")
        : users > 1 ? tr("Shared: used by %1 objects; edits change all of them").arg(users)
        : o->material.empty() ? tr("Built-in, not editable")
                              : tr("Used by this object only"),
        box);
    usage->setObjectName(QStringLiteral("materialUsage"));
    usage->setWordWrap(true);
    form->addRow(usage);
    if (users != 1) {
        auto* unique =
            new QPushButton(o->material.empty() ? tr("New material") : tr("Make unique"), box);
        unique->setObjectName(QStringLiteral("makeUnique"));
        connect(unique, &QPushButton::clicked, this, [this, id] {
            SceneDocument doc = editor_->document();
            makeMaterialUnique(doc, id);
            editor_->edit(tr("Make material unique"), std::move(doc));
        });
        form->addRow(unique);
    }
    layout_->addWidget(box);
    const std::string name = shownMaterial(*o);
    if (name.empty() || !doc.findMaterial(name)) return;
    QFormLayout* materialForm = addSection(
        tr("Material \"%1\"").arg(QString::fromStdString(name)), QStringLiteral("material"),
        Part::Material, ParamKind::Material, [name](auto& d) { return materialNamed(d, name); });
    addColorForm(name, materialForm);
}

void PropertyPanel::addColorForm(const std::string& name, QFormLayout* form) {
    const Material* material = editor_->document().findMaterial(name);
    const ColorMode mode = colorModeOf(*material);
    QComboBox* combo = makeColorModeCombo(form->parentWidget());
    form->insertRow(0, tr("Colour mode"), combo);
    // The flat colour stays in the document under a pattern (Colour mode shows it again).
    const auto& fields = parameters(ParamKind::Material);
    for (std::size_t i = 0; i < fields.size(); ++i)
        if (fields[i].key == "color") form->setRowVisible(int(i) + 1, mode == ColorMode::Colour);
    const QString qname = QString::fromStdString(name);
    connect(combo, &QComboBox::activated, this, [this, name, qname, combo](int index) {
        SceneDocument doc = editor_->document();
        Material* m = findMaterial(doc, name);
        if (!m) return;
        std::string path;
        if (ColorMode(index) == ColorMode::Image && colorModeOf(*m) != ColorMode::Image) {
            path = chooseTextureFile(this, editor_->filePath()).toStdString();
            if (path.empty()) {
                refresh();  // Cancelled: the selector shows the document's mode again.
                return;
            }
        }
        if (!setColorMode(*m, ColorMode(index), path)) return;
        editor_->edit(tr("Colour of \"%1\": %2").arg(qname, combo->itemText(index)),
                      std::move(doc));
    });
    refreshers_.push_back({Part::Material, [this, name, combo] {
                               if (const Material* m = editor_->document().findMaterial(name)) {
                                   const QSignalBlocker block(combo);
                                   combo->setCurrentIndex(int(colorModeOf(*m)));
                               }
                           }});

    if (mode == ColorMode::Checker) {
        addSection(tr("Checker"), QStringLiteral("checker"), Part::Material, ParamKind::Checker,
                   [name](auto& d) {
                       auto* m = materialNamed(d, name);
                       return m ? std::get_if<CheckerPattern>(&m->pattern) : nullptr;
                   });
    } else if (mode == ColorMode::Image) {
        QFormLayout* image =
            addSection(tr("Image texture"), QStringLiteral("texture"), Part::Material,
                       ParamKind::ImageTexture, [name](auto& d) {
                           auto* m = materialNamed(d, name);
                           return m ? std::get_if<ImageTexture>(&m->pattern) : nullptr;
                       });
        // Under the file's row: Choose... and the thumbnail (or why the file cannot be read).
        int row = 0;
        for (const ParamDescriptor& d : parameters(ParamKind::ImageTexture)) {
            ++row;
            if (d.type == ParamType::File) break;
        }
        auto* choose = new QPushButton(tr("Choose…"), image->parentWidget());
        choose->setObjectName(QStringLiteral("chooseTexture"));
        choose->setToolTip(tr("Choose the image file"));
        auto* preview = makeTexturePreview(image->parentWidget());
        preview->setObjectName(QStringLiteral("texturePreview"));
        image->insertRow(row, QString(), choose);
        image->insertRow(row + 1, QString(), preview);
        connect(choose, &QPushButton::clicked, this, [this, name] {
            const QString path = chooseTextureFile(this, editor_->filePath());
            if (path.isEmpty()) return;
            SceneDocument doc = editor_->document();
            Material* m = findMaterial(doc, name);
            if (!m || !setColorMode(*m, ColorMode::Image, path.toStdString())) return;
            editor_->edit(tr("Change texture image"), std::move(doc));
        });
        refreshers_.push_back({Part::Material, [this, name, preview] {
                                   const Material* m = editor_->document().findMaterial(name);
                                   if (const auto* t =
                                           m ? std::get_if<ImageTexture>(&m->pattern) : nullptr)
                                       preview->setImage(t->image.source());
                               }});
    }
}

void PropertyPanel::rebuild() {
    // Rebuilt for the same selection (its material's colour mode switched, a part given a
    // material, an undo): the fields stay where the user scrolled to. Another selection
    // starts at the top.
    const ObjectId selection = editor_->selection();
    const int scrolled = selection == builtFor_ ? verticalScrollBar()->value() : 0;
    builtFor_ = selection;
    refreshers_.clear();
    appliers_.clear();
    if (QWidget* old = takeWidget()) {
        old->hide();
        old->deleteLater();  // A widget of it may be running the handler that got us here.
    }
    content_ = new QWidget;
    layout_ = new QVBoxLayout(content_);
    errorLabel_ = new QLabel(content_);
    errorLabel_->setStyleSheet(QStringLiteral("color: #d03030;"));
    errorLabel_->setWordWrap(true);
    errorLabel_->setVisible(!lastError_.isEmpty());
    errorLabel_->setText(lastError_);
    layout_->addWidget(errorLabel_);

    const SceneDocument& doc = editor_->document();
    const ObjectId id = editor_->selection();
    if (const auto& ids = editor_->selectedIds(); ids.size() > 1) {
        // Several selected: the panel edits the active one (the last picked) and says so;
        // the viewport's gizmo and G/R/S, Delete and Duplicate act on them all.
        const auto nameOf = [&](ObjectId e) {
            if (const Object* o = doc.findObject(e)) return QString::fromStdString(o->name);
            if (const Light* l = doc.findLight(e)) return QString::fromStdString(l->name);
            return QString();
        };
        auto* summary = new QLabel(
            tr("<b>%1 selected.</b> Below: %2, the active one (the last picked); edits here "
               "change it alone. Move, rotate, scale, delete and duplicate act on all %1.")
                .arg(ids.size())
                .arg(nameOf(id).toHtmlEscaped()),
            content_);
        summary->setObjectName(QStringLiteral("selectionSummary"));
        summary->setWordWrap(true);
        layout_->addWidget(summary);
    }
    if (const Object* o = doc.findObject(id)) {
        addSection(QString::fromLatin1(kindLabel(geometryKind(o->geometry))),
                   QStringLiteral("geometry"), Part::Object, geometryKind(o->geometry),
                   [id](auto& d) {
                       auto* obj = d.findObject(id);
                       return obj ? &obj->geometry : decltype(&obj->geometry){};
                   });
        if (!std::holds_alternative<PlaneGeometry>(o->geometry))
            addSection(tr("Transform"), QStringLiteral("transform"), Part::Object,
                       ParamKind::Transform, [id](auto& d) {
                           auto* obj = d.findObject(id);
                           return obj ? &obj->transform : decltype(&obj->transform){};
                       });
        addMaterialChooser(id);
        addPartMaterials(id);
    } else if (const Light* l = doc.findLight(id)) {
        addSection(QString::fromLatin1(kindLabel(lightKind(*l))), QStringLiteral("light"),
                   Part::Light, lightKind(*l), [id](auto& d) { return d.findLight(id); });
    } else {
        if (id == SceneEditor::kCameraSelection)
            addSection(tr("Camera"), QStringLiteral("camera"), Part::Camera, ParamKind::Camera,
                       [](auto& d) { return &d.camera; });
        addSection(tr("Render settings"), QStringLiteral("render"), Part::Render, ParamKind::Render,
                   [](auto& d) { return &d.render; });
    }
    layout_->addStretch(1);
    setWidget(content_);
    // As wide as the fields need (a row of three coordinates), never cutting a value off.
    setMinimumWidth(std::max(kMinimumWidth, content_->minimumSizeHint().width() +
                                                verticalScrollBar()->sizeHint().width() +
                                                2 * frameWidth()));
    signature_ = signature();
    refresh();
    verticalScrollBar()->setValue(scrolled);  // setWidget measured the new content: in range
}

}  // namespace rs::ui
