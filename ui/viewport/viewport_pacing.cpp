// RepaintPacing: the viewport's hand-over pace.
#include "viewport/viewport_pacing.h"

#include <algorithm>

namespace rs::ui {

int64_t RepaintPacing::delay(int64_t nowMs) const {
    if (completion_ || interacting_ || lastHandOver_ == kNever) return 0;
    if (lastInput_ != kNever && nowMs - lastInput_ < quiet_) return 0;
    // The first tiles after a quiet spell at once (an edit's first pixels), then at the pace.
    return std::max<int64_t>(0, interval_ - (nowMs - lastHandOver_));
}

}  // namespace rs::ui
