// PostedLook: the display settings of the posted document, carried onto the displayed frame.
#include "adapter/posted_look.h"

namespace rs::ui {

bool PostedLook::post(const RenderSettings& render) {
    const bool changed = render.tonemap != tonemap_ || render.exposure != exposure_;
    tonemap_ = render.tonemap;
    exposure_ = render.exposure;
    return changed;
}

void PostedLook::applyTo(DisplayFrame& d) const {
    if (d.tonemap == tonemap_ && d.exposure == exposure_) return;
    d.tonemap = tonemap_;
    d.exposure = exposure_;
    ++d.serial;
}

}  // namespace rs::ui
