// Descriptor-driven editor widgets; each type maps to one small widget group.
#include "parameter_widgets.h"

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

QDoubleSpinBox* makeSpin(const ParamDescriptor& d, QWidget* parent) {
    auto* spin = new QDoubleSpinBox(parent);
    spin->setRange(d.min, d.max);
    spin->setSingleStep(d.step);
    spin->setDecimals(decimalsFor(d.step));
    spin->setKeyboardTracking(false);
    spin->setAccelerated(true);
    // The ±1e6 ranges would make the size hint huge; let the form share the width instead.
    spin->setMinimumWidth(56);
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
    const QColor q = QColor::fromRgbF(std::clamp(c.x, 0.0f, 1.0f), std::clamp(c.y, 0.0f, 1.0f),
                                      std::clamp(c.z, 0.0f, 1.0f));
    const QString text = q.lightnessF() > 0.5 ? QStringLiteral("black") : QStringLiteral("white");
    b->setStyleSheet(QStringLiteral("background-color: %1; color: %2; min-height: 18px;").arg(q.name(), text));
    b->setText(QStringLiteral("%1, %2, %3").arg(c.x, 0, 'g', 3).arg(c.y, 0, 'g', 3).arg(c.z, 0, 'g', 3));
}

ParamEditor floatEditor(const ParamDescriptor& d, QWidget* parent,
                        std::function<void(const ParamValue&)> onChange) {
    QHBoxLayout* layout;
    QWidget* w = row(parent, layout);
    auto* spin = makeSpin(d, w);
    QSlider* slider = nullptr;
    if (d.max - d.min <= 1000.0) {
        slider = new QSlider(Qt::Horizontal, w);
        slider->setRange(0, kSliderSteps);
        layout->addWidget(slider, 2);
        const double lo = d.min, span = d.max - d.min;
        QObject::connect(slider, &QSlider::valueChanged, spin, [=](int v) {
            const double value = lo + span * v / kSliderSteps;
            const QSignalBlocker block(spin);
            spin->setValue(value);
            onChange(float(value));
        });
    }
    layout->addWidget(spin, 1);
    QObject::connect(spin, &QDoubleSpinBox::valueChanged, w, [onChange](double v) { onChange(float(v)); });
    auto set = [=](const ParamValue& v) {
        const double x = std::get<float>(v);
        const QSignalBlocker b1(spin);
        spin->setValue(x);
        if (slider) {
            const QSignalBlocker b2(slider);
            slider->setValue(int(std::lround((x - d.min) / (d.max - d.min) * kSliderSteps)));
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
    auto set = [spins](const ParamValue& v) {
        const Vec3 x = std::get<Vec3>(v);
        for (int i = 0; i < 3; ++i) {
            const QSignalBlocker b(spins[std::size_t(i)]);
            spins[std::size_t(i)]->setValue(x[i]);
        }
    };
    return {w, set};
}

ParamEditor colorEditor(const ParamDescriptor& d, QWidget* parent,
                        std::function<void(const ParamValue&)> onChange) {
    auto* button = new QPushButton(parent);
    auto value = std::make_shared<Vec3>(0.0f);
    QObject::connect(button, &QPushButton::clicked, button, [=] {
        const Vec3 c = glm::clamp(*value, Vec3(0.0f), Vec3(1.0f));
        const QColor chosen = QColorDialog::getColor(QColor::fromRgbF(c.x, c.y, c.z), button,
                                                     QString::fromStdString(d.label));
        if (!chosen.isValid()) return;
        onChange(Vec3(float(chosen.redF()), float(chosen.greenF()), float(chosen.blueF())));
    });
    auto set = [=](const ParamValue& v) {
        *value = std::get<Vec3>(v);
        paintSwatch(button, *value);
    };
    return {button, set};
}

}  // namespace

ParamEditor makeParamEditor(const ParamDescriptor& d, QWidget* parent,
                            std::function<void(const ParamValue&)> onChange) {
    switch (d.type) {
        case ParamType::Float: return floatEditor(d, parent, std::move(onChange));
        case ParamType::Vec3: return vecEditor(d, parent, std::move(onChange));
        case ParamType::Color: return colorEditor(d, parent, std::move(onChange));
        case ParamType::Int: {
            auto* spin = new QSpinBox(parent);
            spin->setRange(int(d.min), int(d.max));
            spin->setKeyboardTracking(false);
            QObject::connect(spin, &QSpinBox::valueChanged, spin, [onChange](int v) { onChange(v); });
            return {spin, [spin](const ParamValue& v) {
                        const QSignalBlocker b(spin);
                        spin->setValue(std::get<int>(v));
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
            for (const auto& n : d.enumNames) combo->addItem(QString::fromStdString(n));
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

}  // namespace rs::ui
