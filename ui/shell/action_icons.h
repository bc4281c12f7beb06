// Icons of the designer's actions: the desktop's freedesktop theme icon where one exists,
// else the project's own SVG in resources/icons/actions/.
#pragma once

#include <QIcon>

namespace rs::ui {

/// The theme's `themeName` icon (empty: none is looked up), falling back to
/// :/icons/actions/`bundled`.svg.
QIcon actionIcon(const char* themeName, const char* bundled);

}  // namespace rs::ui
