// SessionController: worker-thread callbacks to GUI-thread signals at display rate.
#include "adapter/session_controller.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "adapter/frame_handover.h"
#include "session/render_session.h"

namespace rs::ui {

namespace {
/// How soon a hand-over that found the frame lock held tries again. A tile commit holds it
/// for microseconds, an edit's dirty marking for a few milliseconds.
constexpr int kBusyRetryMs = 2;
}  // namespace

void SessionHandle::setObserver(SessionObserver* observer) {
    session_.setObserver(observer);
}
void SessionHandle::setThreads(int threads) {
    session_.setThreads(threads);
}
void SessionHandle::setPolicy(const InteractionPolicy& policy) {
    session_.setPolicy(policy);
}
InteractionPolicy SessionHandle::policy() const {
    return session_.policy();
}
void SessionHandle::setEngine(EngineKind engine) {
    session_.setEngine(engine);
}
void SessionHandle::setFocus(float px, float py) {
    session_.setFocus(px, py);
}
uint64_t SessionHandle::generation() const {
    return session_.generation();
}
std::shared_ptr<const CompiledScene> SessionHandle::snapshot() const {
    return session_.snapshot();
}

SessionController::SessionController(int threads, QObject* parent)
    : QObject(parent), session_(std::make_unique<RenderSession>(threads)), mailbox_(this) {
    qRegisterMetaType<rs::PassInfo>();
    // Zero: fires when this event-loop pass has handled what was queued.
    updateTimer_.setSingleShot(true);
    updateTimer_.setInterval(0);
    connect(&updateTimer_, &QTimer::timeout, this, &SessionController::onUpdateTimer);
    session_->setObserver(this);
    session_->setDisplayWaits(true);  // Whether whole frames are waited for is the policy's.
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
        // The first change of this pass goes out at once; later ones wait for its end.
        onUpdateTimer();
        updateTimer_.start();
    }
}

void SessionController::onUpdateTimer() {
    if (!pendingDoc_) return;
    frameStorage_.request(std::size_t(std::max(pendingDoc_->render.width, 0)) *
                          std::size_t(std::max(pendingDoc_->render.height, 0)));
    const uint64_t generation = session_->update(*pendingDoc_);
    postedGeneration_ = generation;
    // Tone mapping and exposure trace nothing, so no tile will announce them: repaint here.
    const bool displayChanged = postedLook_.post(pendingDoc_->render);
    pendingDoc_.reset();
    updateRate_.count();
    Q_EMIT documentPosted(requestSerial_, generation);
    if (displayChanged) Q_EMIT frameUpdated();
}

void SessionController::flushUpdate() {
    onUpdateTimer();
}

std::shared_ptr<const CompiledScene> SessionController::appliedSnapshot() {
    flushUpdate();
    if (postedGeneration_ > 0) session_->waitForUpdate(postedGeneration_, std::chrono::seconds(1));
    return session_->snapshot();
}

void SessionController::beginInteraction(ObjectId moving) {
    flushUpdate();
    interacting_ = true;
    session_->beginInteraction(moving);
    Q_EMIT interactionChanged(true);
}

void SessionController::endInteraction() {
    flushUpdate();
    interacting_ = false;
    session_->endInteraction();
    Q_EMIT interactionChanged(false);
}

std::shared_ptr<const DisplayFrame> SessionController::displayFrame(FrameWait wait) {
    const auto start = std::chrono::steady_clock::now();
    if (FrameStorage room = frameStorage_.take(); room.pixels > 0) frame_->adopt(std::move(room));
    // Before the tiles are taken: every tile of the pass that made the frame whole is in them.
    const uint64_t wholeMark = session_->wholeMark();
    const bool tryOnly = wait == FrameWait::TryOnly;
    const bool onlyWhole = tryOnly && interacting_ && session_->policy().wholeFramesWhileMoving;
    // Every tile announced so far is copied below, so the copy holds their generation.
    CommittedTiles::Batch batch = tiles_.take();
    DisplayFrame& d = *frame_;
    const uint64_t serialBefore = d.serial;
    bool whole = false;
    if (!copyFrame(batch, tryOnly, onlyWhole, wholeMark, whole)) return frame_;
    postedLook_.applyTo(d);
    d.generation = std::max(d.generation, batch.generation);
    if (d.serial != serialBefore) Q_EMIT frameHandedOver(d.serial, whole);
    if (whole) session_->wholeFrameShown(wholeMark);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ++handover_.count;
    handover_.totalMs += ms;
    handover_.maxMs = std::max(handover_.maxMs, ms);
    return frame_;
}

bool SessionController::copyFrame(CommittedTiles::Batch& batch, bool tryOnly, bool onlyWhole,
                                  uint64_t wholeMark, bool& whole) {
    bool torn = false;
    const auto copy = [&](const DeepFrame& f, const std::shared_ptr<const CompiledScene>&) {
        const auto locked = std::chrono::steady_clock::now();
        whole = session_->wholeSince(wholeMark);
        if (onlyWhole && !whole) {
            torn = true;  // The last whole frame stays; these tiles wait for the next.
            return;
        }
        if (batch.everything) batch.tiles.assign(1, QRect(0, 0, f.width(), f.height()));
        // Edits clear the previous edit's re-traced overlay outside any tile: the flags follow
        // whole when the generation moved (a byte a pixel).
        const uint64_t generation = session_->generation();
        refreshFrame(*frame_, f, mergeRects(std::move(batch.tiles), QSize(f.width(), f.height())),
                     generation != frameSessionGeneration_);
        frameSessionGeneration_ = generation;
        handover_.copyMs +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - locked)
                .count();
    };
    if (!tryOnly) {
        session_->withFrame(copy);
        return true;
    }
    if (session_->tryWithFrame(copy) && !torn) return true;
    tiles_.hold(std::move(batch));
    // Torn is not busy: the pass that makes the frame whole ends with a hand-over (the
    // viewport's passFinished).
    if (torn) return false;
    // Kept for the next look, which comes soon whether or not more tiles arrive.
    ++handover_.busy;
    pacer_.retry(kBusyRetryMs);
    return false;
}

void SessionController::tileDone(int x0, int y0, int x1, int y1, uint64_t generation) {
    tiles_.add(x0, y0, x1, y1, generation);
    if (pacer_.announce()) mailbox_.post([this] { pacer_.schedule(); });
}

void SessionController::passDone(const PassInfo& info) {
    mailbox_.post([this, info] { Q_EMIT passFinished(info); });
}

void SessionController::frameComplete(uint64_t generation) {
    mailbox_.post([this, generation] {
        Q_EMIT frameUpdated();
        Q_EMIT frameCompleted(generation);
    });
}

}  // namespace rs::ui
