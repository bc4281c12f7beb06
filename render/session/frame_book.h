// The session's whole-frame bookkeeping: the deep frame, which of its pixels an edit marked,
// the shadows a drag left to mark, and whether the frame shows one document (whole frames).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <vector>

#include "session/dirty_region.h"
#include "session/frame/deep_frame.h"
#include "session/frame_lock.h"
#include "session/interaction_policy.h"
#include "snapshot/compiled_scene.h"

namespace rs {

/// What marking an edit did: the pixels marked and how much of the frame it looked at.
struct EditMarks {
    std::size_t pixels = 0;
    std::size_t blocksTested = 0;
    std::size_t blocksGrown = 0;
    bool blocksCounted = false;  ///< The block counts describe this edit (not a resize's).
};

/// Guarded by the session's mutex; the frame's pixels also by its FrameLock (see
/// RenderSession). wholeMark() and wholeSince() may be read from any thread.
class FrameBook {
public:
    DeepFrame& frame() { return frame_; }
    const DeepFrame& frame() const { return frame_; }

    /// Marks the pixels `edit` can change (every pixel when a resize is pending: the frame is
    /// traced again at its new sides, `width` x `height`). With `interacting` and the policy
    /// deferring shadows, the edit's shadow effects are left for markReleasedShadows().
    /// Under the frame lock.
    EditMarks markEdit(const SceneEdit& edit, const CompiledScene& snapshot,
                       const InteractionPolicy& policy, bool interacting, int width, int height);
    /// The user let go: marks the shadows the drag moved (taking `frameLock` when there are
    /// any), and forgets them.
    void markReleasedShadows(const CompiledScene* snapshot, FrameLock& frameLock);

    /// The applied document's sides differ from the frame's: the next pass resizes it.
    void requestResize() { pendingResize_ = true; }
    bool resizePending() const { return pendingResize_; }
    /// Resizes the frame when requestResize() asked for it (taking `frameLock`).
    void resizeIfPending(int width, int height, FrameLock& frameLock);
    /// Rendering failed: a resize under way may have left sides and buffers disagreeing, so
    /// readers get an empty frame instead (the next update sizes it again). Under the lock.
    void dropFrameIfResizing(FrameLock& frameLock);

    /// Tiles of another picture are about to be written: the frame is no longer whole.
    void torn() { tears_.fetch_add(1, std::memory_order_release); }
    /// A pass ended; if it left no pixel stale the frame is whole again.
    void passEnded();
    uint64_t wholeMark() const { return wholeMark_.load(std::memory_order_acquire); }
    bool wholeSince(uint64_t mark) const {
        return tears_.load(std::memory_order_acquire) == mark &&
               wholeMark_.load(std::memory_order_acquire) == mark;
    }
    /// With display waits on: whether the frame is whole and the display has not taken it
    /// yet; `whole` is its mark.
    bool wholeUnseen(uint64_t& whole) const;
    void shown(uint64_t mark) { wholeShown_ = std::max(wholeShown_, mark); }
    uint64_t wholeShown() const { return wholeShown_; }
    void setDisplayWaits(bool on) { displayWaits_ = on; }
    bool displayWaits() const { return displayWaits_; }

    /// A pass of `generation` completed (or nothing was left to trace for it).
    void completed(uint64_t generation) {
        completedPassGeneration_ = std::max(completedPassGeneration_, generation);
    }
    uint64_t completedGeneration() const { return completedPassGeneration_; }

private:
    DeepFrame frame_;
    DirtyMask dirtyMask_;                     ///< The latest marking (kept: see DirtyMask).
    std::vector<uint8_t> lastTouchedBlocks_;  ///< Blocks whose overlay flags may be set.
    /// Regions of this interaction's edits whose shadow effects were left unmarked
    /// (MarkScope::WithoutShadows); markReleasedShadows marks them.
    std::vector<Aabb> deferredShadowRegions_;
    bool pendingResize_ = false;
    std::atomic<uint64_t> tears_{0};  ///< See RenderSession::wholeMark().
    std::atomic<uint64_t> wholeMark_{0};
    uint64_t wholeShown_ = 0;  ///< wholeFrameShown's latest mark.
    bool displayWaits_ = false;
    uint64_t completedPassGeneration_ = 0;
};

}  // namespace rs
