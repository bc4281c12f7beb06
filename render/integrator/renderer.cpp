// Tile scheduling for full renders and the per-pixel sampling they share with the session.
#include "integrator/renderer.h"

#include <tbb/blocked_range2d.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <thread>

#include "core/parallel.h"
#include "core/scratch_arena.h"
#include "integrator/sampling.h"
#include "integrator/trace_kernel.h"

namespace rs {

namespace {
/// Camera rays handed to the kernel per call when supersampling (a bounded working set).
constexpr std::size_t kSampleBatch = 4096;
}  // namespace

Color renderPixel(const WhittedIntegrator& integrator, const CameraModel& camera, int x, int y,
                  int spp, TraceCounters& counters) {
    if (spp <= 1) {
        Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
        return integrator.traceCamera(ray, pixelSeed(x, y, 0), counters);
    }
    Color sum(0.0f);
    const PixelSamples samples(x, y, spp);
    for (int k = 0; k < spp; ++k)
        sum += integrator.traceCamera(samples.ray(camera, k), samples.seed(k), counters);
    return sum / float(spp);
}

bool supersamplePixels(const TraceKernel& kernel, const int32_t* xs, const int32_t* ys,
                       std::size_t count, int spp, Color* out, TraceCounters& counters,
                       const std::function<bool()>& stale) {
    thread_local ScratchVector<Vec3> origins, dirs;
    thread_local ScratchVector<uint32_t> seeds;
    thread_local ScratchVector<Color> colors;
    const CameraModel& camera = kernel.scene().camera();
    const std::size_t perCall = std::max<std::size_t>(1, kSampleBatch / std::size_t(spp));
    for (std::size_t first = 0; first < count; first += perCall) {
        const std::size_t n = std::min(perCall, count - first);
        origins.clear(), dirs.clear(), seeds.clear();
        for (std::size_t i = first; i < first + n; ++i) {
            const PixelSamples samples(xs[i], ys[i], spp);
            for (int k = 0; k < spp; ++k) {
                const Ray ray = samples.ray(camera, k);
                origins.push_back(ray.origin);
                dirs.push_back(ray.dir);
                seeds.push_back(samples.seed(k));
            }
        }
        colors.resize(origins.size());
        TraceOutput result;
        result.color = colors.data();
        if (!kernel.trace(
                CameraBatch{origins.data(), dirs.data(), seeds.data(), origins.size(), true},
                result, counters, stale))
            return false;
        // Each pixel adds its samples in order k = 0, 1, ... as renderPixel does.
        for (std::size_t j = 0; j < n; ++j) {
            Color sum(0.0f);
            for (int k = 0; k < spp; ++k) sum += colors[j * std::size_t(spp) + std::size_t(k)];
            out[first + j] = sum / float(spp);
        }
    }
    return true;
}

bool needsSupersampling(const Color* colors, const ObjectId* ids, const Vec3* normals, int width,
                        int height, int x, int y, int bufferRow) {
    constexpr float kNormalCos = 0.95f;
    constexpr float kColorDelta = 0.1f;
    const std::size_t w = std::size_t(width);
    const std::size_t i = std::size_t(y - bufferRow) * w + std::size_t(x);
    const Color c = glm::min(colors[i], Color(1.0f));
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
            const std::size_t j = std::size_t(ny - bufferRow) * w + std::size_t(nx);
            if (ids[j] != ids[i]) return true;
            if (glm::dot(normals[j], normals[i]) < kNormalCos) return true;
            const Color d = glm::abs(glm::min(colors[j], Color(1.0f)) - c);
            if (std::max(d.x, std::max(d.y, d.z)) > kColorDelta) return true;
        }
    }
    return false;
}

namespace {

/// Waits while `options.hold` is set (and the render is not cancelled).
void waitWhileHeld(const RenderOptions& options) {
    while (options.hold && options.hold->load(std::memory_order_relaxed) &&
           !(options.cancel && options.cancel->load(std::memory_order_relaxed)))
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

/// Runs `body(x0, y0, x1, y1, counters)` over all tiles of rows [rowBegin, rowEnd) in
/// parallel, with cancellation and progress; returns false when cancelled.
template <class Body>
bool forEachTile(int width, int rowBegin, int rowEnd, const RenderOptions& options, uint64_t& rays,
                 Body&& body) {
    const int ts = std::max(1, options.tileSize);
    const int tilesX = (width + ts - 1) / ts, tilesY = (rowEnd - rowBegin + ts - 1) / ts;
    const int total = tilesX * tilesY;
    std::atomic<int> done{0};
    std::atomic<uint64_t> rayCount{0};
    std::mutex progressMutex;
    parallelFor(tbb::blocked_range2d<int>(0, tilesY, 1, 0, tilesX, 1), [&](const auto& r) {
        for (int ty = r.rows().begin(); ty != r.rows().end(); ++ty) {
            for (int tx = r.cols().begin(); tx != r.cols().end(); ++tx) {
                waitWhileHeld(options);
                TraceCounters counters;
                const int x0 = tx * ts, y0 = rowBegin + ty * ts;
                body(x0, y0, std::min(width, x0 + ts), std::min(rowEnd, y0 + ts), counters);
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

/// A tile's pixels as lists (row-major), optionally only those `pick` selects.
template <class Pick>
void tilePixels(int x0, int y0, int x1, int y1, ScratchVector<int32_t>& xs,
                ScratchVector<int32_t>& ys, Pick&& pick) {
    xs.clear();
    ys.clear();
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            if (pick(x, y)) xs.push_back(x), ys.push_back(y);
}

}  // namespace

RenderResult renderImage(const CompiledScene& scene, const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const RenderSettings& settings = scene.settings();
    const int w = settings.width, h = settings.height;
    const int spp = std::max(1, settings.supersampling);
    const bool adaptive = settings.adaptiveSupersampling && spp > 1;
    const CameraModel& camera = scene.camera();
    const TraceKernel kernel(scene, TraceOptions::fromSettings(settings));
    // The band asked for, and the rows traced in pass 1: adaptive decisions at the band's
    // edges compare with the rows next to it, so those are traced too (and cropped at the end).
    const int r0 = std::clamp(options.firstRow, 0, h);
    const int r1 = options.endRow < 0 ? h : std::clamp(options.endRow, r0, h);
    const int t0 = adaptive ? std::max(0, r0 - 1) : r0;
    const int t1 = adaptive ? std::min(h, r1 + 1) : r1;
    auto index = [&](int x, int y) {
        return std::size_t(y - t0) * std::size_t(w) + std::size_t(x);
    };
    const std::function<bool()> cancelled = [&] {
        return options.cancel && options.cancel->load(std::memory_order_relaxed);
    };

    // Pass 1 writes every pixel (tiles skipped on cancellation are cleared), so the buffers
    // are not cleared first: that would touch 15 MB at 1280x720 before any tracing.
    RenderResult result;
    result.image = ImageRgb::uninitialized(w, t1 - t0);
    const std::size_t pixelCount = result.image.pixels.size();
    std::vector<ObjectId> ids;  // adaptive supersampling reads them even when not asked for
    if (options.ids || adaptive) ids.resize(pixelCount);
    std::vector<Vec3> normals(adaptive ? pixelCount : 0);
    auto clearTile = [&](int x0, int x1, int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const std::size_t i = index(x, y);
                result.image.pixels[i] = Color(0.0f);
                if (!ids.empty()) ids[i] = kNoObject;
            }
        }
    };

    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::info::default_concurrency());
    arenaExecute(arena, [&] {
        // Pass 1: one centre sample per pixel (all the image needs without supersampling), or
        // the full pattern when supersampling everywhere. Ids come from the centre ray.
        result.cancelled = !forEachTile(
            w, t0, t1, options, result.rays,
            [&](int x0, int y0, int x1, int y1, TraceCounters& counters) {
                // Each worker's tile buffers, in its huge-page scratch arena (a cold render
                // would otherwise fault them in 4 KiB at a time on its first tiles).
                thread_local ScratchVector<int32_t> xs, ys;
                thread_local ScratchVector<Vec3> columns, origins, dirs;
                thread_local ScratchVector<uint32_t> seeds;
                thread_local ScratchVector<Color> colors;
                thread_local ScratchVector<PrimaryInfo> infos;
                thread_local ScratchVector<ObjectId> tileIds;
                if (cancelled()) return clearTile(x0, x1, y0, y1);
                // The centre rays row by row (row-major, as tilePixels lists them), with what
                // depends on the column alone or on the row alone worked out once.
                const std::size_t width = std::size_t(x1 - x0);
                const std::size_t n = width * std::size_t(y1 - y0);
                columns.resize(width);
                origins.resize(n), dirs.resize(n), seeds.resize(n), colors.resize(n);
                for (int x = x0; x < x1; ++x)
                    columns[std::size_t(x - x0)] = camera.columnTerm(float(x) + 0.5f);
                const uint32_t centreKey = hashKey(0u);
                for (int y = y0; y < y1; ++y) {
                    const std::size_t row = std::size_t(y - y0) * width;
                    camera.rowRays(columns.data(), width, float(y) + 0.5f, origins.data() + row,
                                   dirs.data() + row);
                    const uint32_t rowKey = hashKey(uint32_t(y));
                    for (int x = x0; x < x1; ++x)
                        seeds[row + std::size_t(x - x0)] = pixelSeedKeyed(x, rowKey, centreKey);
                }
                if (spp > 1 && !adaptive)  // supersamplePixels takes the pixels as lists
                    tilePixels(x0, y0, x1, y1, xs, ys, [](int, int) { return true; });
                const CameraBatch centres{origins.data(), dirs.data(), seeds.data(), n, true};
                bool done;
                if (spp == 1 || adaptive) {
                    TraceOutput out;
                    out.color = colors.data();
                    if (!ids.empty()) {
                        infos.resize(n);
                        out.primary = infos.data();
                    }
                    done = kernel.trace(centres, out, counters, cancelled);
                } else {
                    done = supersamplePixels(kernel, xs.data(), ys.data(), n, spp, colors.data(),
                                             counters, cancelled);
                    if (done && !ids.empty()) {
                        tileIds.resize(n);
                        kernel.firstHits(centres, tileIds.data());
                        counters.rays += n;  // the id pass traces its centre rays too
                        infos.resize(n);
                        for (std::size_t k = 0; k < n; ++k) infos[k].id = tileIds[k];
                    }
                }
                if (!done) return clearTile(x0, x1, y0, y1);
                for (int y = y0; y < y1; ++y) {
                    const std::size_t row = std::size_t(y - y0) * width, i = index(x0, y);
                    std::copy_n(colors.data() + row, width, result.image.pixels.data() + i);
                    if (!ids.empty())
                        for (std::size_t k = 0; k < width; ++k) ids[i + k] = infos[row + k].id;
                    if (adaptive)
                        for (std::size_t k = 0; k < width; ++k)
                            normals[i + k] = infos[row + k].normal;
                }
                if (options.tileDone) options.tileDone(result.image, x0, y0 - t0, x1, y1 - t0);
            });
        if (!adaptive || result.cancelled) return;
        // Pass 2: supersample only where neighbours differ; decisions read pass 1's image,
        // so they are written to a copy.
        ImageRgb refined = result.image;
        result.cancelled =
            !forEachTile(w, r0, r1, options, result.rays,
                         [&](int x0, int y0, int x1, int y1, TraceCounters& counters) {
                             thread_local ScratchVector<int32_t> xs, ys;
                             thread_local ScratchVector<Color> colors;
                             if (cancelled()) return;
                             tilePixels(x0, y0, x1, y1, xs, ys, [&](int x, int y) {
                                 return needsSupersampling(result.image.pixels.data(), ids.data(),
                                                           normals.data(), w, h, x, y, t0);
                             });
                             colors.resize(xs.size());
                             if (!supersamplePixels(kernel, xs.data(), ys.data(), xs.size(), spp,
                                                    colors.data(), counters, cancelled))
                                 return;
                             for (std::size_t k = 0; k < xs.size(); ++k)
                                 refined.at(xs[k], ys[k] - t0) = colors[k];
                         });
        result.image = std::move(refined);
    });
    if (t0 != r0 || t1 != r1) {  // drop the margin rows: only the band was asked for
        const std::size_t first = index(0, r0), count = std::size_t(w) * std::size_t(r1 - r0);
        ImageRgb band = ImageRgb::uninitialized(w, r1 - r0);
        std::copy_n(result.image.pixels.begin() + std::ptrdiff_t(first), count,
                    band.pixels.begin());
        result.image = std::move(band);
        if (options.ids)
            ids = std::vector<ObjectId>(ids.begin() + std::ptrdiff_t(first),
                                        ids.begin() + std::ptrdiff_t(first + count));
    }
    if (options.ids) result.ids = std::move(ids);
    result.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace rs
