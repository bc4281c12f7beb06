// Internal to the session: what one pass will do, decided under the lock, run without it.
#pragma once

#include <atomic>
#include <memory>
#include <vector>

#include "integrator/trace_kernel.h"
#include "session/dirty_region.h"
#include "session/session_observer.h"
#include "snapshot/compiled_scene.h"

namespace rs {

/// Totals of a pass, added to by every tile.
struct PassCounters {
    std::atomic<std::size_t> pixels{0};
    std::atomic<uint64_t> rays{0};
};

/// One tile of a pass.
struct TileJob {
    PixelRect rect;
    int tile = 0;
};

/// A pass: its kind, the snapshot and options it traces with, and its tiles. Workers read
/// each tile's pixel states from the frame itself: edits change states only between passes
/// (they are applied on the scheduler thread, which runs the pass), and a tile's pixels are
/// written only by that tile's commit, after it has read them.
struct PassPlan {
    PassKind kind = PassKind::Base;
    uint64_t generation = 0;
    int width = 0, height = 0;
    std::shared_ptr<const CompiledScene> scene;  ///< Traced (a box proxy while moving).
    TraceOptions options;
    bool deferredRecords = false;  ///< Interactive pass whose records complete each pixel.
    bool resultIsBase = false;     ///< Interactive pass that is in fact full quality.
    int step = 1;                  ///< Undersampling block size.
    bool interleaved = false;
    int parity = 0;
    int spp = 1;           ///< The scene's supersampling.
    int sppChunk = 4;      ///< Samples added per supersampling pass.
    bool adaptive = true;  ///< Supersample only where neighbours differ.
    std::vector<TileJob> tiles;
    int governorLevel = -1;
    /// The kernel every tile traces through (of `scene` with `options`), built once a pass.
    std::unique_ptr<const TraceKernel> kernel;

    /// Back to a default plan, keeping the tile list's storage.
    void reset() {
        std::vector<TileJob> keepTiles = std::move(tiles);
        *this = PassPlan{};
        keepTiles.clear();
        tiles = std::move(keepTiles);
    }
};

}  // namespace rs
