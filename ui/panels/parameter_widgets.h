// Editor widgets generated from parameter descriptors (spin boxes, sliders, colour buttons,
// combos), one factory for every kind the render side describes.
#pragma once

#include <functional>
#include <optional>

#include "scene/parameters.h"

class QWidget;

namespace rs::ui {

/// A widget editing one parameter, and how to show a new value without emitting a change.
struct ParamEditor {
    QWidget* widget = nullptr;
    std::function<void(const ParamValue&)> setValue;
};

/// Shows a value the user is trying (a colour dialog's current colour) without an undo
/// step; nullopt ends the try and puts the document's value back.
using ParamPreview = std::function<void(const std::optional<ParamValue>&)>;

/// Builds the editor for `desc` as a child of `parent`; `onChange` gets every user edit,
/// `onPreview` (when set) the values a dialog tries before its OK.
ParamEditor makeParamEditor(const ParamDescriptor& desc, QWidget* parent,
                            std::function<void(const ParamValue&)> onChange,
                            ParamPreview onPreview = {});

}  // namespace rs::ui
