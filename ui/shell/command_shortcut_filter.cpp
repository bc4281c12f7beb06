// Command shortcuts over focused fields: refuse the fields' ShortcutOverride for action keys.
#include "shell/command_shortcut_filter.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QKeyEvent>
#include <QKeySequence>

#include "viewport/viewport.h"

namespace rs::ui {

namespace {

/// Keys that name a command rather than edit text.
bool isCommandKey(const QKeyEvent& e) {
    const Qt::KeyboardModifiers command = Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier;
    return (e.modifiers() & command) || (e.key() >= Qt::Key_F1 && e.key() <= Qt::Key_F35);
}

}  // namespace

CommandShortcutFilter::CommandShortcutFilter(QWidget* window) : QObject(window), window_(window) {
    qApp->installEventFilter(this);
}

bool CommandShortcutFilter::inWindow(const QWidget* w) const {
    const QWidget* top = w->window();
    // A floating dock (the properties torn off) still belongs to the main window.
    return top == window_ || (qobject_cast<const QDockWidget*>(top) && window_->isAncestorOf(top));
}

bool CommandShortcutFilter::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::ShortcutOverride || !watched->isWidgetType()) return false;
    auto* key = static_cast<QKeyEvent*>(event);
    if (!isCommandKey(*key) || !inWindow(static_cast<QWidget*>(watched))) return false;
    if (watched->property(kTakesAllKeys).toBool()) return false;
    const QKeySequence pressed(
        QKeyCombination(key->modifiers() & ~Qt::KeypadModifier, Qt::Key(key->key())));
    for (const QAction* a : window_->findChildren<QAction*>()) {
        if (a->isEnabled() && a->shortcuts().contains(pressed)) {
            // Unaccepted and not delivered: the shortcut map gets the key, not the field.
            key->ignore();
            return true;
        }
    }
    return false;
}

}  // namespace rs::ui
