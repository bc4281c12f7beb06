// SessionController: worker-thread callbacks to GUI-thread signals at display rate.
#include "session_controller.h"

#include <QMetaObject>

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
    if (!updateTimer_.isActive()) {
        // The first change after a quiet spell goes out at once; later ones wait for the tick.
        onUpdateTimer();
        updateTimer_.start();
    }
}

void SessionController::onUpdateTimer() {
    if (!pendingDoc_) return;
    session_->update(*pendingDoc_);
    pendingDoc_.reset();
    ++updatesThisSecond_;
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

void SessionController::tileDone(int, int, int, int, uint64_t) {
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
