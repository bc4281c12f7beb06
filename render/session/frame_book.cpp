// Whole-frame bookkeeping: marking edits into the frame, deferred shadows, resizes, tears.
#include "session/frame_book.h"

namespace rs {

namespace {

/// More regions than this are merged into their bounding box (a long, winding drag).
constexpr std::size_t kMaxDeferredShadowRegions = 64;

}  // namespace

EditMarks FrameBook::markEdit(const SceneEdit& traced, const CompiledScene& snapshot,
                              const InteractionPolicy& policy, bool interacting, int width,
                              int height) {
    EditMarks marks;
    if (pendingResize_ || traced.everything || !policy.dirtyRegions)
        deferredShadowRegions_.clear();  // Every pixel is traced again anyway.
    if (pendingResize_) {
        marks.pixels = std::size_t(width) * std::size_t(height);
        return marks;
    }
    SceneEdit edit = traced;
    if (!policy.dirtyRegions) edit.everything = true;
    if (edit.everything) {
        // Every pixel: no mask to build or read, one pass over the states and flags.
        frame_.markAllStale();
        lastTouchedBlocks_.assign(std::size_t(frame_.blocksX()) * std::size_t(frame_.blocksY()), 1);
        marks.pixels = frame_.pixelCount();
        marks.blocksCounted = true;
        return marks;
    }
    // While dragging with shadows off or deferred, the moving object's shadow is not on
    // screen: its pixels are marked once, on release, instead of on every step.
    const bool deferShadows =
        interacting && !edit.everything &&
        (policy.shadows == MovingShadows::Off || policy.shadows == MovingShadows::Deferred);
    MarkStats markStats;
    marks.pixels =
        markDirtyPixels(edit, snapshot, frame_, dirtyMask_,
                        deferShadows ? MarkScope::WithoutShadows : MarkScope::All, &markStats);
    marks.blocksTested = markStats.blocksTested;
    marks.blocksGrown = markStats.blocksGrown;
    marks.blocksCounted = true;
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
    return marks;
}

void FrameBook::markReleasedShadows(const CompiledScene* snapshot, FrameLock& frameLock) {
    if (!deferredShadowRegions_.empty() && snapshot && !pendingResize_) {
        // The shadows the drag moved: pixels still showing an older shadow go back to stale.
        // Pixels traced during the drag already wait for refinement (and keep their deferred
        // records). No pass runs now, so no tile commits meanwhile.
        auto lock = frameLock.exclusive();
        SceneEdit edit;
        edit.regions.swap(deferredShadowRegions_);
        if (markDirtyPixels(edit, *snapshot, frame_, dirtyMask_, MarkScope::ShadowsOnly) > 0) {
            for (const int b : dirtyMask_.blocks)
                frame_.applyShadowMarks(std::size_t(b), dirtyMask_.pixels);
        }
    }
    deferredShadowRegions_.clear();
}

void FrameBook::resizeIfPending(int width, int height, FrameLock& frameLock) {
    if (!pendingResize_) return;
    auto lock = frameLock.exclusive();  // Readers may be copying the old frame.
    frame_.resize(width, height);
    pendingResize_ = false;
}

void FrameBook::dropFrameIfResizing(FrameLock& frameLock) {
    if (!pendingResize_) return;
    auto lock = frameLock.exclusive();
    frame_ = DeepFrame{};
}

void FrameBook::passEnded() {
    // Between passes the scheduler reads the frame under the session's mutex alone; every
    // tile of the pass has been announced to the observer by now.
    if (!frame_.anyBelow(kInteractive))
        wholeMark_.store(tears_.load(std::memory_order_relaxed), std::memory_order_release);
}

bool FrameBook::wholeUnseen(uint64_t& whole) const {
    whole = wholeMark_.load(std::memory_order_relaxed);
    return displayWaits_ && tears_.load() == whole && wholeShown_ < whole;
}

}  // namespace rs
