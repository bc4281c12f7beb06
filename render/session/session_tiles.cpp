// Tile work of a pass: gather the tile's pixels by what they need, trace each list as one
// batch through the trace kernel (or resolve deferred shadows, or add samples), then commit
// to the frame only if the generation is still current.
#include "integrator/renderer.h"
#include "integrator/trace_kernel.h"
#include "session/session_plan.h"
#include "session/tile_output.h"

#include <algorithm>

namespace rs {

namespace {

constexpr int kRecordsPerPixel = 16;
constexpr int kSegmentsPerPixel = 24;

/// A pixel written from one camera ray's result; hitBound is left to the caller.
PixelOut primaryPixel(std::size_t index, const Color& color, const PrimaryInfo& info,
                      uint32_t cost, uint8_t state, uint8_t flags) {
    PixelOut o{};
    o.index = uint32_t(index);
    o.color = color;
    o.id = info.id;
    o.depth = info.depth;
    o.normal = info.normal;
    o.cost = cost;
    o.state = state;
    o.flags = flags;
    return o;
}

/// The hit point of a camera ray as a bounding sphere of radius 0 (none for a miss).
glm::vec4 pointBound(const Vec3& origin, const Vec3& dir, const PrimaryInfo& info) {
    if (info.id == kNoObject) return glm::vec4(0.0f, 0.0f, 0.0f, -1.0f);
    return glm::vec4(origin + dir * info.depth, 0.0f);
}

/// Grows a bounding sphere to contain `p` (conservative, centre kept).
glm::vec4 growBound(glm::vec4 b, const Vec3& p) {
    if (b.w < 0.0f) return glm::vec4(p, 0.0f);
    b.w = std::max(b.w, glm::length(p - Vec3(b)));
    return b;
}

/// Camera rays of one list of a tile and everything the kernel writes back for them.
struct RayList {
    std::vector<Vec3> origin, dir;
    std::vector<uint32_t> seed;
    std::vector<std::size_t> pixel;  ///< Frame index (block entries: the block's top-left).
    std::vector<uint8_t> extra;      ///< Flags or span packed by the caller.
    std::vector<Color> color;
    std::vector<PrimaryInfo> info;
    std::vector<uint32_t> rays;
    PerRayStorage<ShadingRecord> records;
    PerRayStorage<TreeSegment> segments;

    void clear() {
        origin.clear(), dir.clear(), seed.clear(), pixel.clear(), extra.clear();
    }
    void add(const Ray& ray, uint32_t s, std::size_t i, uint8_t e) {
        origin.push_back(ray.origin);
        dir.push_back(ray.dir);
        seed.push_back(s);
        pixel.push_back(i);
        extra.push_back(e);
    }
    std::size_t size() const { return origin.size(); }
    /// Traces the list; false when the generation went stale meanwhile.
    bool trace(const TraceKernel& kernel, bool withRecords, bool withSegments,
               TraceCounters& counters, const std::function<bool()>& stale) {
        const std::size_t n = size();
        if (n == 0) return true;
        color.resize(n), info.resize(n), rays.resize(n);
        TraceOutput out;
        out.color = color.data();
        out.primary = info.data();
        out.rays = rays.data();
        if (withRecords) out.records = records.lists(n, kRecordsPerPixel);
        if (withSegments) out.segments = segments.lists(n, kSegmentsPerPixel);
        return kernel.trace(CameraBatch{origin.data(), dir.data(), seed.data(), n, true}, out,
                            counters, stale);
    }
};

}  // namespace

void RenderSession::processTile(const Plan& plan, const TileJob& job, PassCounters& counters) {
    thread_local std::vector<PixelOut> out;
    thread_local std::vector<ShadingRecord> records;
    thread_local std::vector<TreeSegment> segments;
    thread_local RayList full, moving, blocks, samples;
    thread_local std::vector<std::size_t> resolvePixels;
    thread_local std::vector<ShadingRecord> resolveRecords;
    thread_local std::vector<Color> resolved;
    thread_local std::vector<std::size_t> samplePixels;
    thread_local std::vector<int> sampleFirst;  ///< Per supersampled pixel: its first sample.
    out.clear();
    records.clear();
    segments.clear();
    full.clear(), moving.clear(), blocks.clear(), samples.clear();
    resolvePixels.clear(), resolveRecords.clear(), samplePixels.clear(), sampleFirst.clear();
    const CompiledScene& scene = *plan.scene;
    const CameraModel& camera = scene.camera();
    const TraceKernel kernel(scene, plan.options);
    const PixelRect& r = job.rect;
    const int w = plan.width;
    const std::function<bool()> stale = [&] {
        return generation_.load(std::memory_order_relaxed) != plan.generation;
    };
    if (stale()) return;
    auto centreRay = [&](int x, int y) {
        return camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
    };

    // Gather: which pixels need what.
    for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const uint8_t s = plan.state[i];
            if (plan.kind == PassKind::Interactive) {
                if (plan.step == 1) {
                    if (s != kStale) continue;
                    if (plan.interleaved && ((x + y + plan.parity) & 1)) continue;
                    (plan.resultIsBase ? full : moving)
                        .add(centreRay(x, y), pixelSeed(x, y, 0), i, kTracedLastUpdate);
                    continue;
                }
                // Undersampling: one ray per step x step block, shown over the whole block.
                if (x % plan.step || y % plan.step) continue;
                const int bx1 = std::min(r.x1, x + plan.step), by1 = std::min(r.y1, y + plan.step);
                if (plan.interleaved && (((x / plan.step) + (y / plan.step) + plan.parity) & 1))
                    continue;
                bool anyStale = false;
                for (int yy = y; yy < by1 && !anyStale; ++yy)
                    for (int xx = x; xx < bx1 && !anyStale; ++xx)
                        anyStale = plan.state[std::size_t(yy) * std::size_t(w) + std::size_t(xx)] == kStale;
                if (!anyStale) continue;
                const Ray ray = camera.generateRay(0.5f * float(x + bx1), 0.5f * float(y + by1));
                blocks.add(ray, pixelSeed(x, y, 0), i, uint8_t((bx1 - x) | ((by1 - y) << 4)));
            } else if (plan.kind == PassKind::Base) {
                if (s >= kBase) continue;
                if (s == kInteractive && (plan.flags[i] & kDeferredValid)) {
                    // Deferred shadows: add the light terms at the stored shading points;
                    // camera and secondary rays are not traced again (thesis 3.3).
                    const auto& pool = frame_.tileRecords[std::size_t(job.tile)];
                    const uint32_t start = frame_.recordStart[i];
                    resolvePixels.push_back(i);
                    resolveRecords.insert(resolveRecords.end(), pool.begin() + start,
                                          pool.begin() + start + frame_.recordCount[i]);
                } else {
                    full.add(centreRay(x, y), pixelSeed(x, y, 0), i,
                             uint8_t(plan.flags[i] & kTracedLastUpdate));
                }
            } else {  // Supersample
                if (s != kBase) continue;
                if (!plan.needSupersampling[i]) {
                    PixelOut o{};
                    o.index = uint32_t(i);
                    o.color = o.base = frame_.base[i];
                    o.id = frame_.id[i];
                    o.depth = frame_.depth[i];
                    o.normal = frame_.normal[i];
                    o.flags = plan.flags[i];
                    o.hitBound = frame_.hitBound[i];
                    o.cost = frame_.cost[i];
                    o.segmentMode = kKeep;
                    o.state = kFinal;
                    out.push_back(o);
                    continue;
                }
                // Progressive: up to sppChunk samples more, in the order renderPixel sums them.
                const int count = frame_.sampleCount[i];
                const int end = std::min(plan.spp, count + plan.sppChunk);
                const uint32_t patternSeed = pixelSeed(x, y, 0x5eed);
                samplePixels.push_back(i);
                sampleFirst.push_back(int(samples.size()));
                for (int k = count; k < end; ++k) {
                    const Vec3 off = pixelSampleOffset(k, plan.spp, patternSeed);
                    samples.add(camera.generateRay(float(x) + off.x, float(y) + off.y),
                                pixelSeed(x, y, k), i, 0);
                }
            }
        }
    }
    sampleFirst.push_back(int(samples.size()));

    // Trace.
    TraceCounters tc;
    const bool segmentsWanted = true;
    if (!full.trace(kernel, false, segmentsWanted, tc, stale)) return;
    if (!moving.trace(kernel, plan.deferredRecords, segmentsWanted, tc, stale)) return;
    if (!blocks.trace(kernel, false, false, tc, stale)) return;
    if (!samples.trace(kernel, false, segmentsWanted, tc, stale)) return;
    resolved.resize(resolveRecords.size());
    kernel.resolveDeferred(resolveRecords.data(), resolveRecords.size(), resolved.data(), tc);
    if (stale()) return;
    const std::size_t traced = full.size() + moving.size() + blocks.size() + resolvePixels.size() +
                               samplePixels.size();

    // Results as PixelOut entries.
    auto keepSegments = [&](PixelOut& o, const RayList& list, std::size_t k) {
        o.segmentOffset = uint32_t(segments.size());
        o.segmentCount = list.segments.count[k];
        const TreeSegment* first = list.segments.of(k, kSegmentsPerPixel);
        segments.insert(segments.end(), first, first + list.segments.count[k]);
        if (list.segments.overflow[k]) o.flags |= kTreeUnknown;
    };
    const uint8_t doneState = plan.spp == 1 ? kFinal : kBase;
    for (std::size_t k = 0; k < full.size(); ++k) {
        const PrimaryInfo& info = full.info[k];
        PixelOut o = primaryPixel(full.pixel[k], full.color[k], info, full.rays[k], doneState,
                                  uint8_t((info.touchedSpecular ? kTouchedSpecular : 0) | full.extra[k]));
        o.hitBound = pointBound(full.origin[k], full.dir[k], info);
        o.base = full.color[k];
        keepSegments(o, full, k);
        out.push_back(o);
    }
    for (std::size_t k = 0; k < moving.size(); ++k) {
        const PrimaryInfo& info = moving.info[k];
        const bool complete = plan.deferredRecords && !moving.records.overflow[k];
        PixelOut o = primaryPixel(
            moving.pixel[k], moving.color[k], info, moving.rays[k], kInteractive,
            uint8_t((info.touchedSpecular ? kTouchedSpecular : 0) | moving.extra[k] |
                    (complete ? kDeferredValid : 0)));
        o.hitBound = pointBound(moving.origin[k], moving.dir[k], info);
        o.recordOffset = uint32_t(records.size());
        o.recordCount = complete ? moving.records.count[k] : 0;
        if (complete) {
            const ShadingRecord* first = moving.records.of(k, kRecordsPerPixel);
            records.insert(records.end(), first, first + moving.records.count[k]);
        }
        keepSegments(o, moving, k);
        out.push_back(o);
    }
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        const PrimaryInfo& info = blocks.info[k];
        // One entry for the block; the commit writes it to every pixel of it.
        PixelOut o = primaryPixel(
            blocks.pixel[k], blocks.color[k], info, blocks.rays[k], kInteractive,
            uint8_t((info.touchedSpecular ? kTouchedSpecular | kTreeUnknown : 0) | kTracedLastUpdate));
        o.hitBound = pointBound(blocks.origin[k], blocks.dir[k], info);
        o.spanX = uint8_t(blocks.extra[k] & 15);
        o.spanY = uint8_t(blocks.extra[k] >> 4);
        out.push_back(o);
    }
    for (std::size_t k = 0, record = 0; k < resolvePixels.size(); ++k) {
        const std::size_t i = resolvePixels[k];
        Color c = frame_.color[i];
        for (uint32_t j = 0; j < frame_.recordCount[i]; ++j) c += resolved[record++];
        PixelOut o{};
        o.index = uint32_t(i);
        o.color = o.base = c;
        o.id = frame_.id[i];
        o.depth = frame_.depth[i];
        o.normal = frame_.normal[i];
        o.cost = frame_.cost[i];
        o.state = doneState;
        o.flags = uint8_t(plan.flags[i] & (kTouchedSpecular | kTracedLastUpdate | kTreeUnknown));
        o.hitBound = frame_.hitBound[i];
        o.segmentMode = kKeep;
        out.push_back(o);
    }
    for (std::size_t k = 0; k < samplePixels.size(); ++k) {
        const std::size_t i = samplePixels[k];
        PixelOut o{};
        o.index = uint32_t(i);
        o.base = frame_.base[i];
        o.id = frame_.id[i];
        o.depth = frame_.depth[i];
        o.normal = frame_.normal[i];
        o.flags = plan.flags[i];
        o.hitBound = frame_.hitBound[i];
        o.cost = frame_.cost[i];
        Color sum = frame_.sampleSum[i];
        int count = frame_.sampleCount[i];
        o.segmentOffset = uint32_t(segments.size());
        uint32_t kept = 0;
        for (int j = sampleFirst[k]; j < sampleFirst[k + 1]; ++j) {
            const std::size_t q = std::size_t(j);
            sum += samples.color[q];
            const PrimaryInfo& info = samples.info[q];
            if (info.id != kNoObject)
                o.hitBound = growBound(o.hitBound, samples.origin[q] + samples.dir[q] * info.depth);
            if (info.touchedSpecular) o.flags |= kTouchedSpecular;
            o.cost += samples.rays[q];
            // The pixel's segments of all its new samples, as one sink of kSegmentsPerPixel.
            const TreeSegment* first = samples.segments.of(q, kSegmentsPerPixel);
            for (uint8_t s = 0; s < samples.segments.count[q]; ++s) {
                if (kept < kSegmentsPerPixel) {
                    segments.push_back(first[s]);
                    ++kept;
                } else {
                    o.flags |= kTreeUnknown;
                }
            }
            if (samples.segments.overflow[q]) o.flags |= kTreeUnknown;
            ++count;
        }
        o.segmentCount = uint8_t(kept);
        o.segmentMode = kAppend;
        o.sampleSum = sum;
        o.sampleCount = uint16_t(count);
        o.color = count == plan.spp ? sum / float(plan.spp) : sum / float(count);
        o.state = count == plan.spp ? kFinal : kBase;
        out.push_back(o);
    }
    const uint64_t rays = tc.total();

    {
        // Shared: other tiles commit their own pixels concurrently; an edit holds it exclusively
        // while it bumps the generation, so a stale tile can never get in after it.
        std::shared_lock lock(frameMutex_);
        if (generation_.load() != plan.generation) return;  // Never write a stale tile.
        for (const PixelOut& o : out) {
            forEachWritten(o, w, [&](std::size_t i) {
                frame_.color[i] = o.color;
                frame_.id[i] = o.id;
                frame_.depth[i] = o.depth;
                frame_.normal[i] = o.normal;
                frame_.cost[i] = o.cost;
                frame_.state[i] = o.state;
                frame_.flags[i] = o.flags;
                frame_.hitBound[i] = o.hitBound;
                if (o.state >= kBase) frame_.base[i] = o.base;
                frame_.sampleSum[i] = o.sampleSum;
                frame_.sampleCount[i] = o.sampleCount;
            });
        }
        if (plan.kind == PassKind::Interactive && plan.deferredRecords) {
            // Rebuild the tile's record pool: new records for traced pixels, old ones kept for
            // untouched pixels that still wait for their deferred shadows.
            auto& pool = frame_.tileRecords[std::size_t(job.tile)];
            std::vector<ShadingRecord> fresh;
            std::vector<uint8_t> written(std::size_t(r.x1 - r.x0) * std::size_t(r.y1 - r.y0), 0);
            for (const PixelOut& o : out) {
                const int px = int(o.index % uint32_t(w)), py = int(o.index / uint32_t(w));
                written[std::size_t(py - r.y0) * std::size_t(r.x1 - r.x0) + std::size_t(px - r.x0)] = 1;
                frame_.recordStart[o.index] = uint32_t(fresh.size());
                frame_.recordCount[o.index] = o.recordCount;
                fresh.insert(fresh.end(), records.begin() + o.recordOffset,
                             records.begin() + o.recordOffset + o.recordCount);
            }
            for (int y = r.y0; y < r.y1; ++y) {
                for (int x = r.x0; x < r.x1; ++x) {
                    const std::size_t i = frame_.index(x, y);
                    if (written[std::size_t(y - r.y0) * std::size_t(r.x1 - r.x0) + std::size_t(x - r.x0)]) continue;
                    if (!(frame_.flags[i] & kDeferredValid)) continue;
                    const uint32_t start = frame_.recordStart[i];
                    frame_.recordStart[i] = uint32_t(fresh.size());
                    fresh.insert(fresh.end(), pool.begin() + start,
                                 pool.begin() + start + frame_.recordCount[i]);
                }
            }
            pool.swap(fresh);
        }
        commitSegments(frame_, job.rect, job.tile, out, segments);
    }
    counters.pixels += traced;
    counters.rays += rays;
    if (SessionObserver* observer = observer_) observer->tileDone(r.x0, r.y0, r.x1, r.y1, plan.generation);
}

}  // namespace rs
