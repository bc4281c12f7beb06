// The designer's view bookmarks (View -> Bookmarks): named cameras, saved with the scene
// (scenes/FORMAT.md, "views"), that the view can go back to.
#pragma once

#include <QObject>
#include <QString>
#include <string>

#include "scene/document.h"

class QMenu;
class QWidget;

namespace rs::ui {

class SceneEditor;
class Viewport;

/// Why `name` cannot name a view of `doc` (empty, or another view has it; `renaming` is the
/// view being renamed, which may keep its name); empty when it can.
QString viewNameError(const SceneDocument& doc, const QString& name,
                      const std::string& renaming = {});
/// "View 1", "View 2", ...: the first such name no view of `doc` has.
QString freeViewName(const SceneDocument& doc);

/// The Bookmarks menu and its edits. Going to a bookmark moves the view as navigation does
/// (the scene camera stays; View -> Scene Camera from View takes it); adding, renaming and
/// removing one are undoable edits of the document.
class ViewBookmarks : public QObject {
    Q_OBJECT

public:
    ViewBookmarks(SceneEditor* editor, Viewport* viewport, QWidget* dialogParent);

    /// The menu, filled from the document each time it opens.
    QMenu* menu() const { return menu_; }
    /// Bookmark This View: asks a name (offering a free one) and adds the view as it is now.
    void bookmarkView();
    /// Looks through view `name`; false when there is none.
    bool goTo(const std::string& name);
    /// Asks a new name for view `name` and renames it.
    void rename(const std::string& name);
    /// Removes view `name`.
    void remove(const std::string& name);

private:
    void fillMenu();
    /// Asks for a name until it is free or the user cancels; nullopt then.
    std::optional<QString> askName(const QString& title, const QString& initial,
                                   const std::string& renaming);

    SceneEditor* editor_;
    Viewport* viewport_;
    QWidget* dialogParent_;
    QMenu* menu_;
};

}  // namespace rs::ui
