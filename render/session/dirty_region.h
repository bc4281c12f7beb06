// Which pixels an edit can change (thesis 3.2), conservatively, so skipping the rest is exact.
#pragma once

#include "session/deep_frame.h"
#include "session/scene_update.h"
#include "snapshot/compiled_scene.h"

#include <vector>

namespace rs {

/// Screen rectangle [x0, x1) x [y0, y1) in pixels.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    int area() const { return empty() ? 0 : (x1 - x0) * (y1 - y0); }
};

/// Pixels whose samples can see into `box`: the projected corners' bounding rectangle grown
/// by a pixel; the whole image when the box reaches behind the camera.
PixelRect screenFootprint(const CameraModel& camera, const Aabb& box);

/// Which of an edit's effects markDirtyPixels looks for.
enum class MarkScope {
    All,
    /// Everything but shadows: while dragging with shadows off or deferred, a shadow the
    /// object casts is not shown anyway, so those pixels wait until release (thesis 3.3).
    WithoutShadows,
    /// Only pixels whose shadow rays (from first or later hits) can cross the edit's regions:
    /// what WithoutShadows left for the release.
    ShadowsOnly,
};

/// How much of the frame one marking looked at (the session's statistics, and tests that
/// check the work follows the edit, not the frame).
struct MarkStats {
    std::size_t blocksTested = 0;  ///< Blocks tested against their summaries (their tile passed).
    std::size_t blocksGrown = 0;   ///< Blocks visited to grow the marks by a pixel.
    /// Pixels tested one by one, and pixels grown by looking at their neighbours: blocks that
    /// lie wholly inside a footprint are marked and grown whole, without either.
    std::size_t pixelsTested = 0;
    std::size_t pixelsGrown = 0;
};

/// Sets mask[i] = 1 for every pixel `edit` can change, given the frame as it was traced under
/// `before`: the old and new footprints, pixels whose ray tree met a mirror or glass, pixels
/// showing a retinted object (any supersampled pixel, whose samples may have seen it), and,
/// when shadows are traced, pixels whose shadow rays can cross
/// the old or new bounds. Grown by one pixel so adaptive supersampling decisions stay exact.
/// Runs in parallel; returns the number of pixels marked. `touchedBlocks` (optional) gets 1
/// for every 8x8 block in which the mask may be non-zero, so callers can skip the others.
/// Tiles are tested by their summaries first, then the blocks of those that pass: the work
/// follows the edit's reach, not the frame's size (`stats`, optional, says how much).
std::size_t markDirtyPixels(const SceneEdit& edit, const CompiledScene& after,
                            const DeepFrame& frame, std::vector<uint8_t>& mask,
                            std::vector<uint8_t>* touchedBlocks = nullptr,
                            MarkScope scope = MarkScope::All, MarkStats* stats = nullptr);

}  // namespace rs
