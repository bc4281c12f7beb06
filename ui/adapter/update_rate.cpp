// UpdateRate: a once-a-second count of the documents posted to the session.
#include "adapter/update_rate.h"

#include <utility>

namespace rs::ui {

UpdateRate::UpdateRate(std::function<void(double)> changed) : changed_(std::move(changed)) {
    timer_.setInterval(1000);
    QObject::connect(&timer_, &QTimer::timeout, [this] { onSecond(); });
    timer_.start();
}

void UpdateRate::onSecond() {
    const bool changed = perSecond_ != thisSecond_;
    perSecond_ = thisSecond_;
    thisSecond_ = 0;
    // Also when it falls to 0: passes stop when the user does, and with them passFinished,
    // so a status bar updated only there kept the drag's rate while idle.
    if (changed) changed_(perSecond_);
}

}  // namespace rs::ui
