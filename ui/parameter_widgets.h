// Editor widgets generated from parameter descriptors (spin boxes, sliders, colour buttons,
// combos), one factory for every kind the render side describes.
#pragma once

#include "scene/parameters.h"

#include <functional>

class QWidget;

namespace rs::ui {

/// A widget editing one parameter, and how to show a new value without emitting a change.
struct ParamEditor {
    QWidget* widget = nullptr;
    std::function<void(const ParamValue&)> setValue;
};

/// Builds the editor for `desc` as a child of `parent`; `onChange` gets every user edit.
ParamEditor makeParamEditor(const ParamDescriptor& desc, QWidget* parent,
                            std::function<void(const ParamValue&)> onChange);

}  // namespace rs::ui
