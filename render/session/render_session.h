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

#include "scene/document.h"
#include "session/document_inbox.h"
#include "session/frame/deep_frame.h"
#include "session/frame_book.h"
#include "session/frame_lock.h"
#include "session/interaction_policy.h"
#include "session/pass_planner.h"
#include "session/scene_update.h"
#include "session/session_observer.h"
#include "session/tile_arena.h"
#include "snapshot/compiled_scene.h"

namespace rs {

struct PassCounters;
struct PassPlan;
struct TileJob;

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

/// Schedules tiles on a oneTBB arena from a scheduler thread. Every edit bumps a generation;
/// workers drop stale tiles within one row, and a tile of an older generation is never written.
/// Edits are applied on the scheduler thread: update() only posts the document.
///
/// A facade over its parts, all guarded by its mutex: the DocumentInbox (documents posted and
/// applied), the PassPlanner (what the user does, policy, governor, the pass running), the
/// FrameBook (the deep frame, its marks and whole-frame bookkeeping) and the TileArena.
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
        f(book_.frame(), inbox_.snapshot());
    }
    /// withFrame if the frame can be had within kReaderBudget (tile commits that have not
    /// begun hold off meanwhile), else false and `f` does not run: the display comes back
    /// later instead of waiting on the GUI thread behind an edit's marking.
    template <class F>
    bool tryWithFrame(F&& f) const {
        auto lock = frameLock_.tryExclusive(kReaderBudget);
        if (!lock.owns_lock()) return false;
        f(book_.frame(), inbox_.snapshot());
        return true;
    }
    /// How long tryWithFrame may wait: a few tile commits, far below a GUI stall.
    static constexpr std::chrono::microseconds kReaderBudget{1500};
    SessionStats stats() const;
    /// The generation update() gave last (the one being traced may be older: see update()).
    uint64_t generation() const { return inbox_.postedGeneration().load(); }
    /// Whole frames, for the display: a frame is whole when all its pixels show one
    /// document. Edits only mark pixels stale (their colours stay), so a frame is torn from
    /// the start of a pass that re-traces stale pixels (or a resize) until a pass leaves no
    /// pixel stale, which makes it whole at the count of such tears. Read wholeMark()
    /// before taking the tiles announced so far (every tile of that pass has been announced
    /// by then), then, inside withFrame or tryWithFrame, wholeSince(mark): not torn since,
    /// so those tiles' pixels complete the picture of one document.
    uint64_t wholeMark() const { return book_.wholeMark(); }
    bool wholeSince(uint64_t mark) const { return book_.wholeSince(mark); }
    /// The display showed the whole frame of `mark`. With setDisplayWaits(true) and the
    /// policy's wholeFramesWhileMoving, while the user drags or orbits, a pass that would tear
    /// a whole frame the display has not taken yet waits for it (up to kDisplayWait): else
    /// the next edit's pass, which starts at once, tears every frame before the display, a
    /// queued event away, can copy it.
    void wholeFrameShown(uint64_t mark);
    void setDisplayWaits(bool on);
    static constexpr std::chrono::milliseconds kDisplayWait{12};
    std::shared_ptr<const CompiledScene> snapshot() const;

private:
    void run();
    void runPasses(std::unique_lock<std::mutex>& lock);
    void applyPendingLocked(std::unique_lock<std::mutex>& lock);
    /// Runs the document's updater with the mutex (held by `lock`) released, so that
    /// update() may post the next meanwhile, and takes it again; null when it threw
    /// (`failure` says why).
    std::optional<SceneUpdate> buildUnlocked(std::unique_lock<std::mutex>& lock,
                                             const DocumentToApply& job,
                                             std::exception_ptr& failure);
    /// Makes the built update the applied document and marks what it changed.
    void commitUpdateLocked(DocumentToApply&& job, const SceneUpdate& u,
                            std::chrono::steady_clock::time_point start);
    void markReleasedShadowsLocked();
    bool hasWorkLocked() const;
    uint8_t targetStateLocked() const { return planner_.targetState(inbox_.snapshot().get()); }
    /// Plans the next pass into `plan`, resizing the frame first if the document asks;
    /// false when there is nothing to trace.
    bool planLocked(PassPlan& plan);
    /// With the display waiting for whole frames while the user moves: waits (briefly) for
    /// it to take the whole frame before a pass that re-traces stale pixels tears it.
    /// False when the session stops meanwhile.
    bool tearLocked(std::unique_lock<std::mutex>& lock, const PassPlan& plan);
    /// Runs the pass with the mutex released; then records what it did and tells the observer.
    void runPassUnlocked(std::unique_lock<std::mutex>& lock, PassPlan& plan, double planMs);
    void passDoneLocked(std::unique_lock<std::mutex>& lock, const PassPlan& plan,
                        const PassInfo& info);
    void execute(PassPlan& plan, PassInfo& info);
    void processTile(const PassPlan& plan, const TileJob& job, PassCounters& counters);

    mutable std::mutex mutex_;  ///< Guards the parts below; taken before frameLock_.
    /// Frame pixels. Tiles commit disjoint pixels under a shared lock; edits (generation bump
    /// and dirty marking) and readers take it exclusively. Between passes no tile writes, so
    /// the scheduler reads the frame under mutex_ alone.
    mutable FrameLock frameLock_;
    std::condition_variable wake_;
    std::condition_variable done_;
    /// The generation being traced: tiles of another stop and are not written.
    std::atomic<uint64_t> generation_{0};

    DocumentInbox inbox_;
    PassPlanner planner_;
    FrameBook book_;
    TileArena arena_;
    SessionStats stats_;

    SessionObserver* observer_ = nullptr;
    /// Calls to the observer under way outside mutex_ from the scheduler or update(): what
    /// waitUntilComplete() and setObserver() wait for. Workers' tileDone calls are inside a
    /// pass (planner_.running()).
    int notifying_ = 0;
    /// Calls `call(observer)` with mutex_ (held by `lock`) released, counted in notifying_;
    /// waiters are woken before and after it.
    template <class Call>
    void notifyObserver(std::unique_lock<std::mutex>& lock, Call&& call);

    bool stop_ = false;
    std::thread scheduler_;
};

}  // namespace rs
