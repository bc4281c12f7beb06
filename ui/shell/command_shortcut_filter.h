// Keeps the main window's command shortcuts working while one of its fields has focus.
#pragma once

#include <QObject>

class QWidget;

namespace rs::ui {

/// Application-wide filter for one main window: a Ctrl, Alt or Meta chord or a function key
/// that one of the window's actions has as a shortcut goes to that action even when the
/// focused widget (a property-panel spin box, the outliner's rename field) would take it as an
/// editing key (Ctrl+E is end-of-line and Ctrl+Z the field's own undo on X11). Plain keys
/// (Delete, Backspace, letters, arrows) stay with the field. Dialogs are left alone, and so
/// is a widget whose kTakesAllKeys property (viewport/viewport.h) is true (the viewport during a
/// drag or gesture, where Ctrl+Z cancels the gesture instead of undoing under it).
class CommandShortcutFilter : public QObject {
public:
    /// Installs itself on the application; removed when `window` (its parent) is destroyed.
    explicit CommandShortcutFilter(QWidget* window);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool inWindow(const QWidget* w) const;

    QWidget* window_;
};

}  // namespace rs::ui
