// RenderSession API and scheduler: edits, generations, applying documents, running passes,
// waiting. Its parts: DocumentInbox, PassPlanner (pass_planner.cpp), FrameBook, TileArena.
#include "session/render_session.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/failure_message.h"
#include "core/parallel.h"
#include "session/dirty_region.h"
#include "session/session_plan.h"

namespace rs {

namespace {

/// The observer's message for a failure of rendering or of applying a document.
std::string failureMessage(std::exception_ptr failure) {
    return "rendering failed: " + describeFailure(failure);
}

double msBetween(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace

RenderSession::RenderSession(int threads) : arena_(threads) {
    scheduler_ = std::thread(&RenderSession::run, this);
}

RenderSession::~RenderSession() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        ++generation_;  // Makes running tiles stop within a row.
    }
    wake_.notify_all();
    scheduler_.join();
}

void RenderSession::setObserver(SessionObserver* observer) {
    std::unique_lock lock(mutex_);
    // Between passes, with no call to the observer under way: then the workers' next reads of
    // observer_ come after this lock is released (a pass starts under it).
    done_.wait(lock, [&] { return !planner_.running() && notifying_ == 0; });
    observer_ = observer;
}

template <class Call>
void RenderSession::notifyObserver(std::unique_lock<std::mutex>& lock, Call&& call) {
    SessionObserver* observer = observer_;
    ++notifying_;
    lock.unlock();
    done_.notify_all();
    // Relocked and uncounted on the way out, also when the call throws.
    struct Done {
        RenderSession& session;
        std::unique_lock<std::mutex>& lock;
        ~Done() {
            lock.lock();
            --session.notifying_;
            session.done_.notify_all();
        }
    } done{*this, lock};
    if (observer) call(*observer);
}

void RenderSession::setThreads(int threads) {
    std::lock_guard lock(mutex_);
    arena_.setThreads(threads);
}

void RenderSession::setPolicy(const InteractionPolicy& policy) {
    {
        std::lock_guard lock(mutex_);
        planner_.setPolicy(policy);
    }
    wake_.notify_all();
}

void RenderSession::wholeFrameShown(uint64_t mark) {
    {
        std::lock_guard lock(mutex_);
        book_.shown(mark);
    }
    wake_.notify_all();
}

void RenderSession::setDisplayWaits(bool on) {
    std::lock_guard lock(mutex_);
    book_.setDisplayWaits(on);
}

void RenderSession::setEngine(EngineKind engine) {
    inbox_.setEngine(engine);
}

EngineKind RenderSession::engine() const {
    return inbox_.engine();
}

InteractionPolicy RenderSession::policy() const {
    std::lock_guard lock(mutex_);
    return planner_.policy();
}

std::shared_ptr<const CompiledScene> RenderSession::snapshot() const {
    std::lock_guard lock(mutex_);
    return inbox_.snapshot();
}

SessionStats RenderSession::stats() const {
    std::lock_guard lock(mutex_);
    return stats_;
}

uint64_t RenderSession::update(const SceneDocument& doc) {
    // It runs on the caller's (the designer's GUI) thread: a copy that cannot be allocated is
    // reported, never thrown; nothing has changed yet, so the session keeps what it showed.
    std::optional<SceneDocument> copy;  // Outside the lock: the scheduler may be planning.
    try {
        copy.emplace(doc);
    } catch (...) {
        const std::string message = failureMessage(std::current_exception());
        std::unique_lock lock(mutex_);
        const uint64_t current = inbox_.postedGeneration();
        notifyObserver(lock, [&](SessionObserver& o) { o.error(message); });
        return current;
    }
    uint64_t gen;
    {
        std::lock_guard lock(mutex_);
        // The bump alone stops running tiles; the old document's frame is out of date anyway.
        // Tiles that commit before the scheduler applies this document are marked with the rest.
        gen = ++inbox_.postedGeneration();
        const auto now = std::chrono::steady_clock::now();
        // While the user drags or orbits, a governed interactive pass within its time runs on:
        // the edits coalesce (the latest wins) and are applied when it ends, so the user sees
        // whole frames. Cut at every mouse move, an orbit's pass never ended: 50 frames a
        // second, each torn between cameras, none whole. Else the bump stops running tiles.
        const bool letFinish = !stop_ && planner_.letsThePassFinish(now);
        if (!letFinish && !planner_.passOwed()) generation_.store(gen);
        inbox_.post(std::move(*copy), gen, now);  // The latest wins.
        ++stats_.postedUpdates;
    }
    wake_.notify_all();
    return gen;
}

void RenderSession::setSceneUpdater(SceneUpdater updater) {
    std::lock_guard lock(mutex_);
    inbox_.setUpdater(std::move(updater));
}

bool RenderSession::waitForUpdate(uint64_t generation, std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    done_.wait_for(lock, timeout, [&] {
        return inbox_.appliedGeneration() >= generation || inbox_.failedGeneration() >= generation;
    });
    return inbox_.appliedGeneration() >= generation;
}

void RenderSession::applyPendingLocked(std::unique_lock<std::mutex>& lock) {
    DocumentToApply job = inbox_.takePending();
    // No pass runs: an edit that let the last one finish takes its generation now.
    if (generation_.load() < job.generation) generation_.store(job.generation);
    const auto start = std::chrono::steady_clock::now();
    std::exception_ptr failure;
    const std::optional<SceneUpdate> u = buildUnlocked(lock, job, failure);
    if (!u) {
        // The document applied last stays; its work goes on. Reported before waiters learn
        // of it.
        const std::string message = failureMessage(failure);
        notifyObserver(lock, [&](SessionObserver& o) { o.error(message); });
        inbox_.failed(job.generation);
        done_.notify_all();
        return;
    }
    inbox_.finishApplying();
    commitUpdateLocked(std::move(job), *u, start);
    lock.unlock();
    done_.notify_all();
    lock.lock();
}

std::optional<SceneUpdate> RenderSession::buildUnlocked(std::unique_lock<std::mutex>& lock,
                                                        const DocumentToApply& job,
                                                        std::exception_ptr& failure) {
    // Without the lock: update() may post the next document meanwhile. Only this thread
    // writes the applied document and snapshot, so it reads them without the lock.
    std::optional<SceneUpdate> u;
    lock.unlock();
    try {
        u = job.updater(inbox_.doc(), job.before, job.doc, job.engine);
    } catch (...) {
        failure = std::current_exception();
        u.reset();
    }
    lock.lock();
    return u;
}

void RenderSession::commitUpdateLocked(DocumentToApply&& job, const SceneUpdate& u,
                                       std::chrono::steady_clock::time_point start) {
    auto frameLock = frameLock_.exclusive();  // Readers wait while pixels change state.
    const uint64_t gen = job.generation;
    inbox_.applied(std::move(job.doc), u.snapshot, gen);
    const SceneDocument& doc = inbox_.doc();
    const CompiledScene& snapshot = *inbox_.snapshot();
    ++stats_.appliedUpdates;
    if (u.edit.resized || book_.frame().width() != doc.render.width ||
        book_.frame().height() != doc.render.height)
        book_.requestResize();

    std::size_t marked = 0;
    if (u.edit.traced()) {  // Else nothing traced changed (names, tone mapping, ...).
        const auto markStart = std::chrono::steady_clock::now();
        const EditMarks marks =
            book_.markEdit(u.edit, snapshot, planner_.policy(), planner_.interacting(),
                           doc.render.width, doc.render.height);
        marked = marks.pixels;
        if (marks.blocksCounted) {
            stats_.lastMarkBlocksTested = marks.blocksTested;
            stats_.lastMarkBlocksGrown = marks.blocksGrown;
        }
        const auto markEnd = std::chrono::steady_clock::now();
        stats_.lastMarkMs = msBetween(markStart, markEnd);
        if (u.edit.focus != kNoObject) {
            const PixelRect r =
                screenFootprint(snapshot.camera(), snapshot.objectBounds(u.edit.focus));
            if (!r.empty()) planner_.setFocus(0.5f * float(r.x0 + r.x1), 0.5f * float(r.y0 + r.y1));
        }
        stats_.lastDirtyPixels = marked;
        planner_.setPassOwed(marked > 0 && planner_.interacting() &&
                             planner_.policy().wholeFramesWhileMoving);
        stats_.lastEditRefitted = u.edit.refitted;
        stats_.lastUpdateMs = msBetween(start, markEnd);
    }
    // Nothing left to trace: the frame is current for this generation (no pass will say so).
    if (marked == 0 && !book_.resizePending() && !book_.frame().anyBelow(targetStateLocked()))
        book_.completed(gen);
    if (book_.resizePending()) book_.torn();
}

void RenderSession::beginInteraction(ObjectId moving) {
    {
        std::lock_guard lock(mutex_);
        planner_.beginInteraction(moving);
    }
    wake_.notify_all();
}

void RenderSession::endInteraction() {
    {
        std::lock_guard lock(mutex_);
        planner_.endInteraction();
        inbox_.requestRelease();  // The scheduler marks the shadows the drag moved.
    }
    wake_.notify_all();
}

void RenderSession::markReleasedShadowsLocked() {
    inbox_.releaseHandled();
    book_.markReleasedShadows(inbox_.snapshot().get(), frameLock_);
}

void RenderSession::setFocus(float px, float py) {
    std::lock_guard lock(mutex_);
    planner_.setFocus(px, py);
}

bool RenderSession::waitForPass(uint64_t generation, std::chrono::milliseconds timeout,
                                PassInfo* info) {
    std::unique_lock lock(mutex_);
    const bool ok = done_.wait_for(lock, timeout, [&] {
        return book_.completedGeneration() >= generation || generation_.load() > generation ||
               inbox_.failedGeneration() >= generation;
    });
    if (info) *info = stats_.lastPass;
    return ok && book_.completedGeneration() >= generation;
}

bool RenderSession::waitUntilComplete(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    return done_.wait_for(lock, timeout, [&] {
        return inbox_.hasApplied() && !inbox_.hasPending() && !inbox_.applying() &&
               !inbox_.releasePending() && !planner_.running() && notifying_ == 0 &&
               !book_.resizePending() && !book_.frame().anyBelow(kFinal);
    });
}

bool RenderSession::hasWorkLocked() const {
    if (inbox_.hasPending() || inbox_.releasePending()) return true;
    if (!inbox_.hasApplied()) return false;
    return book_.resizePending() || book_.frame().anyBelow(targetStateLocked());
}

void RenderSession::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        try {
            runPasses(lock);
            return;
        } catch (...) {
            // A worker's or the planner's exception (bad_alloc of a huge frame, ...) must not
            // terminate the designer: report it, keep the document, wait for the next edit
            // (the same work would fail the same way).
            const std::string message = failureMessage(std::current_exception());
            if (!lock.owns_lock()) lock.lock();
            planner_.passEnded();
            book_.dropFrameIfResizing(frameLock_);
            const uint64_t failed = generation_.load();
            notifyObserver(lock, [&](SessionObserver& o) { o.error(message); });
            wake_.wait(
                lock, [&] { return stop_ || inbox_.hasPending() || generation_.load() != failed; });
            if (stop_) return;
        }
    }
}

void RenderSession::runPasses(std::unique_lock<std::mutex>& lock) {
    PassPlan plan;
    for (;;) {
        wake_.wait(lock, [&] { return stop_ || hasWorkLocked(); });
        if (stop_) return;
        if (inbox_.hasPending() && !planner_.passOwed()) {
            applyPendingLocked(lock);
            continue;
        }
        if (inbox_.releasePending()) {
            markReleasedShadowsLocked();
            done_.notify_all();  // Waiters for a complete frame may have waited on this alone.
            continue;
        }
        if (!inbox_.hasApplied()) continue;
        plan.reset();
        const auto planStart = std::chrono::steady_clock::now();
        const bool planned = planLocked(plan);
        planner_.setPassOwed(
            false);  // Planned and run now, or nothing to show: the next edit applies.
        if (!planned) continue;
        stats_.lastPassTiles = plan.tiles.size();
        const double planMs = msBetween(planStart, std::chrono::steady_clock::now());
        if (!tearLocked(lock, plan)) return;
        runPassUnlocked(lock, plan, planMs);
    }
}

bool RenderSession::planLocked(PassPlan& plan) {
    const SceneDocument& doc = inbox_.doc();
    if (book_.resizePending()) {
        const std::string tooLarge = imageSizeError(doc.render.width, doc.render.height);
        if (!tooLarge.empty()) throw std::length_error(tooLarge);
    }
    arena_.refresh();
    const RenderSettings& settings = inbox_.snapshot()->settings();
    book_.resizeIfPending(settings.width, settings.height, frameLock_);
    return planner_.plan(plan, book_.frame(), inbox_.snapshot(), generation_.load(),
                         stats_.lastUpdateMs, stats_.lastInteractivePass.planMs);
}

bool RenderSession::tearLocked(std::unique_lock<std::mutex>& lock, const PassPlan& plan) {
    if ((plan.kind != PassKind::Interactive && plan.kind != PassKind::Base) ||
        !book_.frame().anyBelow(kInteractive))
        return true;
    // This pass re-traces stale pixels: the frame is torn until one leaves none.
    uint64_t whole = 0;
    if (book_.wholeUnseen(whole) && planner_.policy().wholeFramesWhileMoving &&
        planner_.interacting()) {
        wake_.wait_for(lock, kDisplayWait, [&] {
            return stop_ || book_.wholeShown() >= whole || !planner_.interacting();
        });
        if (stop_) return false;
    }
    book_.torn();
    return true;
}

void RenderSession::runPassUnlocked(std::unique_lock<std::mutex>& lock, PassPlan& plan,
                                    double planMs) {
    planner_.passStarted(plan, std::chrono::steady_clock::now());
    lock.unlock();
    PassInfo info;
    execute(plan, info);
    info.planMs = planMs;
    lock.lock();
    planner_.passEnded();
    passDoneLocked(lock, plan, info);
}

void RenderSession::passDoneLocked(std::unique_lock<std::mutex>& lock, const PassPlan& plan,
                                   const PassInfo& info) {
    const auto now = std::chrono::steady_clock::now();
    book_.passEnded();
    if (info.cancelled)
        stats_.lastCancelLatencyMs = msBetween(inbox_.editTime(), now);
    else
        book_.completed(plan.generation);
    planner_.recordPass(plan, info);
    stats_.lastPass = info;
    if (plan.kind == PassKind::Interactive) stats_.lastInteractivePass = info;
    ++stats_.passes;
    const bool complete = !info.cancelled && !inbox_.hasPending() && !inbox_.releasePending() &&
                          !book_.resizePending() && !book_.frame().anyBelow(kFinal);
    const uint64_t gen = generation_.load();
    notifyObserver(lock, [&](SessionObserver& o) {
        o.passDone(info);
        if (complete && gen == plan.generation) o.frameComplete(gen);
    });
}

void RenderSession::execute(PassPlan& plan, PassInfo& info) {
    const auto start = std::chrono::steady_clock::now();
    PassCounters counters;
    arenaExecute(arena_.arena(), [&] {
        parallelFor(
            tbb::blocked_range<std::size_t>(0, plan.tiles.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& r) {
                for (std::size_t t = r.begin(); t != r.end(); ++t) {
                    if (generation_.load(std::memory_order_relaxed) != plan.generation) return;
                    processTile(plan, plan.tiles[t], counters);
                }
            },
            tbb::simple_partitioner());
    });
    info.kind = plan.kind;
    info.generation = plan.generation;
    info.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    info.tracedPixels = counters.pixels.load();
    info.rays = counters.rays.load();
    info.totalPixels = std::size_t(plan.width) * std::size_t(plan.height);
    info.cancelled = generation_.load() != plan.generation;
    info.governorLevel = plan.governorLevel;
}

}  // namespace rs
