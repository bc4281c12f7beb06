// The interactive render session: owns the deep frame and keeps it current while the user edits.
#pragma once

#include "scene/document.h"
#include "session/deep_frame.h"
#include "session/governor.h"
#include "session/interaction_policy.h"
#include "session/scene_update.h"
#include "session/session_observer.h"
#include "snapshot/compiled_scene.h"

#include <atomic>
#include <chrono>
#include <tbb/task_arena.h>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <thread>
#include <vector>

namespace rs {

struct PassCounters;

/// Counters for the status bar and benchmarks.
struct SessionStats {
    PassInfo lastPass;
    PassInfo lastInteractivePass;
    double lastCancelLatencyMs = 0.0;  ///< Edit to all workers off stale work.
    uint64_t passes = 0;
    std::size_t lastDirtyPixels = 0;   ///< Pixels the latest edit marked.
    bool lastEditRefitted = false;     ///< The latest edit refitted the BVH.
    double lastUpdateMs = 0.0;         ///< Diff, snapshot and dirty marking of the latest edit.
};

/// Schedules tiles on a oneTBB arena from a scheduler thread. Every edit bumps a generation;
/// workers drop stale tiles within one row, and a tile of an older generation is never written.
class RenderSession {
public:
    /// `threads` = 0: all cores.
    explicit RenderSession(int threads = 0);
    ~RenderSession();
    RenderSession(const RenderSession&) = delete;
    RenderSession& operator=(const RenderSession&) = delete;

    /// Sets the observer (may be null). Call before the first update or while idle.
    void setObserver(SessionObserver* observer);
    void setThreads(int threads);
    void setPolicy(const InteractionPolicy& policy);
    /// The ray engine later updates build snapshots with; the next update rebuilds with it.
    void setEngine(EngineKind engine);
    EngineKind engine() const;
    InteractionPolicy policy() const;

    /// Shows `doc`: diffs it against the previous document, refits or rebuilds the snapshot,
    /// marks the pixels the edit can change and restarts work. Returns the new generation.
    /// An exception (bad_alloc of a huge snapshot, ...) is reported through the observer's
    /// error() on the calling thread; the session keeps what it showed before.
    uint64_t update(const SceneDocument& doc);
    /// The user started dragging `moving` (kNoObject: e.g. a camera drag).
    void beginInteraction(ObjectId moving);
    /// The user let go: refine to full quality.
    void endInteraction();
    /// Image point to render around first (the cursor).
    void setFocus(float px, float py);

    /// Waits until a pass of `generation` (or later) has completed uncancelled.
    bool waitForPass(uint64_t generation, std::chrono::milliseconds timeout,
                     PassInfo* info = nullptr);
    /// Waits until every pixel is final for the current generation.
    bool waitUntilComplete(std::chrono::milliseconds timeout);

    /// Runs `f(frame, snapshot)` with tile commits held off; keep it short (copy what you need).
    template <class F>
    void withFrame(F&& f) const {
        std::unique_lock lock(frameMutex_);
        f(frame_, snapshot_);
    }
    SessionStats stats() const;
    uint64_t generation() const { return generation_.load(); }
    std::shared_ptr<const CompiledScene> snapshot() const;

    /// Internal: a planned pass and one of its tiles (session_plan.h).
    struct Plan;
    struct TileJob;

private:
    uint64_t applyUpdate(const SceneDocument& doc);  ///< update() without its guard.
    void run();
    void runPasses(std::unique_lock<std::mutex>& lock);
    bool hasWorkLocked() const;
    bool planLocked(Plan& plan);
    void execute(Plan& plan, PassInfo& info);
    void processTile(const Plan& plan, const TileJob& job, PassCounters& counters);
    bool fullQualityWhileMoving() const;
    uint8_t targetStateLocked() const;

    std::mutex updateMutex_;  ///< Serialises update(); held without the frame lock.
    mutable std::mutex mutex_;  ///< Scheduler state; taken before frameMutex_.
    /// Frame pixels. Tiles commit disjoint pixels under a shared lock; edits (generation bump
    /// and dirty marking) and readers take it exclusively. Between passes no tile writes, so
    /// the scheduler reads the frame under mutex_ alone.
    mutable std::shared_mutex frameMutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    std::atomic<uint64_t> generation_{0};

    SceneDocument doc_;
    std::shared_ptr<const CompiledScene> snapshot_;
    DeepFrame frame_;
    std::vector<uint8_t> dirtyMask_;
    std::vector<uint8_t> touchedBlocks_;      ///< Blocks the latest edit marked (scratch).
    std::vector<uint8_t> lastTouchedBlocks_;  ///< Blocks whose overlay flags may be set.
    /// Regions of this interaction's edits whose shadow effects were left unmarked
    /// (MarkScope::WithoutShadows); endInteraction marks them.
    std::vector<Aabb> deferredShadowRegions_;
    bool pendingResize_ = false;
    bool hasDocument_ = false;

    InteractionPolicy policy_;
    Governor governor_;
    bool interacting_ = false;
    ObjectId moving_ = kNoObject;
    float focusX_ = -1.0f, focusY_ = -1.0f;
    int interleaveParity_ = 0;
    int threads_ = 0;
    std::atomic<EngineKind> engine_{EngineKind::Embree};
    bool threadsChanged_ = false;

    uint64_t completedPassGeneration_ = 0;
    uint64_t completeGeneration_ = 0;
    bool completeValid_ = false;
    bool running_ = false;
    std::chrono::steady_clock::time_point editTime_;
    SessionStats stats_;
    SessionObserver* observer_ = nullptr;

    std::unique_ptr<tbb::task_arena> arena_;
    bool stop_ = false;
    std::thread scheduler_;
};

}  // namespace rs
