// FramePacer: the first tiles after a quiet spell at once, later ones at the display's pace.
#include "adapter/frame_pacer.h"

#include <algorithm>
#include <utility>

namespace rs::ui {

FramePacer::FramePacer(std::function<void()> due) : due_(std::move(due)) {
    timer_.setSingleShot(true);
    QObject::connect(&timer_, &QTimer::timeout, [this] { fire(); });
}

void FramePacer::schedule() {
    if (timer_.isActive()) return;
    const qint64 since = lastDue_.isValid() ? lastDue_.elapsed() : kMinIntervalMs;
    timer_.start(int(std::max<qint64>(0, kMinIntervalMs - since)));
}

void FramePacer::retry(int ms) {
    pending_.store(true);
    if (!timer_.isActive()) timer_.start(ms);
}

void FramePacer::fire() {
    pending_.store(false);
    lastDue_.start();
    due_();
}

}  // namespace rs::ui
