// Tile work of a pass: each pass kind gathers the tile's pixels by what they need, traces
// each list as one batch through the trace kernel (or resolves deferred shadows, or adds
// samples) into a TileResult, which the frame commits only if the generation is still current.
#include <algorithm>

#include "integrator/pixel_samples.h"
#include "integrator/renderer.h"
#include "integrator/trace_kernel.h"
#include "session/render_session.h"
#include "session/session_plan.h"
#include "session/tile_output.h"

namespace rs {

namespace {

/// What a pass kind's tile function reads: the plan, the frame as the plan left it (this
/// tile's pixels are written by nobody else meanwhile) and the kernel.
struct TileInput {
    const PassPlan& plan;
    const TileJob& job;
    const DeepFrame& frame;
    const TraceKernel& kernel;
    const CameraModel& camera;
    const std::function<bool()>& stale;
    TraceCounters& counters;
    /// columnTerm() of each column's centre, from the tile's left edge on.
    const Vec3* columns;

    std::size_t index(int x, int y) const {
        return std::size_t(y) * std::size_t(plan.width) + std::size_t(x);
    }
    /// kFinal when the scene has no supersampling, else kBase.
    uint8_t doneState() const { return plan.spp == 1 ? kFinal : kBase; }
    /// Adds to `list` the centre rays of the pixels of row y for which take(x, i) holds, a
    /// run of neighbours at a time, each with extra(i).
    template <class Take, class Extra>
    void addCentreRays(RayList& list, int y, Take take, Extra extra) const {
        const PixelRect& r = job.rect;
        for (int x = r.x0; x < r.x1;) {
            if (!take(x, index(x, y))) {
                ++x;
                continue;
            }
            int end = x + 1;
            while (end < r.x1 && take(end, index(end, y))) ++end;
            const std::size_t i0 = index(x, y), n = std::size_t(end - x);
            const std::size_t k = list.addCentreRun(camera, columns + (x - r.x0), x, y, n, i0);
            for (std::size_t j = 0; j < n; ++j) list.extra[k + j] = extra(i0 + j);
            x = end;
        }
    }
};

/// Interactive pass at full resolution: stale pixels (every other one when interleaved).
bool interactiveTile(const TileInput& in, TileResult& out) {
    const PassPlan& plan = in.plan;
    const PixelRect& r = in.job.rect;
    const uint8_t* state = in.frame.state().data();
    for (int y = r.y0; y < r.y1; ++y) {
        in.addCentreRays(
            out.traced, y,
            [&](int x, std::size_t i) {
                return state[i] == kStale && !(plan.interleaved && ((x + y + plan.parity) & 1));
            },
            [](std::size_t) { return uint8_t(kTracedLastUpdate); });
    }
    out.tracedState = plan.resultIsBase ? in.doneState() : uint8_t(kInteractive);
    return out.traced.trace(in.kernel, plan.deferredRecords, true, in.counters, in.stale);
}

/// Interactive pass undersampled: one ray per step x step block with a stale pixel, shown
/// over the whole block.
bool blockTile(const TileInput& in, TileResult& out) {
    const PassPlan& plan = in.plan;
    const PixelRect& r = in.job.rect;
    const int step = plan.step;
    const auto firstMultiple = [step](int v) { return (v + step - 1) / step * step; };
    for (int y = firstMultiple(r.y0); y < r.y1; y += step) {
        for (int x = firstMultiple(r.x0); x < r.x1; x += step) {
            const int bx1 = std::min(r.x1, x + step), by1 = std::min(r.y1, y + step);
            if (plan.interleaved && (((x / step) + (y / step) + plan.parity) & 1)) continue;
            bool anyStale = false;
            for (int yy = y; yy < by1 && !anyStale; ++yy)
                for (int xx = x; xx < bx1 && !anyStale; ++xx)
                    anyStale = in.frame.state()[in.index(xx, yy)] == kStale;
            if (!anyStale) continue;
            const Ray ray = in.camera.generateRay(0.5f * float(x + bx1), 0.5f * float(y + by1));
            out.blocks.add(ray, pixelSeed(x, y, 0), in.index(x, y),
                           uint8_t((bx1 - x) | ((by1 - y) << 4)));
        }
    }
    return out.blocks.trace(in.kernel, false, false, in.counters, in.stale);
}

/// Base pass: pixels below full quality are traced, or, when an interactive pass recorded
/// their shading points, get the deferred light terms added there (camera and secondary rays
/// are not traced again; thesis 3.3).
bool baseTile(const TileInput& in, TileResult& out) {
    thread_local std::vector<ShadingRecord> records;
    thread_local std::vector<Color> resolved;
    records.clear();
    const DeepFrame& f = in.frame;
    const PixelRect& r = in.job.rect;
    const auto& pool = f.tileRecords()[std::size_t(in.job.tile)];
    const uint8_t* state = f.state().data();
    const uint8_t* flags = f.flags().data();
    // Waiting for its deferred shadows only: resolved from its records, not traced again.
    const auto deferred = [&](std::size_t i) {
        return state[i] == kInteractive && (flags[i] & kDeferredValid);
    };
    if (f.tileStates()[std::size_t(in.job.tile)][kStale] == uint32_t(r.area())) {
        // Every pixel stale (a camera move, a new frame): all traced, none resolved, and
        // nothing per pixel to decide (this tile's counts only its own commit writes).
        const std::size_t n = std::size_t(r.x1 - r.x0);
        for (int y = r.y0; y < r.y1; ++y) {
            const std::size_t i0 = in.index(r.x0, y);
            const std::size_t k = out.traced.addCentreRun(in.camera, in.columns, r.x0, y, n, i0);
            uint8_t* extra = out.traced.extra.data() + k;
            for (std::size_t j = 0; j < n; ++j)
                extra[j] = uint8_t(flags[i0 + j] & kTracedLastUpdate);
        }
        out.tracedState = in.doneState();
        return out.traced.trace(in.kernel, false, true, in.counters, in.stale);
    }
    for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
            const std::size_t i = in.index(x, y);
            if (state[i] >= kBase || !deferred(i)) continue;
            out.resolvedPixel.push_back(i);
            const uint32_t start = f.recordStart()[i];
            records.insert(records.end(), pool.begin() + start,
                           pool.begin() + start + f.recordCount()[i]);
        }
        in.addCentreRays(
            out.traced, y, [&](int, std::size_t i) { return state[i] < kBase && !deferred(i); },
            [&](std::size_t i) { return uint8_t(flags[i] & kTracedLastUpdate); });
    }
    out.tracedState = in.doneState();
    if (!out.traced.trace(in.kernel, false, true, in.counters, in.stale)) return false;
    resolved.resize(records.size());
    in.kernel.resolveDeferred(records.data(), records.size(), resolved.data(), in.counters);
    out.resolvedState = in.doneState();
    for (std::size_t k = 0, record = 0; k < out.resolvedPixel.size(); ++k) {
        const std::size_t i = out.resolvedPixel[k];
        Color c = f.color()[i];
        for (uint32_t j = 0; j < f.recordCount()[i]; ++j) c += resolved[record++];
        out.resolvedColor.push_back(c);
        out.resolvedFlags.push_back(
            uint8_t(f.flags()[i] & (kTouchedSpecular | kTracedLastUpdate | kTreeUnknown)));
    }
    return true;
}

/// Grows a bounding sphere to contain `p` (conservative, centre kept).
glm::vec4 growBound(glm::vec4 b, const Vec3& p) {
    if (b.w < 0.0f) return glm::vec4(p, 0.0f);
    b.w = std::max(b.w, glm::length(p - Vec3(b)));
    return b;
}

/// Supersample pass: pixels at kBase get up to sppChunk samples more, in the order
/// renderPixel sums them, unless adaptive supersampling says the centre sample is final.
bool supersampleTile(const TileInput& in, TileResult& out) {
    const PassPlan& plan = in.plan;
    const DeepFrame& f = in.frame;
    const PixelRect& r = in.job.rect;
    thread_local std::vector<std::size_t> sampledPixels;
    sampledPixels.clear();
    for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
            const std::size_t i = in.index(x, y);
            if (f.state()[i] != kBase) continue;
            // Decided here, per tile: the pass writes no base, id or normal, so the
            // neighbours this reads (in other tiles too) stay as the Base pass left them.
            if (plan.adaptive &&
                !needsSupersampling(f.base().data(), f.id().data(), f.normal().data(), f.width(),
                                    f.height(), x, y)) {
                out.finishedPixel.push_back(i);
                continue;
            }
            const int count = f.sampleCount()[i];
            const int end = std::min(plan.spp, count + plan.sppChunk);
            const PixelSamples pixelSamples(x, y, plan.spp);
            sampledPixels.push_back(i);
            out.sampleFirst.push_back(int(out.samples.size()));
            for (int k = count; k < end; ++k)
                out.samples.add(pixelSamples.ray(in.camera, k), pixelSamples.seed(k), i, 0);
        }
    }
    out.sampleFirst.push_back(int(out.samples.size()));
    if (!out.samples.trace(in.kernel, false, true, in.counters, in.stale)) return false;
    const RayList& samples = out.samples;
    for (std::size_t k = 0; k < sampledPixels.size(); ++k) {
        const std::size_t i = sampledPixels[k];
        TileResult::Sampled s{i,     Color(0.0f),  f.sampleSum()[i], f.sampleCount()[i],
                              kBase, f.flags()[i], f.cost()[i],      f.hitBound()[i]};
        int kept = 0;
        for (int j = out.sampleFirst[k]; j < out.sampleFirst[k + 1]; ++j) {
            const std::size_t q = std::size_t(j);
            s.sum += samples.color[q];
            const PrimaryInfo& info = samples.info[q];
            if (info.id != kNoObject) {
                s.hitBound = growBound(s.hitBound, samples.origin[q] + samples.dir[q] * info.depth);
                if (info.id != f.id()[i]) s.flags |= kSampleOtherObject;
            } else {
                s.flags |= kSampleMissed;
            }
            if (info.touchedSpecular) s.flags |= kTouchedSpecular;
            s.cost += samples.rays[q];
            // The pixel's segments of all its new samples, as one list of kSegmentsPerPixel.
            const int n = samples.segments.count[q];
            if (kept + n > kSegmentsPerPixel || samples.segments.overflow[q])
                s.flags |= kTreeUnknown;
            kept = std::min(kSegmentsPerPixel, kept + n);
            ++s.count;
        }
        s.color = s.count == plan.spp ? s.sum / float(plan.spp) : s.sum / float(s.count);
        s.state = s.count == plan.spp ? kFinal : kBase;
        out.sampled.push_back(s);
    }
    return true;
}

}  // namespace

void RenderSession::processTile(const PassPlan& plan, const TileJob& job, PassCounters& counters) {
    thread_local TileResult result;
    result.clear();
    result.generation = plan.generation;
    result.tile = job.tile;
    result.rect = job.rect;
    result.keepBase = plan.spp > 1;
    const std::function<bool()> stale = [&] {
        return generation_.load(std::memory_order_relaxed) != plan.generation;
    };
    if (stale()) return;
    const CompiledScene& scene = *plan.scene;
    const TraceKernel& kernel = *plan.kernel;
    TraceCounters tc;
    thread_local std::vector<Vec3> columns;
    columns.resize(std::size_t(job.rect.x1 - job.rect.x0));
    for (int x = job.rect.x0; x < job.rect.x1; ++x)
        columns[std::size_t(x - job.rect.x0)] = scene.camera().columnTerm(float(x) + 0.5f);
    const TileInput in{plan, job, book_.frame(), kernel, scene.camera(), stale, tc, columns.data()};
    bool traced = false;
    switch (plan.kind) {
        case PassKind::Interactive:
            traced = plan.step == 1 ? interactiveTile(in, result) : blockTile(in, result);
            break;
        case PassKind::Base:
            traced = baseTile(in, result);
            break;
        case PassKind::Supersample:
            traced = supersampleTile(in, result);
            break;
    }
    if (!traced || stale()) return;
    {
        // Shared: other tiles commit their own pixels concurrently; an edit's marking holds it
        // exclusively, after every tile of the pass has returned; a waiting reader goes first.
        auto lock = frameLock_.commit();
        if (!book_.frame().commit(result, generation_.load())) return;
    }
    counters.pixels += result.tracedPixels();
    counters.rays += tc.total();
    const PixelRect& r = job.rect;
    if (SessionObserver* observer = observer_)
        observer->tileDone(r.x0, r.y0, r.x1, r.y1, plan.generation);
}

}  // namespace rs
