// The material list dock: the document's materials with New, Duplicate, Rename, Delete and
// Assign to the selection, each one undo step; names checked as the scene format requires.
#pragma once

#include <QStringList>
#include <QWidget>
#include <string>
#include <vector>

#include "scene/document.h"

class QLabel;
class QListWidget;
class QListWidgetItem;
class QPushButton;

namespace rs::ui {

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

private:
    void rebuild();
    void updateButtons();
    void onItemChanged(QListWidgetItem* item);
    void applyRename(const std::string& from, const std::string& to);
    void showMessage(const QString& text);

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
};

}  // namespace rs::ui
