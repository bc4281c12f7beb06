// Pass planning: which kind of pass comes next, at which quality, over which tiles, in what order.
#include "session/pass_planner.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <tuple>

#include "integrator/renderer.h"
#include "session/session_plan.h"

namespace rs {

namespace {

/// Tiles of a focus-ordered pass go in groups this many tiles wide and high (orderByFocus).
constexpr int kFocusGroupX = 8, kFocusGroupY = 2;
/// A governed interactive pass that has run this many times the governor's target is cut
/// by the next edit: the edits that wait for it should not wait for ever (a pass the
/// governor predicted far too cheap). Cut at 1.5 or 3 targets, a loaded machine's orbit
/// passes (40-90 ms at a 33 ms target) were cut as before and showed 2-18 whole frames a
/// second against 10-16 never cut (measure-designer, load 5).
constexpr double kHoldPassForTargets = 6.0;

/// Every field of `o` that shapes a pixel's ray tree: all of them but the shadows (what
/// the lights add at the tree's shading points). Naming each field in one structured
/// binding, this stops compiling when TraceOptions gains one, so a new field cannot be
/// forgotten here.
auto treeFields(const TraceOptions& o) {
    const auto& [maxDepth, shadows, reflectionAsDiffuse, refractionAsDiffuse, refractionExempt,
                 minWeight] = o;
    (void)shadows;
    return std::tie(maxDepth, reflectionAsDiffuse, refractionAsDiffuse, refractionExempt,
                    minWeight);
}

/// Whether options `a` trace the same ray tree as `b` (they may differ in shadows alone).
bool sameTree(const TraceOptions& a, const TraceOptions& b) {
    return treeFields(a) == treeFields(b);
}

/// Whether the tile has a pixel the pass would work on, from the tile's state counts (an
/// interleaved pass also needs a stale pixel of this frame's parity: those tiles are scanned).
bool tileHasCandidate(const PassPlan& plan, const DeepFrame& frame, int tile, const PixelRect& r) {
    const auto& counts = frame.tileStates()[std::size_t(tile)];
    switch (plan.kind) {
        case PassKind::Interactive:
            if (counts[kStale] == 0) return false;
            if (!plan.interleaved) return true;
            for (int y = r.y0; y < r.y1; ++y) {
                const uint8_t* row = frame.state().data() + frame.index(r.x0, y);
                for (int x = r.x0; x < r.x1; ++x) {
                    const int bx = x / plan.step, by = y / plan.step;
                    if (row[x - r.x0] == kStale && ((bx + by + plan.parity) & 1) == 0) return true;
                }
            }
            return false;
        case PassKind::Base:
            return counts[kStale] + counts[kInteractive] > 0;
        case PassKind::Supersample:
            return counts[kBase] > 0;
    }
    return false;
}

/// The tiles of `frame` with a pixel the pass would work on, in row-major order.
void listTiles(PassPlan& plan, const DeepFrame& frame) {
    for (int ty = 0; ty < frame.tilesY(); ++ty) {
        for (int tx = 0; tx < frame.tilesX(); ++tx) {
            TileJob job;
            job.tile = ty * frame.tilesX() + tx;
            job.rect = {tx * frame.tileSize(), ty * frame.tileSize(),
                        std::min(frame.width(), (tx + 1) * frame.tileSize()),
                        std::min(frame.height(), (ty + 1) * frame.tileSize())};
            if (tileHasCandidate(plan, frame, job.tile, job.rect)) plan.tiles.push_back(job);
        }
    }
}

}  // namespace

bool PassPlanner::fullQualityWhileMoving(const CompiledScene* snapshot) const {
    const InteractionPolicy& p = policy_;
    return p.resolution == MovingResolution::Full && !p.interleaved && !p.boxProxy &&
           p.refraction == RefractionMode::Full && p.reflection == ReflectionMode::Full &&
           (p.maxDepthWhileMoving < 0 ||
            (snapshot && p.maxDepthWhileMoving >= snapshot->settings().maxDepth)) &&
           p.shadows == MovingShadows::Full && p.governorTargetMs <= 0.0;
}

uint8_t PassPlanner::targetState(const CompiledScene* snapshot) const {
    if (!interacting_) return kFinal;
    if (!fullQualityWhileMoving(snapshot)) return kInteractive;
    return policy_.supersampleWhileMoving ? kFinal : kBase;
}

bool PassPlanner::letsThePassFinish(std::chrono::steady_clock::time_point now) const {
    if (!policy_.wholeFramesWhileMoving || !interacting_ || !running_ ||
        passKind_ != PassKind::Interactive || passLevel_ < 0)
        return false;
    const double ran = std::chrono::duration<double, std::milli>(now - passStart_).count();
    return ran < kHoldPassForTargets * policy_.governorTargetMs;
}

void PassPlanner::passStarted(const PassPlan& plan, std::chrono::steady_clock::time_point now) {
    running_ = true;
    passStart_ = now;
    passKind_ = plan.kind;
    passLevel_ = plan.governorLevel;
}

void PassPlanner::recordPass(const PassPlan& plan, const PassInfo& info) {
    if (info.cancelled) {
        // What the pass traced before the edit cut it is what this level costs now: a
        // governor fed finished passes alone never learns what an orbit step costs.
        if (plan.kind == PassKind::Interactive)
            governor_.record(plan.governorLevel, info.ms, info.tracedPixels);
    } else if (plan.kind == PassKind::Interactive) {
        if (plan.interleaved) interleaveParity_ ^= 1;
        governor_.record(plan.governorLevel, info.ms, info.tracedPixels);
    } else if (plan.kind == PassKind::Base && info.tracedPixels > 4096) {
        governor_.calibrate(info.ms / double(info.tracedPixels));
    }
}

void PassPlanner::planInteractive(PassPlan& plan,
                                  const std::shared_ptr<const CompiledScene>& snapshot,
                                  std::size_t stale, double lastUpdateMs, double lastPlanMs) const {
    const RenderSettings& settings = snapshot->settings();
    InteractionPolicy effective = policy_;
    if (policy_.governorTargetMs > 0.0) {
        plan.governorLevel = governor_.choose(
            policy_, stale, Governor::budgetMs(policy_.governorTargetMs, lastUpdateMs, lastPlanMs));
        effective = Governor::policyForLevel(policy_, plan.governorLevel);
    }
    plan.options = effective.movingTraceOptions(settings, moving_);
    plan.step = effective.pixelStep();
    plan.interleaved = effective.interleaved;
    plan.parity = interleaveParity_;
    plan.scene = snapshot;
    if (effective.boxProxy && moving_ != kNoObject && snapshot->primitiveIndex(moving_) >= 0)
        plan.scene = std::make_shared<const CompiledScene>(snapshot->withBoxProxy(moving_));
    // Full quality but for the shadows: each pixel's whole ray tree, traced in the scene.
    const bool fullTree = sameTree(plan.options, TraceOptions::fromSettings(settings)) &&
                          plan.scene == snapshot && plan.step == 1;
    plan.deferredRecords = fullTree && plan.options.shadows == ShadowQuality::Deferred;
    plan.resultIsBase = fullTree && plan.options.shadows == ShadowQuality::Full;
}

bool PassPlanner::plan(PassPlan& plan, const DeepFrame& frame,
                       const std::shared_ptr<const CompiledScene>& snapshot, uint64_t generation,
                       double lastUpdateMs, double lastPlanMs) const {
    const RenderSettings& settings = snapshot->settings();
    plan.generation = generation;
    plan.width = frame.width();
    plan.height = frame.height();
    plan.spp = std::max(1, settings.supersampling);

    // From the tiles' state counts: no pixel is looked at.
    const std::size_t stale = frame.countBelow(kInteractive);
    const std::size_t belowBase = frame.countBelow(kBase);
    const std::size_t belowFinal = frame.countBelow(kFinal);
    const uint8_t target = targetState(snapshot.get());
    if (interacting_ && target == kInteractive && stale > 0) {
        plan.kind = PassKind::Interactive;
        planInteractive(plan, snapshot, stale, lastUpdateMs, lastPlanMs);
    } else if (belowBase > 0) {
        plan.kind = PassKind::Base;
        plan.scene = snapshot;
        plan.options = TraceOptions::fromSettings(settings);
    } else if (belowFinal > 0 && target == kFinal) {
        plan.kind = PassKind::Supersample;
        plan.scene = snapshot;
        plan.options = TraceOptions::fromSettings(settings);
        plan.adaptive = settings.adaptiveSupersampling;
    } else {
        return false;
    }
    listTiles(plan, frame);
    plan.kernel = std::make_unique<const TraceKernel>(*plan.scene, plan.options);
    orderByFocus(plan, frame);
    return true;
}

void PassPlanner::orderByFocus(PassPlan& plan, const DeepFrame& frame) const {
    // Tiles near the edit (or the cursor) first: the user looks there. By groups of
    // kFocusGroupX x kFocusGroupY tiles, nearest group first, each traced whole and row by row
    // (the list is in row-major order and the sort is stable): neighbouring tiles of a row
    // share the pages of each frame buffer, which a tile-by-tile spiral leaves at every tile
    // (a full frame of the room took about 6 % more CPU time in that order).
    if (focusX_ < 0.0f) return;
    const int groupW = kFocusGroupX * frame.tileSize(), groupH = kFocusGroupY * frame.tileSize();
    const int groupsX = (frame.width() + groupW - 1) / groupW;
    const float fx = focusX_, fy = focusY_;
    auto group = [&](const TileJob& j) {
        return (j.rect.y0 / groupH) * groupsX + j.rect.x0 / groupW;
    };
    auto distance = [&](const TileJob& j) {
        const int gx = j.rect.x0 / groupW, gy = j.rect.y0 / groupH;
        const float cx = (float(gx) + 0.5f) * float(groupW) - fx;
        const float cy = (float(gy) + 0.5f) * float(groupH) - fy;
        return cx * cx + cy * cy;
    };
    std::stable_sort(plan.tiles.begin(), plan.tiles.end(), [&](const TileJob& a, const TileJob& b) {
        const float da = distance(a), db = distance(b);
        return da < db || (da == db && group(a) < group(b));
    });
}

}  // namespace rs
