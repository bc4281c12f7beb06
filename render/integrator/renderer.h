// Full-frame rendering: tiles traced in parallel on oneTBB, with plain or adaptive supersampling.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "image/image.h"
#include "integrator/pixel_samples.h"
#include "integrator/sampling.h"
#include "integrator/whitted.h"
#include "snapshot/compiled_scene.h"

namespace rs {

class TraceKernel;

/// How to run a full render.
struct RenderOptions {
    int threads = 0;                            ///< Worker threads; 0 = all cores.
    int tileSize = 32;                          ///< Tile edge in pixels.
    const std::atomic<bool>* cancel = nullptr;  ///< Polled between ray-tree levels; may be null.
    /// While true, each worker waits before starting its next tile (the designer's viewport
    /// has the cores while the user edits); the image is the same. May be null.
    const std::atomic<bool>* hold = nullptr;
    /// Fill RenderResult::ids (picking); renders that only write an image leave it off.
    bool ids = true;
    /// Called (serialised) after each tile with tiles done and total; may be empty.
    std::function<void(int done, int total)> progress;
    /// Called from the worker that traced it (concurrently, not serialised) after the first
    /// pass wrote tile [x0, x1) x [y0, y1) of `image`, so a viewer can show the image filling
    /// in; other tiles of `image` are being written meanwhile. May be empty.
    std::function<void(const ImageRgb& image, int x0, int y0, int x1, int y1)> tileDone;
    /// Render only image rows [firstRow, endRow) (a part, image/image_part.h); endRow < 0
    /// means to the last row. Every pixel gets the value a whole-image render gives it: seeds
    /// depend on the pixel alone, and adaptive decisions read a one-row margin traced around
    /// the band. RenderResult's image and ids then hold the band's rows only, and tileDone's
    /// `image` and rows are those of the traced rows (margin included).
    int firstRow = 0;
    int endRow = -1;
};

/// A finished (or cancelled) render.
struct RenderResult {
    ImageRgb image;
    std::vector<ObjectId> ids;  ///< Object id seen through each pixel's centre (options.ids).
    uint64_t rays = 0;          ///< All rays traced, shadow rays included.
    double ms = 0.0;            ///< Wall time of the render, loading excluded.
    bool cancelled = false;     ///< Tiles not traced are black, with no ids.
};

/// The supersampled colour of one pixel: `spp` samples, those of PixelSamples.
Color renderPixel(const WhittedIntegrator& integrator, const CameraModel& camera, int x, int y,
                  int spp, TraceCounters& counters);

/// renderPixel's colours for pixels (xs[i], ys[i]) into out[i], traced as batches: every
/// sample of a group of pixels in one kernel call, each pixel summing its samples in order.
/// False when `stale` stopped the trace.
bool supersamplePixels(const TraceKernel& kernel, const int32_t* xs, const int32_t* ys,
                       std::size_t count, int spp, Color* out, TraceCounters& counters,
                       const std::function<bool()>& stale = {});

/// True when the 1-sample pixel at (x, y) differs from a neighbour in object id, normal or
/// colour enough to deserve adaptive supersampling. The buffers are `width` wide and start at
/// image row `bufferRow`; they must hold every row of the image within one of y (the image is
/// `height` rows; neighbours outside it are ignored).
bool needsSupersampling(const Color* colors, const ObjectId* ids, const Vec3* normals, int width,
                        int height, int x, int y, int bufferRow = 0);

/// Renders the whole image (or options' rows of it) at the scene's render settings.
RenderResult renderImage(const CompiledScene& scene, const RenderOptions& options = {});

}  // namespace rs
