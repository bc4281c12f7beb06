// Pass planning: which kind of pass comes next, at which quality, over which tiles, in what order.
#include "integrator/renderer.h"
#include "session/session_plan.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <cstring>

namespace rs {

namespace {

constexpr uint64_t kOnes = 0x0101010101010101ull;
constexpr uint64_t kHighs = 0x8080808080808080ull;

/// True when one of the eight bytes of `w` is below `n` (n <= 128; bit-twiddling "hasless").
inline bool anyByteBelow(uint64_t w, uint8_t n) { return ((w - kOnes * n) & ~w & kHighs) != 0; }
inline bool anyByteEqual(uint64_t w, uint8_t v) { return anyByteBelow(w ^ (kOnes * v), 1); }

/// Whether any of the `n` bytes at `p` passes `test` (a word test, then a byte test for the
/// tail), eight at a time.
template <class WordTest, class ByteTest>
bool anyInRow(const uint8_t* p, int n, WordTest&& word, ByteTest&& byte) {
    int x = 0;
    for (; x + 8 <= n; x += 8) {
        uint64_t w;
        std::memcpy(&w, p + x, 8);
        if (word(w)) return true;
    }
    for (; x < n; ++x)
        if (byte(p[x])) return true;
    return false;
}

bool tileHasCandidate(const RenderSession::Plan& plan, const PixelRect& r) {
    const int n = r.x1 - r.x0;
    for (int y = r.y0; y < r.y1; ++y) {
        const uint8_t* row = plan.state.data() + std::size_t(y) * std::size_t(plan.width) + r.x0;
        switch (plan.kind) {
            case PassKind::Interactive: {
                const bool anyStale = anyInRow(
                    row, n, [](uint64_t w) { return anyByteEqual(w, kStale); },
                    [](uint8_t s) { return s == kStale; });
                if (!anyStale) break;
                if (!plan.interleaved) return true;
                for (int x = r.x0; x < r.x1; ++x) {
                    const int bx = x / plan.step, by = y / plan.step;
                    if (row[x - r.x0] == kStale && ((bx + by + plan.parity) & 1) == 0) return true;
                }
                break;
            }
            case PassKind::Base:
                if (anyInRow(row, n, [](uint64_t w) { return anyByteBelow(w, kBase); },
                             [](uint8_t s) { return s < kBase; }))
                    return true;
                break;
            case PassKind::Supersample:
                if (anyInRow(row, n, [](uint64_t w) { return anyByteEqual(w, kBase); },
                             [](uint8_t s) { return s == kBase; }))
                    return true;
                break;
        }
    }
    return false;
}

}  // namespace

bool RenderSession::planLocked(Plan& plan) {
    if (threadsChanged_) {
        arena_ = std::make_unique<tbb::task_arena>(threads_ > 0 ? threads_ : tbb::info::default_concurrency());
        threadsChanged_ = false;
    }
    const RenderSettings& settings = snapshot_->settings();
    if (pendingResize_) {
        std::unique_lock frameLock(frameMutex_);  // Readers may be copying the old frame.
        frame_.resize(settings.width, settings.height);
        pendingResize_ = false;
    }
    plan.generation = generation_.load();
    plan.width = frame_.width;
    plan.height = frame_.height;
    plan.spp = std::max(1, settings.supersampling);

    // Counted in chunks with 32-bit sums, which the compiler vectorises.
    std::size_t stale = 0, belowBase = 0, belowFinal = 0;
    for (std::size_t c0 = 0; c0 < frame_.state.size(); c0 += 65536) {
        const std::size_t c1 = std::min(frame_.state.size(), c0 + 65536);
        uint32_t st = 0, bb = 0, bf = 0;
        for (std::size_t i = c0; i < c1; ++i) {
            const uint8_t s = frame_.state[i];
            st += s == kStale;
            bb += s < kBase;
            bf += s < kFinal;
        }
        stale += st, belowBase += bb, belowFinal += bf;
    }
    const uint8_t target = targetStateLocked();
    const TraceOptions full = TraceOptions::fromSettings(settings);
    if (interacting_ && target == kInteractive && stale > 0) {
        plan.kind = PassKind::Interactive;
        InteractionPolicy effective = policy_;
        if (policy_.governorTargetMs > 0.0) {
            // The frame also pays for the edit itself (diff, refit, dirty marking) and for
            // planning the pass: budget the tracing with what is left of the target, less a
            // tenth kept for scheduling jitter, so frames meet the target, not just average it.
            const double budget =
                std::max(0.0, 0.9 * policy_.governorTargetMs - stats_.lastUpdateMs -
                                  stats_.lastInteractivePass.planMs);
            plan.governorLevel = governor_.choose(policy_, stale, budget);
            effective = Governor::policyForLevel(policy_, plan.governorLevel);
        }
        plan.options = effective.movingTraceOptions(settings, moving_);
        plan.step = effective.pixelStep();
        plan.interleaved = effective.interleaved;
        plan.parity = interleaveParity_;
        plan.scene = snapshot_;
        if (effective.boxProxy && moving_ != kNoObject && snapshot_->primitiveIndex(moving_) >= 0)
            plan.scene = std::make_shared<const CompiledScene>(snapshot_->withBoxProxy(moving_));
        const bool fullTree = plan.options.maxDepth == full.maxDepth &&
                              !plan.options.reflectionAsDiffuse &&
                              !plan.options.refractionAsDiffuse && plan.scene == snapshot_ &&
                              plan.step == 1;
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
        plan.needSupersampling.assign(frame_.pixelCount(), 0);
        for (int y = 0; y < frame_.height; ++y) {
            for (int x = 0; x < frame_.width; ++x) {
                const std::size_t i = frame_.index(x, y);
                if (frame_.state[i] != kBase) continue;
                plan.needSupersampling[i] =
                    !settings.adaptiveSupersampling ||
                    needsSupersampling(frame_.base.data(), frame_.id.data(), frame_.normal.data(),
                                       frame_.width, frame_.height, x, y);
            }
        }
    } else {
        return false;
    }
    plan.state = frame_.state;
    plan.flags = frame_.flags;

    for (int ty = 0; ty < frame_.tilesY(); ++ty) {
        for (int tx = 0; tx < frame_.tilesX(); ++tx) {
            TileJob job;
            job.tile = ty * frame_.tilesX() + tx;
            job.rect = {tx * frame_.tileSize, ty * frame_.tileSize,
                        std::min(frame_.width, (tx + 1) * frame_.tileSize),
                        std::min(frame_.height, (ty + 1) * frame_.tileSize)};
            if (tileHasCandidate(plan, job.rect)) plan.tiles.push_back(job);
        }
    }
    // Tiles near the edit (or the cursor) first: the user looks there.
    if (focusX_ >= 0.0f) {
        const float fx = focusX_, fy = focusY_;
        auto distance = [fx, fy](const TileJob& j) {
            const float cx = 0.5f * float(j.rect.x0 + j.rect.x1) - fx;
            const float cy = 0.5f * float(j.rect.y0 + j.rect.y1) - fy;
            return cx * cx + cy * cy;
        };
        std::stable_sort(plan.tiles.begin(), plan.tiles.end(),
                         [&](const TileJob& a, const TileJob& b) { return distance(a) < distance(b); });
    }
    return true;
}

}  // namespace rs
