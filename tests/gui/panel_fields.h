// Finding the property panel's fields by their group and label, and typing into them, as a
// user would: shared by the GUI tests that edit through the panel.
#pragma once

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QTest>

#include "panels/property_panel.h"
#include "shell/main_window.h"

namespace rs::ui::test {

/// The widget of the visible row `label` in the panel's visible group whose title starts with
/// `group`; null if there is none.
inline QWidget* panelField(MainWindow& w, const QString& group, const QString& label) {
    for (QGroupBox* box : w.propertyPanel()->findChildren<QGroupBox*>()) {
        if (!box->title().startsWith(group) || !box->isVisibleTo(w.propertyPanel())) continue;
        auto* form = qobject_cast<QFormLayout*>(box->layout());
        for (int row = 0; form && row < form->rowCount(); ++row) {
            auto* l = form->itemAt(row, QFormLayout::LabelRole);
            auto* f = form->itemAt(row, QFormLayout::FieldRole);
            auto* text = l ? qobject_cast<QLabel*>(l->widget()) : nullptr;
            if (text && f && text->text() == label && text->isVisibleTo(box)) return f->widget();
        }
    }
    return nullptr;
}

/// Replaces the text of `spin` by typing `text` and Enter.
inline void typeInto(QDoubleSpinBox* spin, const QString& text) {
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, text);
    QTest::keyClick(spin, Qt::Key_Return);
}

}  // namespace rs::ui::test
