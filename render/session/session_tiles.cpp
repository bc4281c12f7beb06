// Tile work of a pass: trace (or resolve, or supersample) into a local buffer, then commit it
// to the frame only if its generation is still current.
#include "integrator/packet_tracer.h"
#include "integrator/renderer.h"
#include "session/session_plan.h"
#include "session/tile_output.h"

#include <algorithm>

namespace rs {

namespace {

constexpr int kRecordsPerPixel = 16;
constexpr int kSegmentsPerPixel = 24;

glm::vec4 pointBound(const Ray& ray, const PrimaryInfo& info) {
    if (info.id == kNoObject) return glm::vec4(0.0f, 0.0f, 0.0f, -1.0f);
    return glm::vec4(ray.at(info.depth), 0.0f);
}

/// A pixel written from one camera ray's result; hitBound is left to the caller.
PixelOut primaryPixel(std::size_t index, const Color& color, const PrimaryInfo& info,
                      const TraceCounters& tc, uint8_t state, uint8_t flags) {
    PixelOut o{};
    o.index = uint32_t(index);
    o.color = color;
    o.id = info.id;
    o.depth = info.depth;
    o.normal = info.normal;
    o.cost = uint32_t(tc.total());
    o.state = state;
    o.flags = flags;
    return o;
}

/// primaryPixel with the hit point of `ray` as the bound.
PixelOut primaryPixel(std::size_t index, const Color& color, const Ray& ray,
                      const PrimaryInfo& info, const TraceCounters& tc, uint8_t state,
                      uint8_t flags) {
    PixelOut o = primaryPixel(index, color, info, tc, state, flags);
    o.hitBound = pointBound(ray, info);
    return o;
}

/// Grows a bounding sphere to contain `p` (conservative, centre kept).
glm::vec4 growBound(glm::vec4 b, const Vec3& p) {
    if (b.w < 0.0f) return glm::vec4(p, 0.0f);
    b.w = std::max(b.w, glm::length(p - Vec3(b)));
    return b;
}

}  // namespace

void RenderSession::processTile(const Plan& plan, const TileJob& job, PassCounters& counters) {
    thread_local std::vector<PixelOut> out;
    thread_local std::vector<ShadingRecord> records;
    thread_local std::vector<TreeSegment> segments;
    out.clear();
    records.clear();
    segments.clear();
    const CompiledScene& scene = *plan.scene;
    const CameraModel& camera = scene.camera();
    const WhittedIntegrator integrator(scene, plan.options);
    const PixelRect& r = job.rect;
    const int w = plan.width;
    std::size_t traced = 0;
    uint64_t rays = 0;
    // Camera rays of this tile test only what their cone can hit (bit-identical hits).
    RaySubset subset;
    cullTile(scene, r.x0, r.y0, r.x1, r.y1, subset);
    ShadingRecord sinkBuffer[kRecordsPerPixel];
    TreeSegment segmentBuffer[kSegmentsPerPixel];
    // Keeps a pixel's secondary segments for dirty marking; an overflow flags the tree unknown.
    auto keepSegments = [&](PixelOut& o, const SegmentSink& sink) {
        o.segmentOffset = uint32_t(segments.size());
        o.segmentCount = uint8_t(sink.count);
        segments.insert(segments.end(), sink.data, sink.data + sink.count);
        if (sink.overflow) o.flags |= kTreeUnknown;
    };

    // A full-quality centre sample: the Base pass, or an interactive pass at full quality.
    auto traceBase = [&](int x, int y, std::size_t i, uint8_t extraFlags) {
        TraceCounters tc;
        PrimaryInfo info;
        SegmentSink segSink{segmentBuffer, kSegmentsPerPixel, 0, false};
        const Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
        const Color c = integrator.traceCamera(ray, pixelSeed(x, y, 0), tc, &info, nullptr,
                                               &segSink, &subset);
        PixelOut o = primaryPixel(i, c, ray, info, tc, plan.spp == 1 ? kFinal : kBase,
                                  uint8_t((info.touchedSpecular ? kTouchedSpecular : 0) | extraFlags));
        o.base = c;
        keepSegments(o, segSink);
        out.push_back(o);
        rays += tc.total();
        ++traced;
    };

    // With a packet tracer, full-quality centre samples are collected and traced together.
    thread_local std::vector<int32_t> baseXs, baseYs;
    thread_local std::vector<uint8_t> baseFlags;
    thread_local std::vector<PacketPixel> basePixels;
    baseXs.clear();
    baseYs.clear();
    baseFlags.clear();
    auto requestBase = [&](int x, int y, std::size_t i, uint8_t extraFlags) {
        if (!plan.packets) return traceBase(x, y, i, extraFlags);
        baseXs.push_back(x);
        baseYs.push_back(y);
        baseFlags.push_back(extraFlags);
    };

    for (int y = r.y0; y < r.y1; ++y) {
        // Stale work stops within one row of an edit.
        if (generation_.load(std::memory_order_relaxed) != plan.generation) return;
        for (int x = r.x0; x < r.x1; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const uint8_t s = plan.state[i];
            if (plan.kind == PassKind::Interactive) {
                if (plan.step == 1) {
                    if (s != kStale) continue;
                    if (plan.interleaved && ((x + y + plan.parity) & 1)) continue;
                    if (plan.resultIsBase) {
                        requestBase(x, y, i, kTracedLastUpdate);
                        continue;
                    }
                    TraceCounters tc;
                    PrimaryInfo info;
                    RecordSink sink{sinkBuffer, kRecordsPerPixel, 0, false};
                    SegmentSink segSink{segmentBuffer, kSegmentsPerPixel, 0, false};
                    const Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
                    const Color c = integrator.traceCamera(ray, pixelSeed(x, y, 0), tc, &info,
                                                           plan.deferredRecords ? &sink : nullptr,
                                                           &segSink, &subset);
                    const bool complete = plan.deferredRecords && !sink.overflow;
                    PixelOut o = primaryPixel(
                        i, c, ray, info, tc, kInteractive,
                        uint8_t((info.touchedSpecular ? kTouchedSpecular : 0) | kTracedLastUpdate |
                                (complete ? kDeferredValid : 0)));
                    o.recordOffset = uint32_t(records.size());
                    o.recordCount = complete ? uint8_t(sink.count) : 0;
                    if (complete) records.insert(records.end(), sinkBuffer, sinkBuffer + sink.count);
                    keepSegments(o, segSink);
                    out.push_back(o);
                    rays += tc.total();
                    ++traced;
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
                TraceCounters tc;
                PrimaryInfo info;
                const Ray ray = camera.generateRay(0.5f * float(x + bx1), 0.5f * float(y + by1));
                const Color c = integrator.traceCamera(ray, pixelSeed(x, y, 0), tc, &info, nullptr,
                                                       nullptr, &subset);
                // One entry for the block; the commit writes it to every pixel of it.
                PixelOut o = primaryPixel(
                    std::size_t(y) * std::size_t(w) + std::size_t(x), c, ray, info, tc,
                    kInteractive,
                    uint8_t((info.touchedSpecular ? kTouchedSpecular | kTreeUnknown : 0) |
                            kTracedLastUpdate));
                o.spanX = uint8_t(bx1 - x);
                o.spanY = uint8_t(by1 - y);
                out.push_back(o);
                rays += tc.total();
                ++traced;
            } else if (plan.kind == PassKind::Base) {
                if (s >= kBase) continue;
                if (s == kInteractive && (plan.flags[i] & kDeferredValid)) {
                    // Deferred shadows: add the light terms at the stored shading points;
                    // camera and secondary rays are not traced again (thesis 3.3).
                    TraceCounters tc;
                    Color c = frame_.color[i];
                    const auto& pool = frame_.tileRecords[std::size_t(job.tile)];
                    const uint32_t start = frame_.recordStart[i];
                    for (uint32_t k = 0; k < frame_.recordCount[i]; ++k)
                        c += integrator.resolveDeferred(pool[start + k], tc);
                    PixelOut o{};
                    o.index = uint32_t(i);
                    o.color = o.base = c;
                    o.id = frame_.id[i];
                    o.depth = frame_.depth[i];
                    o.normal = frame_.normal[i];
                    o.cost = frame_.cost[i] + uint32_t(tc.total());
                    o.state = plan.spp == 1 ? kFinal : kBase;
                    o.flags = uint8_t(plan.flags[i] & (kTouchedSpecular | kTracedLastUpdate | kTreeUnknown));
                    o.hitBound = frame_.hitBound[i];
                    o.segmentMode = kKeep;
                    out.push_back(o);
                    rays += tc.total();
                    ++traced;
                } else {
                    requestBase(x, y, i, uint8_t(plan.flags[i] & kTracedLastUpdate));
                }
            } else {  // Supersample
                if (s != kBase) continue;
                PixelOut o{};
                o.index = uint32_t(i);
                o.base = frame_.base[i];
                o.id = frame_.id[i];
                o.depth = frame_.depth[i];
                o.normal = frame_.normal[i];
                o.flags = plan.flags[i];
                o.hitBound = frame_.hitBound[i];
                o.cost = frame_.cost[i];
                o.segmentMode = kKeep;
                if (!plan.needSupersampling[i]) {
                    o.color = o.base;
                    o.state = kFinal;
                    out.push_back(o);
                    continue;
                }
                SegmentSink segSink{segmentBuffer, kSegmentsPerPixel, 0, false};
                // Progressive: add up to sppChunk samples in the order renderPixel sums them,
                // so the final average is bit-identical to a full render's.
                Color sum = frame_.sampleSum[i];
                int count = frame_.sampleCount[i];
                const int end = std::min(plan.spp, count + plan.sppChunk);
                const uint32_t patternSeed = pixelSeed(x, y, 0x5eed);
                TraceCounters tc;
                for (int k = count; k < end; ++k) {
                    const Vec3 off = pixelSampleOffset(k, plan.spp, patternSeed);
                    const Ray ray = camera.generateRay(float(x) + off.x, float(y) + off.y);
                    PrimaryInfo info;
                    sum += integrator.traceCamera(ray, pixelSeed(x, y, k), tc, &info, nullptr,
                                                  &segSink, &subset);
                    if (info.id != kNoObject) o.hitBound = growBound(o.hitBound, ray.at(info.depth));
                    if (info.touchedSpecular) o.flags |= kTouchedSpecular;
                }
                count = end;
                keepSegments(o, segSink);
                o.segmentMode = kAppend;
                o.sampleSum = sum;
                o.sampleCount = uint16_t(count);
                o.color = count == plan.spp ? sum / float(plan.spp) : sum / float(count);
                o.state = count == plan.spp ? kFinal : kBase;
                o.cost += uint32_t(tc.total());
                out.push_back(o);
                rays += tc.total();
                ++traced;
            }
        }
    }

    if (!baseXs.empty()) {
        if (generation_.load(std::memory_order_relaxed) != plan.generation) return;
        basePixels.resize(baseXs.size());
        TraceCounters tc;
        plan.packets->tracePixels(baseXs.data(), baseYs.data(), baseXs.size(), subset,
                                  kSegmentsPerPixel, basePixels.data(), segments, tc);
        for (std::size_t k = 0; k < basePixels.size(); ++k) {
            const PacketPixel& p = basePixels[k];
            const int x = baseXs[k], y = baseYs[k];
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            TraceCounters cost;
            cost.rays = p.rays;
            PixelOut o = primaryPixel(
                i, p.color, p.info, cost, plan.spp == 1 ? kFinal : kBase,
                uint8_t((p.info.touchedSpecular ? kTouchedSpecular : 0) | baseFlags[k]));
            o.hitBound = p.info.id == kNoObject ? glm::vec4(0.0f, 0.0f, 0.0f, -1.0f)
                                                : glm::vec4(p.hitPoint, 0.0f);
            o.base = p.color;
            o.segmentOffset = p.segmentOffset;
            o.segmentCount = uint8_t(p.segmentCount);
            if (p.segmentOverflow) o.flags |= kTreeUnknown;
            out.push_back(o);
        }
        rays += tc.total();
        traced += basePixels.size();
    }

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
