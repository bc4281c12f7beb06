// The session's documents: what the UI posts (kept until the scheduler applies it) and what
// was applied last, with the generations that say how far applying has come.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>

#include "scene/document.h"
#include "session/scene_update.h"
#include "snapshot/compiled_scene.h"

namespace rs {

/// Diffs two documents and builds the snapshot of the second (updateScene's signature).
using SceneUpdater = std::function<SceneUpdate(
    const SceneDocument& before, const std::shared_ptr<const CompiledScene>& beforeSnapshot,
    const SceneDocument& after, EngineKind engine)>;

/// A posted document taken out of the inbox to be applied, with what applying it needs.
struct DocumentToApply {
    SceneDocument doc;
    uint64_t generation = 0;
    std::shared_ptr<const CompiledScene> before;  ///< The applied snapshot (null: none yet).
    EngineKind engine = EngineKind::Embree;
    SceneUpdater updater;
};

/// Guarded by the session's mutex, except where a member says otherwise. The applied
/// document and snapshot are written only by the scheduler thread.
class DocumentInbox {
public:
    /// Keeps `doc` as the one to apply next (one posted earlier and not applied is dropped:
    /// the latest wins) and gives it the generation `generation`.
    void post(SceneDocument&& doc, uint64_t generation, std::chrono::steady_clock::time_point now) {
        pending_ = std::move(doc);
        pendingGeneration_ = generation;
        editTime_ = now;
    }
    bool hasPending() const { return pending_.has_value(); }
    /// Takes the posted document out to be applied (hasPending()): applying() until
    /// finishApplying().
    DocumentToApply takePending() {
        DocumentToApply job{std::move(*pending_), pendingGeneration_,
                            hasApplied_ ? snapshot_ : nullptr, engine_.load(),
                            updater_ ? updater_ : SceneUpdater(updateScene)};
        pending_.reset();
        applying_ = true;
        return job;
    }
    bool applying() const { return applying_; }
    /// The document taken out failed to apply: the one applied before stays.
    void failed(uint64_t generation) {
        applying_ = false;
        failedGeneration_ = std::max(failedGeneration_, generation);
    }
    /// Applying it is over (it is applied next, or failed).
    void finishApplying() { applying_ = false; }
    /// `doc`, of `generation`, is the document applied now, traced with `snapshot`.
    void applied(SceneDocument&& doc, std::shared_ptr<const CompiledScene> snapshot,
                 uint64_t generation) {
        doc_ = std::move(doc);
        hasApplied_ = true;
        snapshot_ = std::move(snapshot);
        appliedGeneration_ = generation;
    }

    /// The document applied last; the scheduler thread reads it without the lock.
    const SceneDocument& doc() const { return doc_; }
    bool hasApplied() const { return hasApplied_; }
    const std::shared_ptr<const CompiledScene>& snapshot() const { return snapshot_; }
    uint64_t appliedGeneration() const { return appliedGeneration_; }
    uint64_t failedGeneration() const { return failedGeneration_; }
    std::chrono::steady_clock::time_point editTime() const { return editTime_; }

    void setUpdater(SceneUpdater updater) { updater_ = std::move(updater); }
    /// Any thread, without the lock.
    void setEngine(EngineKind engine) { engine_.store(engine); }
    EngineKind engine() const { return engine_.load(); }

    /// endInteraction left shadows to mark (the scheduler marks them).
    void requestRelease() { releasePending_ = true; }
    bool releasePending() const { return releasePending_; }
    void releaseHandled() { releasePending_ = false; }

    /// The generation update() gave last; any thread, without the lock.
    std::atomic<uint64_t>& postedGeneration() { return postedGeneration_; }
    const std::atomic<uint64_t>& postedGeneration() const { return postedGeneration_; }

private:
    std::optional<SceneDocument> pending_;  ///< Posted, not yet applied (the latest wins).
    uint64_t pendingGeneration_ = 0;        ///< Generation update() gave pending_.
    std::atomic<uint64_t> postedGeneration_{0};
    std::chrono::steady_clock::time_point editTime_;  ///< When the latest was posted.
    bool applying_ = false;                           ///< The scheduler is applying a document.
    uint64_t appliedGeneration_ = 0;                  ///< Generation of the document applied last.
    uint64_t failedGeneration_ = 0;  ///< Generation whose document failed to apply.
    bool releasePending_ = false;
    SceneUpdater updater_;
    std::atomic<EngineKind> engine_{EngineKind::Embree};
    SceneDocument doc_;  ///< Applied last.
    bool hasApplied_ = false;
    std::shared_ptr<const CompiledScene> snapshot_;  ///< Of doc_.
};

}  // namespace rs
