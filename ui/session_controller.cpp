// SessionController: worker-thread callbacks to GUI-thread signals at display rate.
#include "session_controller.h"

#include <QMetaObject>

#include <algorithm>
#include <chrono>

namespace rs::ui {

namespace {
constexpr int kDisplayIntervalMs = 16;
}

SessionController::SessionController(int threads, QObject* parent)
    : QObject(parent), session_(std::make_unique<RenderSession>(threads)) {
    qRegisterMetaType<rs::PassInfo>();
    repaintTimer_.setSingleShot(true);
    repaintTimer_.setInterval(kDisplayIntervalMs);
    connect(&repaintTimer_, &QTimer::timeout, this, &SessionController::onRepaintTimer);
    updateTimer_.setSingleShot(true);
    updateTimer_.setInterval(kDisplayIntervalMs);
    connect(&updateTimer_, &QTimer::timeout, this, &SessionController::onUpdateTimer);
    rateTimer_.setInterval(1000);
    connect(&rateTimer_, &QTimer::timeout, this, [this] {
        updatesPerSecond_ = updatesThisSecond_;
        updatesThisSecond_ = 0;
    });
    rateTimer_.start();
    session_->setObserver(this);
}

SessionController::~SessionController() {
    // Joins the workers while this observer is still alive; callbacks they queued are
    // dropped with this object.
    session_.reset();
}

void SessionController::requestUpdate(const SceneDocument& doc) {
    pendingDoc_ = doc;
    ++requestSerial_;
    if (!updateTimer_.isActive()) {
        // The first change after a quiet spell goes out at once; later ones wait for the tick.
        onUpdateTimer();
        updateTimer_.start();
    }
}

void SessionController::onUpdateTimer() {
    if (!pendingDoc_) return;
    const uint64_t generation = session_->update(*pendingDoc_);
    pendingDoc_.reset();
    ++updatesThisSecond_;
    Q_EMIT documentPosted(requestSerial_, generation);
}

void SessionController::flushUpdate() {
    onUpdateTimer();
}

void SessionController::beginInteraction(ObjectId moving) {
    flushUpdate();
    session_->beginInteraction(moving);
}

void SessionController::endInteraction() {
    flushUpdate();
    session_->endInteraction();
}

std::shared_ptr<const DisplayFrame> SessionController::displayFrame() {
    const auto start = std::chrono::steady_clock::now();
    const uint64_t generation = committedGeneration_.load();
    auto frame = std::make_shared<DisplayFrame>(DisplayFrame::fromSession(*session_));
    frame->generation = generation;
    frame->serial = ++frameSerial_;
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ++handover_.count;
    handover_.totalMs += ms;
    handover_.maxMs = std::max(handover_.maxMs, ms);
    return frame;
}

void SessionController::tileDone(int, int, int, int, uint64_t generation) {
    uint64_t seen = committedGeneration_.load();
    while (seen < generation && !committedGeneration_.compare_exchange_weak(seen, generation)) {
    }
    if (framePending_.exchange(true)) return;
    QMetaObject::invokeMethod(
        this, [this] { if (!repaintTimer_.isActive()) repaintTimer_.start(); },
        Qt::QueuedConnection);
}

void SessionController::onRepaintTimer() {
    framePending_.store(false);
    Q_EMIT frameUpdated();
}

void SessionController::passDone(const PassInfo& info) {
    QMetaObject::invokeMethod(this, [this, info] { Q_EMIT passFinished(info); },
                              Qt::QueuedConnection);
}

void SessionController::frameComplete(uint64_t generation) {
    QMetaObject::invokeMethod(
        this, [this, generation] {
            Q_EMIT frameUpdated();
            Q_EMIT frameCompleted(generation);
        },
        Qt::QueuedConnection);
}

}  // namespace rs::ui
