// Full-frame rendering: tiles traced in parallel on oneTBB, with plain or adaptive supersampling.
#pragma once

#include "image/image.h"
#include "integrator/sampling.h"
#include "integrator/whitted.h"
#include "snapshot/compiled_scene.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace rs {

/// How to run a full render.
struct RenderOptions {
    int threads = 0;    ///< Worker threads; 0 = all cores.
    int tileSize = 32;  ///< Tile edge in pixels.
    const std::atomic<bool>* cancel = nullptr;  ///< Polled once per row; may be null.
    /// Fill RenderResult::ids (picking); renders that only write an image leave it off.
    bool ids = true;
    /// Trace with PacketTracer where it applies and pays (same bits either way); off forces
    /// the scalar integrator, for tests and for measuring the difference.
    bool packets = true;
    /// Called (serialised) after each tile with tiles done and total; may be empty.
    std::function<void(int done, int total)> progress;
};

/// A finished (or cancelled) render.
struct RenderResult {
    ImageRgb image;
    std::vector<ObjectId> ids;  ///< Object id seen through each pixel's centre (options.ids).
    uint64_t rays = 0;          ///< All rays traced, shadow rays included.
    double ms = 0.0;            ///< Wall time of the render, loading excluded.
    bool cancelled = false;  ///< Tiles not traced are black, with no ids.
};

/// Seed of sample `k` of pixel (x, y): depends on the pixel alone, not on tiles or threads.
inline uint32_t pixelSeed(int x, int y, int k) {
    return hashCombine(hashCombine(uint32_t(x), uint32_t(y)), uint32_t(k));
}

/// The supersampled colour of one pixel: `spp` samples on the pattern of pixelSampleOffset.
/// `subset` (cullTile of a tile holding the pixel) may narrow the camera rays' tests.
Color renderPixel(const WhittedIntegrator& integrator, const CameraModel& camera, int x, int y,
                  int spp, TraceCounters& counters, const RaySubset* subset = nullptr);

/// What the camera rays through pixels [x0, x1) x [y0, y1) can hit (an invalid subset, which
/// tests everything, for an orthographic camera or a scene too large to list).
void cullTile(const CompiledScene& scene, int x0, int y0, int x1, int y1, RaySubset& subset);

/// True when the 1-sample pixel at (x, y) differs from a neighbour in object id, normal or
/// colour enough to deserve adaptive supersampling.
bool needsSupersampling(const Color* colors, const ObjectId* ids, const Vec3* normals, int width,
                        int height, int x, int y);

/// Renders the whole image at the scene's render settings.
RenderResult renderImage(const CompiledScene& scene, const RenderOptions& options = {});

}  // namespace rs
