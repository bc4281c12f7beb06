// The interactive render session: owns the deep frame and keeps it current while the user edits.
#pragma once

#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <thread>
#include <vector>

#include "core/thread_priority.h"
#include "scene/document.h"
#include "session/dirty_region.h"
#include "session/frame/deep_frame.h"
#include "session/frame_lock.h"
#include "session/governor.h"
#include "session/interaction_policy.h"
#include "session/scene_update.h"
#include "session/session_observer.h"
#include "snapshot/compiled_scene.h"

namespace rs {

struct PassCounters;

/// Counters for the status bar and benchmarks.
struct SessionStats {
    PassInfo lastPass;
    PassInfo lastInteractivePass;
    double lastCancelLatencyMs = 0.0;  ///< Edit to all workers off stale work.
    uint64_t passes = 0;
    std::size_t lastDirtyPixels = 0;  ///< Pixels the latest edit marked.
    bool lastEditRefitted = false;    ///< The latest edit refitted the BVH.
    double lastUpdateMs = 0.0;        ///< Diff, snapshot and dirty marking of the latest edit.
    double lastMarkMs = 0.0;          ///< Of which marking (and applying the marks).
    uint64_t postedUpdates = 0;       ///< update() calls.
    uint64_t appliedUpdates = 0;      ///< Documents applied (posted ones coalesce).
    /// How much of the frame the latest edit's marking looked at: blocks tested against their
    /// summaries, and blocks visited to grow the marks (both follow the edit, not the frame).
    std::size_t lastMarkBlocksTested = 0;
    std::size_t lastMarkBlocksGrown = 0;
    std::size_t lastPassTiles = 0;  ///< Tiles the latest pass was planned over.
};

/// Diffs two documents and builds the snapshot of the second (updateScene's signature).
using SceneUpdater = std::function<SceneUpdate(
    const SceneDocument& before, const std::shared_ptr<const CompiledScene>& beforeSnapshot,
    const SceneDocument& after, EngineKind engine)>;

/// Schedules tiles on a oneTBB arena from a scheduler thread. Every edit bumps a generation;
/// workers drop stale tiles within one row, and a tile of an older generation is never written.
/// Edits are applied on the scheduler thread: update() only posts the document.
class RenderSession {
public:
    /// `threads` = 0: all cores.
    explicit RenderSession(int threads = 0);
    ~RenderSession();
    RenderSession(const RenderSession&) = delete;
    RenderSession& operator=(const RenderSession&) = delete;

    /// Sets the observer (may be null). Waits until no pass runs and no call to the old
    /// observer is under way, so the old one may be destroyed when this returns; meant for
    /// before the first update or while idle (it waits for the session to be between passes).
    /// Not from inside an observer callback.
    void setObserver(SessionObserver* observer);
    void setThreads(int threads);
    void setPolicy(const InteractionPolicy& policy);
    /// The ray engine later updates build snapshots with; the next update rebuilds with it.
    void setEngine(EngineKind engine);
    EngineKind engine() const;
    InteractionPolicy policy() const;

    /// Posts `doc` and returns its generation at once: running tiles stop (while the user
    /// drags or orbits, a governed interactive pass runs on to its end first unless it is
    /// long over its time, so that a whole frame is shown), and the scheduler
    /// thread diffs it against the document applied last, refits or rebuilds the snapshot and
    /// marks the pixels the edit can change. Documents posted while one is being applied
    /// coalesce: only the latest is applied. Failures (a bad scene, bad_alloc) go to the
    /// observer's error(); the session keeps the document applied last.
    uint64_t update(const SceneDocument& doc);
    /// Waits until the document of `generation` (or a later one) is applied: snapshot() and
    /// stats() describe it. False on timeout or when applying it failed.
    bool waitForUpdate(uint64_t generation, std::chrono::milliseconds timeout);
    /// Replaces updateScene for the documents applied from now on (tests slow it down).
    void setSceneUpdater(SceneUpdater updater);
    /// The user started dragging `moving` (kNoObject: e.g. a camera drag).
    void beginInteraction(ObjectId moving);
    /// The user let go: refine to full quality (the moved shadows are marked on the
    /// scheduler thread).
    void endInteraction();
    /// Image point to render around first (the cursor).
    void setFocus(float px, float py);

    /// Waits until a pass of `generation` (or later) has completed uncancelled.
    bool waitForPass(uint64_t generation, std::chrono::milliseconds timeout,
                     PassInfo* info = nullptr);
    /// Waits until every pixel is final for the current generation and the observer's calls
    /// for it (passDone, frameComplete) have returned.
    bool waitUntilComplete(std::chrono::milliseconds timeout);

    /// Runs `f(frame, snapshot)` with tile commits held off; keep it short (copy what you need).
    template <class F>
    void withFrame(F&& f) const {
        auto lock = frameLock_.read();
        f(frame_, snapshot_);
    }
    /// withFrame if the frame can be had within kReaderBudget (tile commits that have not
    /// begun hold off meanwhile), else false and `f` does not run: the display comes back
    /// later instead of waiting on the GUI thread behind an edit's marking.
    template <class F>
    bool tryWithFrame(F&& f) const {
        auto lock = frameLock_.tryExclusive(kReaderBudget);
        if (!lock.owns_lock()) return false;
        f(frame_, snapshot_);
        return true;
    }
    /// How long tryWithFrame may wait: a few tile commits, far below a GUI stall.
    static constexpr std::chrono::microseconds kReaderBudget{1500};
    SessionStats stats() const;
    /// The generation update() gave last (the one being traced may be older: see update()).
    uint64_t generation() const { return postedGeneration_.load(); }
    /// Whole frames, for the display: a frame is whole when all its pixels show one
    /// document. Edits only mark pixels stale (their colours stay), so a frame is torn from
    /// the start of a pass that re-traces stale pixels (or a resize) until a pass leaves no
    /// pixel stale, which makes it whole at the count of such tears. Read wholeMark()
    /// before taking the tiles announced so far (every tile of that pass has been announced
    /// by then), then, inside withFrame or tryWithFrame, wholeSince(mark): not torn since,
    /// so those tiles' pixels complete the picture of one document.
    uint64_t wholeMark() const { return wholeMark_.load(std::memory_order_acquire); }
    bool wholeSince(uint64_t mark) const {
        return tears_.load(std::memory_order_acquire) == mark &&
               wholeMark_.load(std::memory_order_acquire) == mark;
    }
    /// The display showed the whole frame of `mark`. With setDisplayWaits(true) and the
    /// policy's wholeFramesWhileMoving, while the user drags or orbits, a pass that would tear
    /// a whole frame the display has not taken yet waits for it (up to kDisplayWait): else
    /// the next edit's pass, which starts at once, tears every frame before the display, a
    /// queued event away, can copy it.
    void wholeFrameShown(uint64_t mark);
    void setDisplayWaits(bool on);
    static constexpr std::chrono::milliseconds kDisplayWait{12};
    std::shared_ptr<const CompiledScene> snapshot() const;

    /// Internal: a planned pass and one of its tiles (session_plan.h).
    struct Plan;
    struct TileJob;

private:
    void run();
    void runPasses(std::unique_lock<std::mutex>& lock);
    void applyPendingLocked(std::unique_lock<std::mutex>& lock);
    std::size_t markEditLocked(const SceneEdit& edit);
    void markReleasedShadowsLocked();
    bool hasWorkLocked() const;
    bool planLocked(Plan& plan);
    void execute(Plan& plan, PassInfo& info);
    void processTile(const Plan& plan, const TileJob& job, PassCounters& counters);
    bool fullQualityWhileMoving() const;
    uint8_t targetStateLocked() const;
    /// Whether an edit posted now lets the running pass finish first (see update()).
    bool letsThePassFinishLocked(std::chrono::steady_clock::time_point now) const;
    /// Tiles of another picture are about to be written: the frame is no longer whole.
    void tornLocked() { tears_.fetch_add(1, std::memory_order_release); }

    mutable std::mutex mutex_;  ///< Scheduler state; taken before frameLock_.
    /// Frame pixels. Tiles commit disjoint pixels under a shared lock; edits (generation bump
    /// and dirty marking) and readers take it exclusively. Between passes no tile writes, so
    /// the scheduler reads the frame under mutex_ alone.
    mutable FrameLock frameLock_;
    std::condition_variable wake_;
    std::condition_variable done_;
    /// The generation being traced: tiles of another stop and are not written.
    std::atomic<uint64_t> generation_{0};
    std::atomic<uint64_t> postedGeneration_{0};  ///< The last update()'s (>= generation_).
    std::atomic<uint64_t> tears_{0};             ///< See wholeMark().
    std::atomic<uint64_t> wholeMark_{0};
    uint64_t wholeShown_ = 0;  ///< wholeFrameShown's latest mark.
    bool displayWaits_ = false;

    /// The document applied last; only the scheduler thread writes it (under mutex_) and
    /// reads it without the lock while applying the next.
    SceneDocument doc_;
    std::optional<SceneDocument> pendingDoc_;  ///< Posted, not yet applied (the latest wins).
    uint64_t pendingGeneration_ = 0;           ///< Generation update() gave pendingDoc_.
    bool applying_ = false;                    ///< The scheduler is applying a document.
    uint64_t appliedGeneration_ = 0;           ///< Generation of the document applied last.
    uint64_t failedGeneration_ = 0;            ///< Generation whose document failed to apply.
    bool releasePending_ = false;              ///< endInteraction left shadows to mark.
    SceneUpdater updater_;
    std::shared_ptr<const CompiledScene> snapshot_;
    DeepFrame frame_;
    DirtyMask dirtyMask_;                     ///< The latest marking (kept: see DirtyMask).
    std::vector<uint8_t> lastTouchedBlocks_;  ///< Blocks whose overlay flags may be set.
    /// Regions of this interaction's edits whose shadow effects were left unmarked
    /// (MarkScope::WithoutShadows); endInteraction marks them.
    std::vector<Aabb> deferredShadowRegions_;
    bool pendingResize_ = false;
    bool hasDocument_ = false;

    InteractionPolicy policy_;
    Governor governor_;
    bool interacting_ = false;
    /// While moving, an applied edit is shown before the next is applied: set by an apply
    /// that marked pixels, cleared when a pass has run. Otherwise edits that take longer to
    /// apply than the mouse takes to send the next (a refit of 100,000 objects) left no time
    /// for a single pass.
    bool passOwed_ = false;
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
    std::chrono::steady_clock::time_point passStart_;  ///< Of the pass running (running_).
    PassKind passKind_ = PassKind::Base;
    int passLevel_ = -1;  ///< Its governor level (-1: not governed).
    SessionStats stats_;
    SessionObserver* observer_ = nullptr;
    /// Calls to the observer under way outside mutex_ from the scheduler or update(): what
    /// waitUntilComplete() and setObserver() wait for. Workers' tileDone calls are inside a
    /// pass (running_).
    int notifying_ = 0;
    /// Calls `call(observer)` with mutex_ (held by `lock`) released, counted in notifying_;
    /// waiters are woken before and after it.
    template <class Call>
    void notifyObserver(std::unique_lock<std::mutex>& lock, Call&& call);

    std::unique_ptr<BackgroundArena> arena_;  ///< Its tracers run below the GUI thread.
    /// The arena's size for a thread count (0: the machine's).
    static int arenaSize(int threads);
    bool stop_ = false;
    std::thread scheduler_;
};

}  // namespace rs
