// View bookmarks: the Bookmarks menu and the edits of the document's views.
#include "shell/view_bookmarks.h"

#include <QMenu>
#include <algorithm>

#include "document/scene_editor.h"
#include "shell/error_reporter.h"
#include "shell/user_confirmation.h"
#include "viewport/viewport.h"

namespace rs::ui {

QString viewNameError(const SceneDocument& doc, const QString& name, const std::string& renaming) {
    if (name.trimmed().isEmpty()) return QObject::tr("A view needs a name.");
    const std::string wanted = name.toStdString();
    if (wanted != renaming && doc.findView(wanted))
        return QObject::tr("There is already a view named \"%1\".").arg(name);
    return {};
}

QString freeViewName(const SceneDocument& doc) {
    for (int n = 1;; ++n) {
        const QString name = QObject::tr("View %1").arg(n);
        if (!doc.findView(name.toStdString())) return name;
    }
}

ViewBookmarks::ViewBookmarks(SceneEditor* editor, Viewport* viewport, QWidget* dialogParent)
    : QObject(dialogParent),
      editor_(editor),
      viewport_(viewport),
      dialogParent_(dialogParent),
      menu_(new QMenu(tr("&Bookmarks"), dialogParent)) {
    menu_->setObjectName(QStringLiteral("bookmarksMenu"));
    connect(menu_, &QMenu::aboutToShow, this, &ViewBookmarks::fillMenu);
    fillMenu();
}

void ViewBookmarks::fillMenu() {
    menu_->clear();
    menu_->addAction(tr("&Bookmark This View..."), this, &ViewBookmarks::bookmarkView)
        ->setObjectName(QStringLiteral("bookmarkView"));
    const std::vector<ViewBookmark>& views = editor_->document().views;
    if (views.empty()) return;
    menu_->addSeparator();
    for (const ViewBookmark& v : views) {
        // The name as written, with any '&' kept visible rather than taken as a mnemonic.
        QString text = QString::fromStdString(v.name);
        text.replace(QLatin1Char('&'), QStringLiteral("&&"));
        menu_->addAction(text, this, [this, name = v.name] { goTo(name); })
            ->setObjectName(QStringLiteral("goToView:") + QString::fromStdString(v.name));
    }
    menu_->addSeparator();
    QMenu* rename = menu_->addMenu(tr("&Rename"));
    QMenu* remove = menu_->addMenu(tr("Re&move"));
    for (const ViewBookmark& v : views) {
        QString text = QString::fromStdString(v.name);
        text.replace(QLatin1Char('&'), QStringLiteral("&&"));
        rename->addAction(text, this, [this, name = v.name] { this->rename(name); });
        remove->addAction(text, this, [this, name = v.name] { this->remove(name); });
    }
}

std::optional<QString> ViewBookmarks::askName(const QString& title, const QString& initial,
                                              const std::string& renaming) {
    QString offered = initial;
    for (;;) {
        const std::optional<QString> name =
            askText(dialogParent_, title, tr("Name of the view:"), offered);
        if (!name) return std::nullopt;
        const QString why = viewNameError(editor_->document(), *name, renaming);
        if (why.isEmpty()) return name->trimmed();
        reportError(dialogParent_, title, why);
        offered = *name;
    }
}

void ViewBookmarks::bookmarkView() {
    const std::optional<QString> name =
        askName(tr("Bookmark This View"), freeViewName(editor_->document()), {});
    if (!name) return;
    SceneDocument doc = editor_->document();
    doc.views.push_back(ViewBookmark{name->toStdString(), viewport_->viewCamera(), {}});
    editor_->edit(tr("Bookmark View %1").arg(*name), std::move(doc));
}

bool ViewBookmarks::goTo(const std::string& name) {
    const ViewBookmark* view = editor_->document().findView(name);
    if (!view) return false;
    viewport_->setView(view->camera);
    return true;
}

void ViewBookmarks::rename(const std::string& name) {
    if (!editor_->document().findView(name)) return;
    const std::optional<QString> to =
        askName(tr("Rename View"), QString::fromStdString(name), name);
    if (!to || to->toStdString() == name) return;
    SceneDocument doc = editor_->document();
    for (ViewBookmark& v : doc.views)
        if (v.name == name) v.name = to->toStdString();
    editor_->edit(tr("Rename View %1").arg(QString::fromStdString(name)), std::move(doc));
}

void ViewBookmarks::remove(const std::string& name) {
    SceneDocument doc = editor_->document();
    const auto gone = std::remove_if(doc.views.begin(), doc.views.end(),
                                     [&](const ViewBookmark& v) { return v.name == name; });
    if (gone == doc.views.end()) return;
    doc.views.erase(gone, doc.views.end());
    editor_->edit(tr("Remove View %1").arg(QString::fromStdString(name)), std::move(doc));
}

}  // namespace rs::ui
