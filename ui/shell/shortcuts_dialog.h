// Help -> Keyboard Shortcuts: the list is read from the menus, so it cannot go stale.
#pragma once

#include <QList>
#include <QString>

class QDialog;
class QMenuBar;
class QWidget;

namespace rs::ui {

/// One command that has a shortcut: "File > Save As" and its keys in the platform's notation.
struct ShortcutEntry {
    QString command;
    QString keys;
};

/// Every action with a shortcut in `bar`'s menus (submenus included), in menu order.
QList<ShortcutEntry> menuShortcuts(const QMenuBar* bar);

/// Shows `entries` in a non-modal dialog (deleted on close) and returns it.
QDialog* showShortcutsDialog(QWidget* parent, const QList<ShortcutEntry>& entries);

}  // namespace rs::ui
