// Which pixels an edit can change (thesis 3.2), conservatively, so skipping the rest is exact.
#pragma once

#include <cstdint>
#include <vector>

#include "session/frame/deep_frame.h"
#include "session/frame/pixel_rect.h"
#include "session/scene_update.h"
#include "snapshot/compiled_scene.h"

namespace rs {

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

/// An edit's marks, kept from one marking to the next so that each marking clears only the
/// blocks the previous one wrote instead of the whole frame (a frame-sized clear per drag
/// step was most of what marking cost when the edit reached a few blocks).
struct DirtyMask {
    int width = 0, height = 0;  ///< The frame the marks are for.
    /// One byte a pixel, row-major like the frame: 1 where the edit may change the pixel.
    /// Zero outside the blocks of `blocks`.
    std::vector<uint8_t> pixels;
    /// One byte an 8x8 block of the frame: 1 for the blocks in `blocks`.
    std::vector<uint8_t> touched;
    /// The blocks in which `pixels` may be non-zero, in increasing order.
    std::vector<int> blocks;
};

/// Grows marks by one pixel into the 8x8 block whose top-left pixel is (x0, y0): out[i] = 1
/// where pixel i or one of its 8 neighbours is marked in `core` (bytes 0 or 1; both buffers
/// width x height, row-major), else 0, for the block's pixels. Returns how many it marked.
/// Whole block rows go eight pixels a word; a block cut by the frame's right edge, pixel by
/// pixel.
std::size_t growBlockMarks(const uint8_t* core, int width, int height, int x0, int y0,
                           uint8_t* out);

/// Sets mask.pixels[i] = 1 for every pixel `edit` can change, given the frame as it was
/// traced under `before`, and 0 for every other: the old and new footprints, pixels whose ray
/// tree met a mirror or glass, pixels showing a retinted object (any supersampled pixel, whose
/// samples may have seen it), and, when shadows are traced, pixels whose shadow rays can cross
/// the old or new bounds. Grown by one pixel so adaptive supersampling decisions stay exact.
/// Runs in parallel; returns the number of pixels marked. mask.blocks gets every 8x8 block in
/// which a mark may lie, so callers can skip the others; the previous marking's blocks are
/// cleared first (the whole mask when it was for another frame size).
/// Tiles are tested by their summaries first, then the blocks of those that pass: the work
/// follows the edit's reach, not the frame's size (`stats`, optional, says how much).
std::size_t markDirtyPixels(const SceneEdit& edit, const CompiledScene& after,
                            const DeepFrame& frame, DirtyMask& mask,
                            MarkScope scope = MarkScope::All, MarkStats* stats = nullptr);

}  // namespace rs
