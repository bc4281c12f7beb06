// The session's pass scheduling: what the user is doing (dragging what, looking where), the
// policy and governor that decide each pass's quality, and the pass running now.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>

#include "session/frame/deep_frame.h"
#include "session/governor.h"
#include "session/interaction_policy.h"
#include "session/session_observer.h"
#include "snapshot/compiled_scene.h"

namespace rs {

struct PassPlan;

/// Guarded by the session's mutex.
class PassPlanner {
public:
    void setPolicy(const InteractionPolicy& policy) { policy_ = policy; }
    const InteractionPolicy& policy() const { return policy_; }

    /// The user started dragging `moving` (kNoObject: e.g. a camera drag).
    void beginInteraction(ObjectId moving) {
        interacting_ = true;
        moving_ = moving;
    }
    void endInteraction() {
        interacting_ = false;
        moving_ = kNoObject;
    }
    bool interacting() const { return interacting_; }
    /// Image point to render around first.
    void setFocus(float px, float py) {
        focusX_ = px;
        focusY_ = py;
    }

    /// The pixel state a pass should bring every pixel to now (scene traced with `snapshot`,
    /// null before the first document).
    uint8_t targetState(const CompiledScene* snapshot) const;
    /// Plans the next pass over `frame` at `generation` into `plan` (reset); false when no
    /// pass is needed. `lastUpdateMs` and `lastPlanMs` (the latest edit's and interactive
    /// plan's) come off the governor's budget.
    bool plan(PassPlan& plan, const DeepFrame& frame,
              const std::shared_ptr<const CompiledScene>& snapshot, uint64_t generation,
              double lastUpdateMs, double lastPlanMs) const;

    /// A pass of `plan` starts now / has ended.
    void passStarted(const PassPlan& plan, std::chrono::steady_clock::time_point now);
    void passEnded() { running_ = false; }
    bool running() const { return running_; }
    /// Whether an edit posted now lets the running pass finish first (RenderSession::update).
    bool letsThePassFinish(std::chrono::steady_clock::time_point now) const;
    /// Teaches the governor what the pass of `plan` cost; a finished interleaved pass flips
    /// the half traced next.
    void recordPass(const PassPlan& plan, const PassInfo& info);

    /// While moving, an applied edit is shown before the next is applied: set by an apply
    /// that marked pixels, cleared when a pass has been planned. Otherwise edits that take
    /// longer to apply than the mouse takes to send the next (a refit of 100,000 objects)
    /// left no time for a single pass.
    bool passOwed() const { return passOwed_; }
    void setPassOwed(bool owed) { passOwed_ = owed; }

private:
    bool fullQualityWhileMoving(const CompiledScene* snapshot) const;
    /// The interactive pass's quality and scene (plan.kind is Interactive).
    void planInteractive(PassPlan& plan, const std::shared_ptr<const CompiledScene>& snapshot,
                         std::size_t stale, double lastUpdateMs, double lastPlanMs) const;
    /// Tiles near the focus first (plan.tiles in row-major order before).
    void orderByFocus(PassPlan& plan, const DeepFrame& frame) const;

    InteractionPolicy policy_;
    Governor governor_;
    bool interacting_ = false;
    ObjectId moving_ = kNoObject;
    float focusX_ = -1.0f, focusY_ = -1.0f;
    int interleaveParity_ = 0;
    bool passOwed_ = false;
    bool running_ = false;
    std::chrono::steady_clock::time_point passStart_;  ///< Of the pass running (running_).
    PassKind passKind_ = PassKind::Base;
    int passLevel_ = -1;  ///< Its governor level (-1: not governed).
};

}  // namespace rs
