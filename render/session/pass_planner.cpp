// Pass planning: which kind of pass comes next, at which quality, over which tiles, in what order.
#include <tbb/task_arena.h>

#include <algorithm>

#include "integrator/renderer.h"
#include "session/session_plan.h"

namespace rs {

namespace {

/// Tiles of a focus-ordered pass go in groups this many tiles wide and high (planLocked).
constexpr int kFocusGroupX = 8, kFocusGroupY = 2;

/// Whether the tile has a pixel the pass would work on, from the tile's state counts (an
/// interleaved pass also needs a stale pixel of this frame's parity: those tiles are scanned).
bool tileHasCandidate(const RenderSession::Plan& plan, const DeepFrame& frame, int tile,
                      const PixelRect& r) {
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

}  // namespace

bool RenderSession::planLocked(Plan& plan) {
    if (threadsChanged_) {
        arena_ = std::make_unique<BackgroundArena>(arenaSize(threads_));
        threadsChanged_ = false;
    }
    const RenderSettings& settings = snapshot_->settings();
    if (pendingResize_) {
        auto frameLock = frameLock_.exclusive();  // Readers may be copying the old frame.
        frame_.resize(settings.width, settings.height);
        pendingResize_ = false;
    }
    plan.generation = generation_.load();
    plan.width = frame_.width();
    plan.height = frame_.height();
    plan.spp = std::max(1, settings.supersampling);

    // From the tiles' state counts: no pixel is looked at.
    const std::size_t stale = frame_.countBelow(kInteractive);
    const std::size_t belowBase = frame_.countBelow(kBase);
    const std::size_t belowFinal = frame_.countBelow(kFinal);
    const uint8_t target = targetStateLocked();
    const TraceOptions full = TraceOptions::fromSettings(settings);
    if (interacting_ && target == kInteractive && stale > 0) {
        plan.kind = PassKind::Interactive;
        InteractionPolicy effective = policy_;
        if (policy_.governorTargetMs > 0.0) {
            plan.governorLevel =
                governor_.choose(policy_, stale,
                                 Governor::budgetMs(policy_.governorTargetMs, stats_.lastUpdateMs,
                                                    stats_.lastInteractivePass.planMs));
            effective = Governor::policyForLevel(policy_, plan.governorLevel);
        }
        plan.options = effective.movingTraceOptions(settings, moving_);
        plan.step = effective.pixelStep();
        plan.interleaved = effective.interleaved;
        plan.parity = interleaveParity_;
        plan.scene = snapshot_;
        if (effective.boxProxy && moving_ != kNoObject && snapshot_->primitiveIndex(moving_) >= 0)
            plan.scene = std::make_shared<const CompiledScene>(snapshot_->withBoxProxy(moving_));
        const bool fullTree =
            plan.options.maxDepth == full.maxDepth && !plan.options.reflectionAsDiffuse &&
            !plan.options.refractionAsDiffuse && plan.scene == snapshot_ && plan.step == 1;
        plan.deferredRecords = fullTree && plan.options.shadows == ShadowQuality::Deferred;
        plan.resultIsBase = fullTree && plan.options.shadows == ShadowQuality::Full;
    } else if (belowBase > 0) {
        plan.kind = PassKind::Base;
        plan.scene = snapshot_;
        plan.options = full;
    } else if (belowFinal > 0 && target == kFinal) {
        plan.kind = PassKind::Supersample;
        plan.scene = snapshot_;
        plan.options = full;
        plan.adaptive = settings.adaptiveSupersampling;
    } else {
        return false;
    }
    for (int ty = 0; ty < frame_.tilesY(); ++ty) {
        for (int tx = 0; tx < frame_.tilesX(); ++tx) {
            TileJob job;
            job.tile = ty * frame_.tilesX() + tx;
            job.rect = {tx * frame_.tileSize(), ty * frame_.tileSize(),
                        std::min(frame_.width(), (tx + 1) * frame_.tileSize()),
                        std::min(frame_.height(), (ty + 1) * frame_.tileSize())};
            if (tileHasCandidate(plan, frame_, job.tile, job.rect)) plan.tiles.push_back(job);
        }
    }
    plan.kernel = std::make_unique<const TraceKernel>(*plan.scene, plan.options);
    // Tiles near the edit (or the cursor) first: the user looks there. By groups of
    // kFocusGroupX x kFocusGroupY tiles, nearest group first, each traced whole and row by row
    // (the list is in row-major order and the sort is stable): neighbouring tiles of a row
    // share the pages of each frame buffer, which a tile-by-tile spiral leaves at every tile
    // (a full frame of the room took about 6 % more CPU time in that order).
    if (focusX_ >= 0.0f) {
        const int groupW = kFocusGroupX * frame_.tileSize(),
                  groupH = kFocusGroupY * frame_.tileSize();
        const int groupsX = (frame_.width() + groupW - 1) / groupW;
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
        std::stable_sort(plan.tiles.begin(), plan.tiles.end(),
                         [&](const TileJob& a, const TileJob& b) {
                             const float da = distance(a), db = distance(b);
                             return da < db || (da == db && group(a) < group(b));
                         });
    }
    return true;
}

}  // namespace rs
