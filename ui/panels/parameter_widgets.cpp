// Descriptor-driven editor widgets; each type maps to one small widget group.
#include "panels/parameter_widgets.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <algorithm>
#include <cmath>
#include <memory>

namespace rs::ui {

namespace {

constexpr int kSliderSteps = 1000;

int decimalsFor(double step) {
    return std::clamp(int(std::ceil(-std::log10(step))) + 2, 2, 5);
}

/// The editor's bounds: the descriptor's soft range, which a value beyond it (held by a file,
/// inside the format's range) widens so that it is shown and kept, never clamped.
std::pair<double, double> offeredRange(const ParamDescriptor& d, double value) {
    return {std::min(d.softMin, value), std::max(d.softMax, value)};
}

QDoubleSpinBox* makeSpin(const ParamDescriptor& d, QWidget* parent) {
    auto* spin = new QDoubleSpinBox(parent);
    spin->setRange(d.softMin, d.softMax);
    if (!d.specialValueText.empty())
        spin->setSpecialValueText(QString::fromStdString(d.specialValueText));
    spin->setSingleStep(d.step);
    spin->setDecimals(decimalsFor(d.step));
    spin->setKeyboardTracking(false);
    spin->setAccelerated(true);
    // The ±1e6 ranges would make the size hint huge; let the form share the width instead,
    // but never below what a value of a few digits needs (with the arrows and the frame).
    const QString typical = QStringLiteral("-0000.") + QString(spin->decimals(), QLatin1Char('0'));
    spin->setMinimumWidth(spin->fontMetrics().horizontalAdvance(typical) + 36);
    spin->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    return spin;
}

QWidget* row(QWidget* parent, QHBoxLayout*& layout) {
    auto* w = new QWidget(parent);
    layout = new QHBoxLayout(w);
    layout->setContentsMargins(0, 0, 0, 0);
    return w;
}

void paintSwatch(QPushButton* b, const Vec3& c) {
    // An HDR colour shows its hue: the colour divided by its value.
    const Vec3 shown = glm::clamp(c / std::max({1.0f, c.x, c.y, c.z}), Vec3(0.0f), Vec3(1.0f));
    const QColor q = QColor::fromRgbF(shown.x, shown.y, shown.z);
    const QString text = q.lightnessF() > 0.5 ? QStringLiteral("black") : QStringLiteral("white");
    b->setStyleSheet(
        QStringLiteral("background-color: %1; color: %2; min-height: 18px;").arg(q.name(), text));
    b->setText(
        QStringLiteral("%1, %2, %3").arg(c.x, 0, 'g', 3).arg(c.y, 0, 'g', 3).arg(c.z, 0, 'g', 3));
}

ParamEditor floatEditor(const ParamDescriptor& d, QWidget* parent,
                        std::function<void(const ParamValue&)> onChange) {
    QHBoxLayout* layout;
    QWidget* w = row(parent, layout);
    auto* spin = makeSpin(d, w);
    QSlider* slider = nullptr;
    if (d.softMax - d.softMin <= 1000.0) {
        slider = new QSlider(Qt::Horizontal, w);
        slider->setRange(0, kSliderSteps);
        layout->addWidget(slider, 2);
        const double lo = d.softMin, span = d.softMax - d.softMin;
        QObject::connect(slider, &QSlider::valueChanged, spin, [=](int v) {
            const double value = lo + span * v / kSliderSteps;
            const QSignalBlocker block(spin);
            spin->setValue(value);
            onChange(float(value));
        });
    }
    layout->addWidget(spin, 1);
    QObject::connect(spin, &QDoubleSpinBox::valueChanged, w,
                     [onChange](double v) { onChange(float(v)); });
    auto set = [=](const ParamValue& v) {
        const double x = std::get<float>(v);
        const QSignalBlocker b1(spin);
        const auto [lo, hi] = offeredRange(d, x);
        spin->setRange(lo, hi);
        spin->setValue(x);
        if (slider) {
            const QSignalBlocker b2(slider);
            const double t = std::clamp((x - d.softMin) / (d.softMax - d.softMin), 0.0, 1.0);
            slider->setValue(int(std::lround(t * kSliderSteps)));
        }
    };
    return {w, set};
}

ParamEditor vecEditor(const ParamDescriptor& d, QWidget* parent,
                      std::function<void(const ParamValue&)> onChange) {
    QHBoxLayout* layout;
    QWidget* w = row(parent, layout);
    std::array<QDoubleSpinBox*, 3> spins;
    for (auto*& s : spins) {
        s = makeSpin(d, w);
        layout->addWidget(s);
    }
    auto current = [spins] {
        return Vec3(float(spins[0]->value()), float(spins[1]->value()), float(spins[2]->value()));
    };
    for (auto* s : spins)
        QObject::connect(s, &QDoubleSpinBox::valueChanged, w, [=](double) { onChange(current()); });
    auto set = [spins, d](const ParamValue& v) {
        const Vec3 x = std::get<Vec3>(v);
        for (int i = 0; i < 3; ++i) {
            QDoubleSpinBox* s = spins[std::size_t(i)];
            const QSignalBlocker b(s);
            const auto [lo, hi] = offeredRange(d, x[i]);
            s->setRange(lo, hi);
            s->setValue(x[i]);
        }
    };
    return {w, set};
}

/// Largest component: the colour's value (HSV), which HDR colours take beyond 1.
float valueOf(const Vec3& c) {
    return std::max({c.x, c.y, c.z});
}

/// `c` rescaled so that its value is `v` (a grey of `v` for black).
Vec3 withValue(const Vec3& c, float v) {
    const float m = valueOf(c);
    return m > 0.0f ? c * (v / m) : Vec3(v);
}

/// A colour button (QColorDialog, which clamps to 1, edits the colour divided by its HDR
/// multiplier max(1, value)) and a value spin box that goes beyond 1. While the dialog is
/// open the colour shown in it is previewed; Cancel puts the old one back, OK is one edit.
ParamEditor colorEditor(const ParamDescriptor& d, QWidget* parent,
                        std::function<void(const ParamValue&)> onChange, ParamPreview onPreview) {
    QHBoxLayout* layout;
    QWidget* w = row(parent, layout);
    auto* button = new QPushButton(w);
    button->setObjectName(QStringLiteral("colorButton"));
    auto* value = new QDoubleSpinBox(w);
    value->setObjectName(QStringLiteral("colorValue"));
    value->setRange(0.0, d.softMax);
    value->setSingleStep(0.1);
    value->setDecimals(3);
    value->setKeyboardTracking(false);
    value->setPrefix(QStringLiteral("× "));
    value->setToolTip(QObject::tr("Value: the largest component; beyond 1 for HDR colours"));
    // The panel takes its width from its rows' minimum widths when it is built, before a
    // colour is set: neither field's minimum may follow what it shows later. The swatch keeps
    // room for three components of three digits (its tooltip carries longer ones), the value
    // for three digits before the point.
    paintSwatch(button, Vec3(0.888f));
    button->setMinimumWidth(button->sizeHint().width());
    value->setRange(0.0, 999.999);
    value->setMinimumWidth(value->minimumSizeHint().width());
    value->setRange(0.0, d.softMax);
    layout->addWidget(button, 3);
    layout->addWidget(value, 1);
    auto colour = std::make_shared<Vec3>(0.0f);
    QObject::connect(button, &QPushButton::clicked, button, [=] {
        const float scale = std::max(1.0f, valueOf(*colour));
        const Vec3 base = glm::clamp(*colour / scale, Vec3(0.0f), Vec3(1.0f));
        const QColor initial = QColor::fromRgbF(base.x, base.y, base.z);
        auto hdr = [scale](const QColor& q) {
            return Vec3(float(q.redF()), float(q.greenF()), float(q.blueF())) * scale;
        };
        QColorDialog dialog(initial, button);
        dialog.setWindowTitle(QString::fromStdString(d.label));
        dialog.setOption(QColorDialog::DontUseNativeDialog);  // Native ones report no live colour.
        if (onPreview)
            QObject::connect(&dialog, &QColorDialog::currentColorChanged, &dialog,
                             [&](const QColor& q) { onPreview(ParamValue(hdr(q))); });
        const bool ok = dialog.exec() == QDialog::Accepted;
        if (onPreview) onPreview(std::nullopt);
        const QColor chosen = dialog.selectedColor();
        if (ok && chosen.isValid() && chosen.rgb() != initial.rgb()) onChange(hdr(chosen));
    });
    QObject::connect(value, &QDoubleSpinBox::valueChanged, w,
                     [=](double v) { onChange(withValue(*colour, float(v))); });
    auto set = [=](const ParamValue& v) {
        *colour = std::get<Vec3>(v);
        paintSwatch(button, *colour);
        button->setToolTip(button->text());
        const QSignalBlocker block(value);
        value->setRange(0.0, std::max(d.softMax, double(valueOf(*colour))));
        value->setValue(valueOf(*colour));
    };
    return {w, set};
}

ParamEditor editorFor(const ParamDescriptor& d, QWidget* parent,
                      std::function<void(const ParamValue&)> onChange, ParamPreview onPreview) {
    switch (d.type) {
        case ParamType::Float:
            return floatEditor(d, parent, std::move(onChange));
        case ParamType::Vec3:
            return vecEditor(d, parent, std::move(onChange));
        case ParamType::Color:
            return colorEditor(d, parent, std::move(onChange), std::move(onPreview));
        case ParamType::Int: {
            auto* spin = new QSpinBox(parent);
            spin->setRange(int(d.softMin), int(d.softMax));
            if (!d.specialValueText.empty())
                spin->setSpecialValueText(QString::fromStdString(d.specialValueText));
            spin->setKeyboardTracking(false);
            QObject::connect(spin, &QSpinBox::valueChanged, spin,
                             [onChange](int v) { onChange(v); });
            return {spin, [spin, d](const ParamValue& v) {
                        const QSignalBlocker b(spin);
                        const int x = std::get<int>(v);
                        const auto [lo, hi] = offeredRange(d, x);
                        spin->setRange(int(lo), int(hi));
                        spin->setValue(x);
                    }};
        }
        case ParamType::Bool: {
            auto* box = new QCheckBox(parent);
            QObject::connect(box, &QCheckBox::toggled, box, [onChange](bool v) { onChange(v); });
            return {box, [box](const ParamValue& v) {
                        const QSignalBlocker b(box);
                        box->setChecked(std::get<bool>(v));
                    }};
        }
        case ParamType::Enum: {
            auto* combo = new QComboBox(parent);
            for (int i = 0; i < int(d.enumNames.size()); ++i)
                combo->addItem(QString::fromStdString(d.enumLabel(i)));
            QObject::connect(combo, &QComboBox::currentIndexChanged, combo,
                             [onChange](int v) { onChange(v); });
            return {combo, [combo](const ParamValue& v) {
                        const QSignalBlocker b(combo);
                        combo->setCurrentIndex(std::get<int>(v));
                    }};
        }
        case ParamType::Text:
        case ParamType::File: {
            auto* edit = new QLineEdit(parent);
            edit->setReadOnly(d.type == ParamType::File);
            QObject::connect(edit, &QLineEdit::editingFinished, edit,
                             [edit, onChange] { onChange(edit->text().toStdString()); });
            return {edit, [edit](const ParamValue& v) {
                        const QSignalBlocker b(edit);
                        edit->setText(QString::fromStdString(std::get<std::string>(v)));
                    }};
        }
    }
    return {};
}

}  // namespace

ParamEditor makeParamEditor(const ParamDescriptor& d, QWidget* parent,
                            std::function<void(const ParamValue&)> onChange,
                            ParamPreview onPreview) {
    ParamEditor e = editorFor(d, parent, std::move(onChange), std::move(onPreview));
    if (e.widget) {
        // Tests and the Preferences dialog find an editor by its key.
        e.widget->setObjectName(QString::fromStdString(d.key));
        if (!d.toolTip.empty()) e.widget->setToolTip(QString::fromStdString(d.toolTip));
    }
    return e;
}

}  // namespace rs::ui
