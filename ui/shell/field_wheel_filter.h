// The mouse wheel over a field the user has not clicked into scrolls the panel, not the value.
#pragma once

#include <QObject>

namespace rs::ui {

/// Application-wide filter: a wheel event over a spin box, combo box or slider that does not
/// have keyboard focus goes on to the widgets around it (the property panel scrolls) instead
/// of changing the value under the pointer, which would be an undoable edit the user did not
/// mean. Once the user clicks into the field (or tabs to it), the wheel steps its value as Qt
/// does. Such fields lose Qt::WheelFocus for Qt::StrongFocus as they are polished: Qt would
/// otherwise focus them on the first notch, before a filter sees it. Removed with `parent`.
class FieldWheelFilter : public QObject {
public:
    explicit FieldWheelFilter(QObject* parent);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
};

}  // namespace rs::ui
