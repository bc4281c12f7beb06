// Tile scheduling for full renders and the per-pixel sampling they share with the session.
#include "integrator/renderer.h"

#include "core/parallel.h"
#include "integrator/packet_tracer.h"
#include "integrator/sampling.h"

#include <tbb/blocked_range2d.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <mutex>

namespace rs {

Color renderPixel(const WhittedIntegrator& integrator, const CameraModel& camera, int x, int y,
                  int spp, TraceCounters& counters, const RaySubset* subset) {
    if (spp <= 1) {
        Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
        return integrator.traceCamera(ray, pixelSeed(x, y, 0), counters, nullptr, nullptr,
                                      nullptr, subset);
    }
    Color sum(0.0f);
    const uint32_t patternSeed = pixelSeed(x, y, 0x5eed);
    for (int k = 0; k < spp; ++k) {
        Vec3 o = pixelSampleOffset(k, spp, patternSeed);
        Ray ray = camera.generateRay(float(x) + o.x, float(y) + o.y);
        sum += integrator.traceCamera(ray, pixelSeed(x, y, k), counters, nullptr, nullptr,
                                      nullptr, subset);
    }
    return sum / float(spp);
}

bool needsSupersampling(const Color* colors, const ObjectId* ids, const Vec3* normals, int width,
                        int height, int x, int y) {
    constexpr float kNormalCos = 0.95f;
    constexpr float kColorDelta = 0.1f;
    const std::size_t w = std::size_t(width);
    const std::size_t i = std::size_t(y) * w + std::size_t(x);
    const Color c = glm::min(colors[i], Color(1.0f));
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
            const std::size_t j = std::size_t(ny) * w + std::size_t(nx);
            if (ids[j] != ids[i]) return true;
            if (glm::dot(normals[j], normals[i]) < kNormalCos) return true;
            const Color d = glm::abs(glm::min(colors[j], Color(1.0f)) - c);
            if (std::max(d.x, std::max(d.y, d.z)) > kColorDelta) return true;
        }
    }
    return false;
}

void cullTile(const CompiledScene& scene, int x0, int y0, int x1, int y1, RaySubset& subset) {
    Vec3 axis;
    float halfAngle;
    if (scene.camera().tileCone(x0, y0, x1, y1, axis, halfAngle))
        scene.cull(scene.camera().origin(), axis, halfAngle, subset);
    else
        subset = RaySubset{};
}

namespace {

/// Runs `body(x0, y0, x1, y1, counters)` over all tiles in parallel, with cancellation and
/// progress; returns false when cancelled.
template <class Body>
bool forEachTile(int width, int height, const RenderOptions& options, uint64_t& rays,
                 Body&& body) {
    const int ts = std::max(1, options.tileSize);
    const int tilesX = (width + ts - 1) / ts, tilesY = (height + ts - 1) / ts;
    const int total = tilesX * tilesY;
    std::atomic<int> done{0};
    std::atomic<uint64_t> rayCount{0};
    std::mutex progressMutex;
    parallelFor(
        tbb::blocked_range2d<int>(0, tilesY, 1, 0, tilesX, 1), [&](const auto& r) {
            for (int ty = r.rows().begin(); ty != r.rows().end(); ++ty) {
                for (int tx = r.cols().begin(); tx != r.cols().end(); ++tx) {
                    TraceCounters counters;
                    const int x0 = tx * ts, y0 = ty * ts;
                    body(x0, y0, std::min(width, x0 + ts), std::min(height, y0 + ts), counters);
                    rayCount.fetch_add(counters.total(), std::memory_order_relaxed);
                    const int d = done.fetch_add(1) + 1;
                    if (options.progress) {
                        std::lock_guard lock(progressMutex);
                        options.progress(d, total);
                    }
                }
            }
        });
    rays += rayCount.load();
    return !(options.cancel && options.cancel->load(std::memory_order_relaxed));
}

}  // namespace

RenderResult renderImage(const CompiledScene& scene, const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const RenderSettings& settings = scene.settings();
    const int w = settings.width, h = settings.height;
    const int spp = std::max(1, settings.supersampling);
    const bool adaptive = settings.adaptiveSupersampling && spp > 1;
    const CameraModel& camera = scene.camera();
    const WhittedIntegrator integrator(scene);
    auto cancelled = [&] { return options.cancel && options.cancel->load(std::memory_order_relaxed); };

    // Pass 1 writes every pixel (tiles skipped on cancellation are cleared), so the buffers
    // are not cleared first: that would touch 15 MB at 1280x720 before any tracing.
    RenderResult result;
    result.image = ImageRgb::uninitialized(w, h);
    const std::size_t pixelCount = std::size_t(w) * std::size_t(h);
    std::vector<ObjectId> ids;  // adaptive supersampling reads them even when not asked for
    if (options.ids || adaptive) ids.resize(pixelCount);
    std::vector<Vec3> normals(adaptive ? pixelCount : 0);
    auto clearRows = [&](int x0, int x1, int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                result.image.pixels[i] = Color(0.0f);
                if (!ids.empty()) ids[i] = kNoObject;
            }
        }
    };

    // Packet tracing of supersampled pixels: all pixels of a tile (pass 1 without adaptive
    // supersampling, with the centre rays' ids), or those `pick` selects (adaptive pass 2).
    auto supersampleTile = [&](const PacketTracer& tracer, int x0, int y0, int x1, int y1,
                               const RaySubset& subset, TraceCounters& counters,
                               ImageRgb* into = nullptr,
                               const std::function<bool(int, int)>& pick = {}) {
        thread_local std::vector<int32_t> xs, ys;
        thread_local std::vector<Color> colors;
        xs.clear();
        ys.clear();
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                if (!pick || pick(x, y)) xs.push_back(x), ys.push_back(y);
        colors.resize(xs.size());
        tracer.traceSamples(xs.data(), ys.data(), xs.size(), spp, subset, colors.data(), counters);
        ImageRgb& image = into ? *into : result.image;
        for (std::size_t k = 0; k < xs.size(); ++k) image.at(xs[k], ys[k]) = colors[k];
        if (into || ids.empty()) return;
        thread_local std::vector<ObjectId> tileIds;
        tileIds.resize(xs.size());
        tracer.firstHits(xs.data(), ys.data(), xs.size(), subset, tileIds.data());
        for (std::size_t k = 0; k < xs.size(); ++k)
            ids[std::size_t(ys[k]) * std::size_t(w) + std::size_t(xs[k])] = tileIds[k];
    };

    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::info::default_concurrency());
    arenaExecute(arena, [&] {
        // Pass 1: one centre sample per pixel (all the image needs without supersampling), or
        // the full pattern when supersampling everywhere. Ids come from the centre ray.
        const bool packets =
            options.packets && PacketTracer::profitable() && PacketTracer::supports(scene);
        const PacketTracer packetTracer(scene);
        result.cancelled = !forEachTile(w, h, options, result.rays,
            [&](int x0, int y0, int x1, int y1, TraceCounters& counters) {
                RaySubset subset;
                cullTile(scene, x0, y0, x1, y1, subset);
                if (packets) {
                    // The same bits as the loop below, eight rays at a time.
                    if (cancelled())
                        clearRows(x0, x1, y0, y1);
                    else if (spp == 1 || adaptive)
                        packetTracer.traceTile(x0, y0, x1, y1, subset, std::size_t(w),
                                               result.image.pixels.data(),
                                               ids.empty() ? nullptr : ids.data(),
                                               adaptive ? normals.data() : nullptr, counters);
                    else
                        supersampleTile(packetTracer, x0, y0, x1, y1, subset, counters);
                    return;
                }
                int y = y0;
                for (; y < y1 && !cancelled(); ++y) {
                    for (int x = x0; x < x1; ++x) {
                        const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                        PrimaryInfo info;
                        Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
                        if (spp == 1 || adaptive) {
                            result.image.pixels[i] = integrator.traceCamera(
                                ray, pixelSeed(x, y, 0), counters, &info, nullptr, nullptr, &subset);
                        } else {
                            info = PrimaryInfo{};
                            SurfaceHit hit;
                            if (scene.intersect(ray, 0.0f, kInfinity, hit, &subset)) info.id = hit.id;
                            result.image.pixels[i] =
                                renderPixel(integrator, camera, x, y, spp, counters, &subset);
                        }
                        if (!ids.empty()) ids[i] = info.id;
                        if (adaptive) normals[i] = info.normal;
                    }
                }
                clearRows(x0, x1, y, y1);
            });
        if (!adaptive || result.cancelled) {
            if (options.ids) result.ids = std::move(ids);
            return;
        }
        // Pass 2: supersample only where neighbours differ; decisions read pass 1's image,
        // so they are written to a copy.
        ImageRgb refined = result.image;
        result.cancelled = !forEachTile(w, h, options, result.rays,
            [&](int x0, int y0, int x1, int y1, TraceCounters& counters) {
                RaySubset subset;
                cullTile(scene, x0, y0, x1, y1, subset);
                if (packets) {
                    if (cancelled()) return;
                    supersampleTile(packetTracer, x0, y0, x1, y1, subset, counters, &refined,
                                    [&](int x, int y) {
                                        return needsSupersampling(result.image.pixels.data(),
                                                                  ids.data(), normals.data(), w,
                                                                  h, x, y);
                                    });
                    return;
                }
                for (int y = y0; y < y1 && !cancelled(); ++y)
                    for (int x = x0; x < x1; ++x)
                        if (needsSupersampling(result.image.pixels.data(), ids.data(),
                                               normals.data(), w, h, x, y))
                            refined.at(x, y) =
                                renderPixel(integrator, camera, x, y, spp, counters, &subset);
            });
        result.image = std::move(refined);
        if (options.ids) result.ids = std::move(ids);
    });
    result.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
    return result;
}

}  // namespace rs
