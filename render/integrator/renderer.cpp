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

/// One full render: what its passes share (the kernel, the rows traced, pass 1's ids and
/// normals that pass 2 reads) and its steps.
class FullRender {
public:
    FullRender(const CompiledScene& scene, const RenderOptions& options)
        : options_(options),
          camera_(scene.camera()),
          kernel_(scene, TraceOptions::fromSettings(scene.settings())),
          w_(scene.settings().width),
          h_(scene.settings().height),
          spp_(std::max(1, scene.settings().supersampling)),
          adaptive_(scene.settings().adaptiveSupersampling && spp_ > 1),
          // The band asked for, and the rows traced in pass 1: adaptive decisions at the
          // band's edges compare with the rows next to it, so those are traced too (and
          // cropped at the end).
          r0_(std::clamp(options.firstRow, 0, h_)),
          r1_(options.endRow < 0 ? h_ : std::clamp(options.endRow, r0_, h_)),
          t0_(adaptive_ ? std::max(0, r0_ - 1) : r0_),
          t1_(adaptive_ ? std::min(h_, r1_ + 1) : r1_),
          cancelled_([this] {
              return options_.cancel && options_.cancel->load(std::memory_order_relaxed);
          }) {}

    RenderResult run() {
        // Pass 1 writes every pixel (tiles skipped on cancellation are cleared), so the
        // buffers are not cleared first: that would touch 15 MB at 1280x720 before any tracing.
        result_.image = ImageRgb::uninitialized(w_, t1_ - t0_);
        const std::size_t pixelCount = result_.image.pixels.size();
        // Adaptive supersampling reads the ids even when they are not asked for.
        if (options_.ids || adaptive_) ids_.resize(pixelCount);
        normals_.resize(adaptive_ ? pixelCount : 0);
        tbb::task_arena arena(options_.threads > 0 ? options_.threads
                                                   : tbb::info::default_concurrency());
        arenaExecute(arena, [&] {
            result_.cancelled =
                !forEachTile(w_, t0_, t1_, options_, result_.rays,
                             [&](int x0, int y0, int x1, int y1, TraceCounters& counters) {
                                 centreTile(x0, y0, x1, y1, counters);
                             });
            if (!adaptive_ || result_.cancelled) return;
            // Pass 2: supersample only where neighbours differ; decisions read pass 1's
            // image, so they are written to a copy.
            ImageRgb refined = result_.image;
            result_.cancelled =
                !forEachTile(w_, r0_, r1_, options_, result_.rays,
                             [&](int x0, int y0, int x1, int y1, TraceCounters& counters) {
                                 refineTile(x0, y0, x1, y1, refined, counters);
                             });
            result_.image = std::move(refined);
        });
        cropToBand();
        if (options_.ids) result_.ids = std::move(ids_);
        return std::move(result_);
    }

private:
    std::size_t index(int x, int y) const {
        return std::size_t(y - t0_) * std::size_t(w_) + std::size_t(x);
    }

    void clearTile(int x0, int x1, int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const std::size_t i = index(x, y);
                result_.image.pixels[i] = Color(0.0f);
                if (!ids_.empty()) ids_[i] = kNoObject;
            }
        }
    }

    /// Pass 1 of a tile: one centre sample per pixel (all the image needs without
    /// supersampling), or the full pattern when supersampling everywhere. Ids come from the
    /// centre ray.
    void centreTile(int x0, int y0, int x1, int y1, TraceCounters& counters) {
        // Each worker's tile buffers, in its huge-page scratch arena (a cold render would
        // otherwise fault them in 4 KiB at a time on its first tiles).
        thread_local ScratchVector<int32_t> xs, ys;
        thread_local ScratchVector<Vec3> origins, dirs;
        thread_local ScratchVector<uint32_t> seeds;
        thread_local ScratchVector<Color> colors;
        thread_local ScratchVector<PrimaryInfo> infos;
        thread_local ScratchVector<ObjectId> tileIds;
        if (cancelled_()) return clearTile(x0, x1, y0, y1);
        const std::size_t width = std::size_t(x1 - x0);
        const std::size_t n = width * std::size_t(y1 - y0);
        origins.resize(n), dirs.resize(n), seeds.resize(n), colors.resize(n);
        centreRays(x0, y0, x1, y1, origins.data(), dirs.data(), seeds.data());
        if (spp_ > 1 && !adaptive_)  // supersamplePixels takes the pixels as lists
            tilePixels(x0, y0, x1, y1, xs, ys, [](int, int) { return true; });
        const CameraBatch centres{origins.data(), dirs.data(), seeds.data(), n, true};
        bool done;
        if (spp_ == 1 || adaptive_) {
            TraceOutput out;
            out.color = colors.data();
            if (!ids_.empty()) {
                infos.resize(n);
                out.primary = infos.data();
            }
            done = kernel_.trace(centres, out, counters, cancelled_);
        } else {
            done = supersamplePixels(kernel_, xs.data(), ys.data(), n, spp_, colors.data(),
                                     counters, cancelled_);
            if (done && !ids_.empty()) {
                tileIds.resize(n);
                kernel_.firstHits(centres, tileIds.data());
                counters.rays += n;  // the id pass traces its centre rays too
                infos.resize(n);
                for (std::size_t k = 0; k < n; ++k) infos[k].id = tileIds[k];
            }
        }
        if (!done) return clearTile(x0, x1, y0, y1);
        for (int y = y0; y < y1; ++y) {
            const std::size_t row = std::size_t(y - y0) * width, i = index(x0, y);
            std::copy_n(colors.data() + row, width, result_.image.pixels.data() + i);
            if (!ids_.empty())
                for (std::size_t k = 0; k < width; ++k) ids_[i + k] = infos[row + k].id;
            if (adaptive_)
                for (std::size_t k = 0; k < width; ++k) normals_[i + k] = infos[row + k].normal;
        }
        if (options_.tileDone) options_.tileDone(result_.image, x0, y0 - t0_, x1, y1 - t0_);
    }

    /// The tile's centre rays row by row (row-major, as tilePixels lists them), with what
    /// depends on the column alone or on the row alone worked out once.
    void centreRays(int x0, int y0, int x1, int y1, Vec3* origins, Vec3* dirs,
                    uint32_t* seeds) const {
        thread_local ScratchVector<Vec3> columns;
        const std::size_t width = std::size_t(x1 - x0);
        columns.resize(width);
        for (int x = x0; x < x1; ++x)
            columns[std::size_t(x - x0)] = camera_.columnTerm(float(x) + 0.5f);
        const uint32_t centreKey = hashKey(0u);
        for (int y = y0; y < y1; ++y) {
            const std::size_t row = std::size_t(y - y0) * width;
            camera_.rowRays(columns.data(), width, float(y) + 0.5f, origins + row, dirs + row);
            const uint32_t rowKey = hashKey(uint32_t(y));
            for (int x = x0; x < x1; ++x)
                seeds[row + std::size_t(x - x0)] = pixelSeedKeyed(x, rowKey, centreKey);
        }
    }

    /// Pass 2 of a tile: the pixels whose neighbours differ in pass 1, supersampled into
    /// `refined`.
    void refineTile(int x0, int y0, int x1, int y1, ImageRgb& refined, TraceCounters& counters) {
        thread_local ScratchVector<int32_t> xs, ys;
        thread_local ScratchVector<Color> colors;
        if (cancelled_()) return;
        tilePixels(x0, y0, x1, y1, xs, ys, [&](int x, int y) {
            return needsSupersampling(result_.image.pixels.data(), ids_.data(), normals_.data(), w_,
                                      h_, x, y, t0_);
        });
        colors.resize(xs.size());
        if (!supersamplePixels(kernel_, xs.data(), ys.data(), xs.size(), spp_, colors.data(),
                               counters, cancelled_))
            return;
        for (std::size_t k = 0; k < xs.size(); ++k) refined.at(xs[k], ys[k] - t0_) = colors[k];
    }

    /// Drops the margin rows: only the band was asked for.
    void cropToBand() {
        if (t0_ == r0_ && t1_ == r1_) return;
        const std::size_t first = index(0, r0_), count = std::size_t(w_) * std::size_t(r1_ - r0_);
        ImageRgb band = ImageRgb::uninitialized(w_, r1_ - r0_);
        std::copy_n(result_.image.pixels.begin() + std::ptrdiff_t(first), count,
                    band.pixels.begin());
        result_.image = std::move(band);
        if (options_.ids)
            ids_ = std::vector<ObjectId>(ids_.begin() + std::ptrdiff_t(first),
                                         ids_.begin() + std::ptrdiff_t(first + count));
    }

    const RenderOptions& options_;
    const CameraModel& camera_;
    const TraceKernel kernel_;
    const int w_, h_, spp_;
    const bool adaptive_;
    const int r0_, r1_, t0_, t1_;
    const std::function<bool()> cancelled_;
    RenderResult result_;
    std::vector<ObjectId> ids_;
    std::vector<Vec3> normals_;
};

}  // namespace

RenderResult renderImage(const CompiledScene& scene, const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    RenderResult result = FullRender(scene, options).run();
    result.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace rs
