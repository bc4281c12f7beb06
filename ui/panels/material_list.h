// The material list dock: the document's materials with New, Duplicate, Rename, Delete and
// Assign to the selection, each one undo step; names checked as the scene format requires.
// Each material shows a preview sphere traced in the background (material_preview.h).
#pragma once

#include <QStringList>
#include <QWidget>
#include <string>
#include <utility>
#include <vector>

#include "scene/document.h"

class QLabel;
class QListWidget;
class QListWidgetItem;
class QPushButton;

namespace rs::ui {

class MaterialPreviews;
class SceneEditor;

/// The objects "Assign" gives the material: the selection's objects (lights and the camera
/// have no material). The one place that reads the selection for the material list.
std::vector<ObjectId> materialTargets(const SceneEditor& editor);

/// Lists the materials by name (with their number of users); renaming is in place (F2,
/// double-click or Rename). Actions that cannot apply are disabled, with the reason shown.
class MaterialList : public QWidget {
    Q_OBJECT
public:
    explicit MaterialList(SceneEditor* editor, QWidget* parent = nullptr);

    QListWidget* list() const { return list_; }
    /// The material chosen in the list (empty for none).
    std::string current() const;
    /// Chooses material `name` in the list; false when there is none.
    bool setCurrent(const std::string& name);
    /// The reason shown for what cannot be done now, or the last refused edit's error.
    QString message() const;

    void newMaterial();
    void duplicateMaterial();
    /// Opens the in-place editor on the current material's name.
    void renameMaterial();
    void deleteMaterial();
    void assignToSelection();

    /// The previews' renderer (tests count its renders).
    MaterialPreviews* previews() const { return previews_; }
    /// Edge of a list icon in logical pixels.
    static constexpr int kIconSide = 48;

private:
    void rebuild();
    /// rebuild() for a document change: nothing when the change cannot touch the list (a
    /// drag), so moving one of 100,000 objects does not count every object's material.
    void onDocumentChanged();
    /// Gives each item its preview, or its swatch while the preview renders; asks only for
    /// materials whose content (or the environment) changed since, unless `force`.
    void refreshPreviews(bool force);
    void onPreviewReady(const QString& name, const QString& key, const QImage& image);
    /// Shows `image` as the item's icon, unless its name is being edited in place: a change of
    /// the item would put the name back into the editor, over what is being typed. That icon
    /// is set once the editor closes.
    void setPreviewIcon(QListWidgetItem* item, const QImage& image);
    void updateButtons();
    void onItemChanged(QListWidgetItem* item);
    void applyRename(const std::string& from, const std::string& to);
    void showMessage(const QString& text);
    /// Makes the active object's material the current item when it is not the one last
    /// followed (another object selected, or the active object given another material), and
    /// leaves a material the user picked in the list alone otherwise.
    void followActiveMaterial();

    SceneEditor* editor_;
    QListWidget* list_;
    QPushButton* new_;
    QPushButton* duplicate_;
    QPushButton* rename_;
    QPushButton* delete_;
    QPushButton* assign_;
    QLabel* message_;
    QString refused_;    ///< A refused rename's error, shown until the next change.
    QStringList shown_;  ///< "name/users" of each material listed.
    /// The active object and its material when the list last followed them.
    ObjectId followedObject_ = kNoObject;
    std::string followedMaterial_;
    /// updateButtons()'s delete refusal for the material named first, valid while the second
    /// is true (rebuild() clears it: users may have changed).
    std::pair<std::string, std::string> deleteError_;
    bool deleteErrorValid_ = false;
    MaterialPreviews* previews_;
    std::vector<Material> previewed_;  ///< The materials as the icons were last asked for.
    Environment previewedEnvironment_;
    int previewedSide_ = 0;
    /// Per row, the preview key (materialPreviewKey) its icon shows or waits for. Kept out of
    /// the items: any change of an item puts its name back into an open in-place editor.
    std::vector<QString> iconKeys_;
    bool iconsDeferred_ = false;  ///< An icon waits for the in-place editor to close.
};

}  // namespace rs::ui
