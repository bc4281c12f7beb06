// RenderSession API and scheduler: edits, generations, pass planning, waiting.
#include "session/render_session.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
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

/// More regions than this are merged into their bounding box (a long, winding drag).
constexpr std::size_t kMaxDeferredShadowRegions = 64;
/// A governed interactive pass that has run this many times the governor's target is cut
/// by the next edit: the edits that wait for it should not wait for ever (a pass the
/// governor predicted far too cheap). Cut at 1.5 or 3 targets, a loaded machine's orbit
/// passes (40-90 ms at a 33 ms target) were cut as before and showed 2-18 whole frames a
/// second against 10-16 never cut (measure-designer, load 5).
constexpr double kHoldPassForTargets = 6.0;
}  // namespace

int RenderSession::arenaSize(int threads) {
    return threads > 0 ? threads : tbb::info::default_concurrency();
}

RenderSession::RenderSession(int threads)
    : threads_(threads), arena_(std::make_unique<BackgroundArena>(arenaSize(threads))) {
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
    done_.wait(lock, [&] { return !running_ && notifying_ == 0; });
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
    if (threads == threads_) return;
    threads_ = threads;
    threadsChanged_ = true;
}

void RenderSession::setPolicy(const InteractionPolicy& policy) {
    {
        std::lock_guard lock(mutex_);
        policy_ = policy;
    }
    wake_.notify_all();
}

void RenderSession::wholeFrameShown(uint64_t mark) {
    {
        std::lock_guard lock(mutex_);
        wholeShown_ = std::max(wholeShown_, mark);
    }
    wake_.notify_all();
}

void RenderSession::setDisplayWaits(bool on) {
    std::lock_guard lock(mutex_);
    displayWaits_ = on;
}

void RenderSession::setEngine(EngineKind engine) {
    engine_.store(engine);
}

EngineKind RenderSession::engine() const {
    return engine_.load();
}

InteractionPolicy RenderSession::policy() const {
    std::lock_guard lock(mutex_);
    return policy_;
}

std::shared_ptr<const CompiledScene> RenderSession::snapshot() const {
    std::lock_guard lock(mutex_);
    return snapshot_;
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
        const uint64_t current = postedGeneration_;
        notifyObserver(lock, [&](SessionObserver& o) { o.error(message); });
        return current;
    }
    uint64_t gen;
    {
        std::lock_guard lock(mutex_);
        // The bump alone stops running tiles; the old document's frame is out of date anyway.
        // Tiles that commit before the scheduler applies this document are marked with the rest.
        gen = ++postedGeneration_;
        const auto now = std::chrono::steady_clock::now();
        // While the user drags or orbits, a governed interactive pass within its time runs on:
        // the edits coalesce (the latest wins) and are applied when it ends, so the user sees
        // whole frames. Cut at every mouse move, an orbit's pass never ended: 50 frames a
        // second, each torn between cameras, none whole. Else the bump stops running tiles.
        if (!letsThePassFinishLocked(now) && !passOwed_) generation_.store(gen);
        pendingDoc_ = std::move(*copy);  // A document not yet applied is dropped: the latest wins.
        pendingGeneration_ = gen;
        editTime_ = now;
        ++stats_.postedUpdates;
    }
    wake_.notify_all();
    return gen;
}

void RenderSession::setSceneUpdater(SceneUpdater updater) {
    std::lock_guard lock(mutex_);
    updater_ = std::move(updater);
}

bool RenderSession::waitForUpdate(uint64_t generation, std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    done_.wait_for(lock, timeout, [&] {
        return appliedGeneration_ >= generation || failedGeneration_ >= generation;
    });
    return appliedGeneration_ >= generation;
}

void RenderSession::applyPendingLocked(std::unique_lock<std::mutex>& lock) {
    SceneDocument doc = std::move(*pendingDoc_);
    pendingDoc_.reset();
    const uint64_t gen = pendingGeneration_;
    // No pass runs: an edit that let the last one finish takes its generation now.
    if (generation_.load() < gen) generation_.store(gen);
    const auto start = std::chrono::steady_clock::now();
    applying_ = true;
    const std::shared_ptr<const CompiledScene> before = hasDocument_ ? snapshot_ : nullptr;
    const EngineKind engine = engine_.load();
    const SceneUpdater updater = updater_ ? updater_ : SceneUpdater(updateScene);
    // Without the lock: update() may post the next document meanwhile. Only this thread
    // writes doc_ and snapshot_.
    lock.unlock();
    SceneUpdate u;
    std::exception_ptr failure;
    try {
        u = updater(doc_, before, doc, engine);
    } catch (...) {
        failure = std::current_exception();
    }
    lock.lock();
    if (failure) {
        // The document applied last stays; its work goes on. Reported before waiters learn
        // of it.
        const std::string message = failureMessage(failure);
        notifyObserver(lock, [&](SessionObserver& o) { o.error(message); });
        applying_ = false;
        failedGeneration_ = std::max(failedGeneration_, gen);
        done_.notify_all();
        return;
    }
    applying_ = false;

    auto frameLock = frameLock_.exclusive();  // Readers wait while pixels change state.
    doc_ = std::move(doc);
    hasDocument_ = true;
    snapshot_ = u.snapshot;
    appliedGeneration_ = gen;
    ++stats_.appliedUpdates;
    if (u.edit.resized || frame_.width() != doc_.render.width ||
        frame_.height() != doc_.render.height)
        pendingResize_ = true;

    std::size_t marked = 0;
    if (u.edit.traced()) {  // Else nothing traced changed (names, tone mapping, ...).
        const auto markStart = std::chrono::steady_clock::now();
        marked = markEditLocked(u.edit);
        const auto markEnd = std::chrono::steady_clock::now();
        stats_.lastMarkMs = std::chrono::duration<double, std::milli>(markEnd - markStart).count();
        if (u.edit.focus != kNoObject) {
            const PixelRect r =
                screenFootprint(snapshot_->camera(), snapshot_->objectBounds(u.edit.focus));
            if (!r.empty()) {
                focusX_ = 0.5f * float(r.x0 + r.x1);
                focusY_ = 0.5f * float(r.y0 + r.y1);
            }
        }
        stats_.lastDirtyPixels = marked;
        passOwed_ = marked > 0 && interacting_ && policy_.wholeFramesWhileMoving;
        stats_.lastEditRefitted = u.edit.refitted;
        stats_.lastUpdateMs = std::chrono::duration<double, std::milli>(markEnd - start).count();
    }
    // Nothing left to trace: the frame is current for this generation (no pass will say so).
    if (marked == 0 && !pendingResize_ && !frame_.anyBelow(targetStateLocked()))
        completedPassGeneration_ = std::max(completedPassGeneration_, gen);
    if (pendingResize_) tornLocked();
    frameLock.unlock();
    lock.unlock();
    done_.notify_all();
    lock.lock();
}

std::size_t RenderSession::markEditLocked(const SceneEdit& traced) {
    if (pendingResize_ || traced.everything || !policy_.dirtyRegions)
        deferredShadowRegions_.clear();  // Every pixel is traced again anyway.
    if (pendingResize_) return std::size_t(doc_.render.width) * std::size_t(doc_.render.height);
    SceneEdit edit = traced;
    if (!policy_.dirtyRegions) edit.everything = true;
    if (edit.everything) {
        // Every pixel: no mask to build or read, one pass over the states and flags.
        frame_.markAllStale();
        lastTouchedBlocks_.assign(std::size_t(frame_.blocksX()) * std::size_t(frame_.blocksY()), 1);
        stats_.lastMarkBlocksTested = stats_.lastMarkBlocksGrown = 0;
        return frame_.pixelCount();
    }
    // While dragging with shadows off or deferred, the moving object's shadow is not on
    // screen: its pixels are marked once, on release, instead of on every step.
    const bool deferShadows =
        interacting_ && !edit.everything &&
        (policy_.shadows == MovingShadows::Off || policy_.shadows == MovingShadows::Deferred);
    MarkStats markStats;
    const std::size_t marked =
        markDirtyPixels(edit, *snapshot_, frame_, dirtyMask_,
                        deferShadows ? MarkScope::WithoutShadows : MarkScope::All, &markStats);
    stats_.lastMarkBlocksTested = markStats.blocksTested;
    stats_.lastMarkBlocksGrown = markStats.blocksGrown;
    if (deferShadows) {
        deferredShadowRegions_.insert(deferredShadowRegions_.end(), edit.regions.begin(),
                                      edit.regions.end());
        if (deferredShadowRegions_.size() > kMaxDeferredShadowRegions) {
            Aabb all;
            for (const Aabb& b : deferredShadowRegions_) all.expand(b);
            deferredShadowRegions_.assign(1, all);
        }
    }
    // Only blocks this edit or the previous one touched can change flags: the previous
    // edit's re-traced overlay is cleared, this edit's pixels go stale.
    const std::vector<uint8_t>& touched = dirtyMask_.touched;
    if (lastTouchedBlocks_.size() != touched.size()) lastTouchedBlocks_.assign(touched.size(), 1);
    for (std::size_t b = 0; b < touched.size(); ++b) {
        if (touched[b] || lastTouchedBlocks_[b]) frame_.applyBlockMarks(b, dirtyMask_.pixels);
    }
    lastTouchedBlocks_ = touched;
    return marked;
}

void RenderSession::beginInteraction(ObjectId moving) {
    {
        std::lock_guard lock(mutex_);
        interacting_ = true;
        moving_ = moving;
    }
    wake_.notify_all();
}

void RenderSession::endInteraction() {
    {
        std::lock_guard lock(mutex_);
        interacting_ = false;
        moving_ = kNoObject;
        releasePending_ = true;  // The scheduler marks the shadows the drag moved.
    }
    wake_.notify_all();
}

void RenderSession::markReleasedShadowsLocked() {
    releasePending_ = false;
    if (!deferredShadowRegions_.empty() && snapshot_ && !pendingResize_) {
        // The shadows the drag moved: pixels still showing an older shadow go back to stale.
        // Pixels traced during the drag already wait for refinement (and keep their deferred
        // records). No pass runs now, so no tile commits meanwhile.
        auto frameLock = frameLock_.exclusive();
        SceneEdit edit;
        edit.regions.swap(deferredShadowRegions_);
        if (markDirtyPixels(edit, *snapshot_, frame_, dirtyMask_, MarkScope::ShadowsOnly) > 0) {
            for (const int b : dirtyMask_.blocks)
                frame_.applyShadowMarks(std::size_t(b), dirtyMask_.pixels);
        }
    }
    deferredShadowRegions_.clear();
}

void RenderSession::setFocus(float px, float py) {
    std::lock_guard lock(mutex_);
    focusX_ = px;
    focusY_ = py;
}

bool RenderSession::waitForPass(uint64_t generation, std::chrono::milliseconds timeout,
                                PassInfo* info) {
    std::unique_lock lock(mutex_);
    const bool ok = done_.wait_for(lock, timeout, [&] {
        return completedPassGeneration_ >= generation || generation_.load() > generation ||
               failedGeneration_ >= generation;
    });
    if (info) *info = stats_.lastPass;
    return ok && completedPassGeneration_ >= generation;
}

bool RenderSession::waitUntilComplete(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    return done_.wait_for(lock, timeout, [&] {
        return hasDocument_ && !pendingDoc_ && !applying_ && !releasePending_ && !running_ &&
               notifying_ == 0 && !pendingResize_ && !frame_.anyBelow(kFinal);
    });
}

bool RenderSession::fullQualityWhileMoving() const {
    const InteractionPolicy& p = policy_;
    return p.resolution == MovingResolution::Full && !p.interleaved && !p.boxProxy &&
           p.refraction == RefractionMode::Full && p.reflection == ReflectionMode::Full &&
           (p.maxDepthWhileMoving < 0 ||
            (snapshot_ && p.maxDepthWhileMoving >= snapshot_->settings().maxDepth)) &&
           p.shadows == MovingShadows::Full && p.governorTargetMs <= 0.0;
}

uint8_t RenderSession::targetStateLocked() const {
    if (!interacting_) return kFinal;
    if (!fullQualityWhileMoving()) return kInteractive;
    return policy_.supersampleWhileMoving ? kFinal : kBase;
}

bool RenderSession::letsThePassFinishLocked(std::chrono::steady_clock::time_point now) const {
    if (!policy_.wholeFramesWhileMoving || !interacting_ || !running_ ||
        passKind_ != PassKind::Interactive || passLevel_ < 0 || stop_)
        return false;
    const double ran = std::chrono::duration<double, std::milli>(now - passStart_).count();
    return ran < kHoldPassForTargets * policy_.governorTargetMs;
}

bool RenderSession::hasWorkLocked() const {
    if (pendingDoc_ || releasePending_) return true;
    if (!hasDocument_) return false;
    return pendingResize_ || frame_.anyBelow(targetStateLocked());
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
            running_ = false;
            if (pendingResize_) {
                // A resize that threw leaves sides and buffers disagreeing: readers must see an
                // empty frame instead (the next update sizes it again).
                auto frameLock = frameLock_.exclusive();
                frame_ = DeepFrame{};
            }
            const uint64_t failed = generation_.load();
            notifyObserver(lock, [&](SessionObserver& o) { o.error(message); });
            wake_.wait(lock, [&] { return stop_ || pendingDoc_ || generation_.load() != failed; });
            if (stop_) return;
        }
    }
}

void RenderSession::runPasses(std::unique_lock<std::mutex>& lock) {
    Plan plan;
    for (;;) {
        wake_.wait(lock, [&] { return stop_ || hasWorkLocked(); });
        if (stop_) return;
        if (pendingDoc_ && !passOwed_) {
            applyPendingLocked(lock);
            continue;
        }
        if (releasePending_) {
            markReleasedShadowsLocked();
            done_.notify_all();  // Waiters for a complete frame may have waited on this alone.
            continue;
        }
        if (!hasDocument_) continue;
        if (pendingResize_) {
            const std::string tooLarge = imageSizeError(doc_.render.width, doc_.render.height);
            if (!tooLarge.empty()) throw std::length_error(tooLarge);
        }
        plan.reset();
        const auto planStart = std::chrono::steady_clock::now();
        const bool planned = planLocked(plan);
        passOwed_ = false;  // Planned and run now, or nothing to show: the next edit applies.
        if (!planned) continue;
        stats_.lastPassTiles = plan.tiles.size();
        const double planMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - planStart)
                .count();
        if ((plan.kind == PassKind::Interactive || plan.kind == PassKind::Base) &&
            frame_.anyBelow(kInteractive)) {
            // This pass re-traces stale pixels: the frame is torn until one leaves none.
            const uint64_t whole = wholeMark_.load(std::memory_order_relaxed);
            if (displayWaits_ && policy_.wholeFramesWhileMoving && interacting_ &&
                tears_.load() == whole && wholeShown_ < whole) {
                wake_.wait_for(lock, kDisplayWait,
                               [&] { return stop_ || wholeShown_ >= whole || !interacting_; });
                if (stop_) return;
            }
            tornLocked();
        }
        running_ = true;
        passStart_ = std::chrono::steady_clock::now();
        passKind_ = plan.kind;
        passLevel_ = plan.governorLevel;
        lock.unlock();
        PassInfo info;
        execute(plan, info);
        info.planMs = planMs;
        lock.lock();
        running_ = false;
        const auto now = std::chrono::steady_clock::now();
        // Between passes the scheduler reads the frame under mutex_ alone; every tile of the
        // pass has been announced to the observer by now.
        if (!frame_.anyBelow(kInteractive))
            wholeMark_.store(tears_.load(std::memory_order_relaxed), std::memory_order_release);
        if (info.cancelled) {
            stats_.lastCancelLatencyMs =
                std::chrono::duration<double, std::milli>(now - editTime_).count();
            // What the pass traced before the edit cut it is what this level costs now: a
            // governor fed finished passes alone never learns what an orbit step costs.
            if (plan.kind == PassKind::Interactive)
                governor_.record(plan.governorLevel, info.ms, info.tracedPixels);
        } else {
            completedPassGeneration_ = std::max(completedPassGeneration_, plan.generation);
            if (plan.kind == PassKind::Interactive) {
                if (plan.interleaved) interleaveParity_ ^= 1;
                governor_.record(plan.governorLevel, info.ms, info.tracedPixels);
            } else if (plan.kind == PassKind::Base && info.tracedPixels > 4096) {
                governor_.calibrate(info.ms / double(info.tracedPixels));
            }
        }
        stats_.lastPass = info;
        if (plan.kind == PassKind::Interactive) stats_.lastInteractivePass = info;
        ++stats_.passes;
        const bool complete = !info.cancelled && !pendingDoc_ && !releasePending_ &&
                              !pendingResize_ && !frame_.anyBelow(kFinal);
        const uint64_t gen = generation_.load();
        notifyObserver(lock, [&](SessionObserver& o) {
            o.passDone(info);
            if (complete && gen == plan.generation) o.frameComplete(gen);
        });
    }
}

void RenderSession::execute(Plan& plan, PassInfo& info) {
    const auto start = std::chrono::steady_clock::now();
    PassCounters counters;
    arenaExecute(*arena_, [&] {
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
