// MouseDrag: the end of a drag takes its object drag and orbit with it.
#include "viewport/mouse_drag.h"

namespace rs::ui {

std::optional<ObjectDrag> MouseDrag::finish() {
    kind_ = Kind::None;
    orbit_.reset();
    std::optional<ObjectDrag> objects = std::move(objects_);
    objects_.reset();
    return objects;
}

}  // namespace rs::ui
