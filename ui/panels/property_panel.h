// The property panel: sections generated from the parameter descriptors of the selection
// (geometry, transform, material, light, camera, render settings).
#pragma once

#include <QScrollArea>
#include <functional>
#include <vector>

#include "scene/document.h"
#include "scene/document_change.h"
#include "scene/parameters.h"

class QFormLayout;
class QLabel;
class QVBoxLayout;

namespace rs::ui {

class SceneEditor;

/// Rebuilds its sections when the selection (or its kind) changes and refreshes values on
/// every other document change, so a widget the user is dragging is never destroyed. A
/// refresh sets only the fields of the parts the edit changed (SceneEditor::lastChange): moving
/// one of 100,000 objects leaves the panel of another, or the render settings, alone.
class PropertyPanel : public QScrollArea {
    Q_OBJECT
public:
    /// The least width the panel takes; more when its fields need it.
    static constexpr int kMinimumWidth = 340;
    explicit PropertyPanel(SceneEditor* editor, QWidget* parent = nullptr);

    /// Applies a parameter edit as the widgets do (tests use it): `section` is one of
    /// "geometry", "transform", "material", "light", "camera", "render".
    bool applyEdit(const QString& section, const std::string& key, const ParamValue& value);
    /// The last validation error shown (empty when none).
    QString lastError() const { return lastError_; }
    /// How many fields the last refresh set from the document (tests).
    int fieldsRefreshed() const { return fieldsRefreshed_; }

private:
    void onDocumentChanged();
    void rebuild();
    /// What a field shows: the selected object, a material, a light, the camera, the render
    /// settings.
    enum class Part { Object, Material, Light, Camera, Render };
    /// Sets the fields of the parts `change` changed from the document; every field without one.
    void refresh(const DocumentChange* change = nullptr);
    bool changed(Part part, const DocumentChange& change) const;
    QString signature() const;
    template <class Locate>
    QFormLayout* addSection(const QString& title, const QString& section, Part part, ParamKind kind,
                            Locate locate);
    /// A mesh with part materials: a material chooser per part ("Parts").
    void addPartMaterials(ObjectId id);
    void addMaterialChooser(ObjectId id);
    /// The Colour / Checker / Image selector in material `name`'s `form` and, for a pattern,
    /// its section (checker colours and cell size, or the image with its thumbnail).
    void addColorForm(const std::string& name, QFormLayout* form);
    void showError(const QString& text);

    SceneEditor* editor_;
    QWidget* content_ = nullptr;
    QVBoxLayout* layout_ = nullptr;
    QLabel* errorLabel_ = nullptr;
    QString signature_;
    ObjectId builtFor_ = kNoObject;  ///< The selection the fields were last built for.
    QString lastError_;
    struct Refresher {
        Part part;
        std::function<void()> set;
    };
    std::vector<Refresher> refreshers_;
    int fieldsRefreshed_ = 0;
    std::vector<std::pair<QString, std::function<bool(const std::string&, const ParamValue&)>>>
        appliers_;
};

}  // namespace rs::ui
