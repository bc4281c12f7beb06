// FieldWheelFilter: unfocused value fields pass the wheel on to their parents.
#include "shell/field_wheel_filter.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QSlider>

namespace rs::ui {

FieldWheelFilter::FieldWheelFilter(QObject* parent) : QObject(parent) {
    qApp->installEventFilter(this);
}

namespace {

bool isValueField(const QObject* o) {
    return qobject_cast<const QAbstractSpinBox*>(o) || qobject_cast<const QComboBox*>(o) ||
           qobject_cast<const QSlider*>(o);
}

}  // namespace

bool FieldWheelFilter::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Polish && isValueField(watched)) {
        // Qt gives a wheel-focus widget the focus before any filter sees the wheel event.
        auto* field = static_cast<QWidget*>(watched);
        if (field->focusPolicy() == Qt::WheelFocus) field->setFocusPolicy(Qt::StrongFocus);
        return false;
    }
    if (event->type() != QEvent::Wheel || !isValueField(watched)) return false;
    if (static_cast<QWidget*>(watched)->hasFocus()) return false;
    // Not delivered and not accepted: QApplication offers the event to the field's parents,
    // up to the scroll area that holds the panel.
    event->ignore();
    return true;
}

}  // namespace rs::ui
