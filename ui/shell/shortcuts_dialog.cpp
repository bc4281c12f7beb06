// The shortcuts dialog: a two-column table built from the menu bar's actions.
#include "shell/shortcuts_dialog.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

void collect(const QMenu* menu, const QString& path, QList<ShortcutEntry>& out) {
    for (const QAction* a : menu->actions()) {
        if (a->isSeparator()) continue;
        // iconText() is the text without mnemonics and trailing "...".
        const QString name = path + QStringLiteral(" > ") + a->iconText();
        if (const QMenu* sub = a->menu()) {
            collect(sub, name, out);
            continue;
        }
        QStringList keys;
        for (const QKeySequence& k : a->shortcuts()) keys << k.toString(QKeySequence::NativeText);
        if (!keys.isEmpty()) out.append({name, keys.join(QStringLiteral(", "))});
    }
}

}  // namespace

QList<ShortcutEntry> menuShortcuts(const QMenuBar* bar) {
    QList<ShortcutEntry> out;
    for (const QAction* top : bar->actions())
        if (const QMenu* menu = top->menu()) collect(menu, top->iconText(), out);
    return out;
}

QDialog* showShortcutsDialog(QWidget* parent, const QList<ShortcutEntry>& entries) {
    auto* dialog = new QDialog(parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(QObject::tr("Keyboard Shortcuts"));
    auto* table = new QTableWidget(int(entries.size()), 2, dialog);
    table->setObjectName(QStringLiteral("shortcutsTable"));
    table->setHorizontalHeaderLabels({QObject::tr("Command"), QObject::tr("Shortcut")});
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->verticalHeader()->hide();
    for (int i = 0; i < int(entries.size()); ++i) {
        table->setItem(i, 0, new QTableWidgetItem(entries[i].command));
        table->setItem(i, 1, new QTableWidgetItem(entries[i].keys));
    }
    table->resizeColumnsToContents();
    table->horizontalHeader()->setStretchLastSection(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(table);
    layout->addWidget(buttons);
    dialog->resize(520, 480);
    dialog->show();
    return dialog;
}

}  // namespace rs::ui
