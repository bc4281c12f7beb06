// RepaintPacing and HandoverPace: the viewport's hand-over pace.
#include "viewport/viewport_pacing.h"

#include <algorithm>

namespace rs::ui {

int64_t RepaintPacing::delay(int64_t nowMs) const {
    if (completion_ || interacting_ || lastHandOver_ == kNever) return 0;
    if (lastInput_ != kNever && nowMs - lastInput_ < quiet_) return 0;
    // The first tiles after a quiet spell at once (an edit's first pixels), then at the pace.
    return std::max<int64_t>(0, interval_ - (nowMs - lastHandOver_));
}

HandoverPace::HandoverPace(std::function<void()> due) {
    clock_.start();
    timer_.setSingleShot(true);
    QObject::connect(&timer_, &QTimer::timeout, &timer_, std::move(due));
}

void HandoverPace::setPacing(const RepaintPacing& pacing) {
    pacing_ = pacing;
    pacing_.handedOver(clock_.elapsed());
    timer_.stop();
}

bool HandoverPace::waits(bool interacting) {
    pacing_.setInteracting(interacting);
    if (const int64_t wait = pacing_.delay(clock_.elapsed()); wait > 0) {
        // Tiles that come meanwhile are all in the one hand-over the timer brings.
        if (!timer_.isActive()) timer_.start(int(std::min<int64_t>(wait, 1 << 30)));
        return true;
    }
    timer_.stop();
    return false;
}

}  // namespace rs::ui
