// Internal to the session: what a tile writes back for one pixel, and the segment-pool commit.
#pragma once

#include "session/deep_frame.h"
#include "session/dirty_region.h"

#include <cstdint>
#include <vector>

namespace rs {

/// Everything a traced pixel writes back, to it and, for an undersampled pass, to the rest of
/// its spanX x spanY block (index is the block's top-left pixel).
struct PixelOut {
    uint32_t index;
    uint8_t spanX = 1, spanY = 1;
    Color color;
    Color base;
    Color sampleSum;
    uint16_t sampleCount;
    ObjectId id;
    float depth;
    Vec3 normal;
    uint32_t cost;
    uint8_t state;
    uint8_t flags;
    glm::vec4 hitBound;
    uint32_t recordOffset;  ///< Into the tile's local record list.
    uint8_t recordCount;
    uint32_t segmentOffset;  ///< Into the tile's local segment list.
    uint8_t segmentCount;
    uint8_t segmentMode;     ///< SegmentMode.
};

/// How a written pixel's secondary segments relate to the ones it had.
enum SegmentMode : uint8_t { kReplace = 0, kAppend = 1, kKeep = 2 };

/// Rebuilds tile `tile`'s segment pool: written pixels get their new segments (or keep or
/// extend their old ones), untouched pixels keep theirs; then refreshes the tile summary.
/// Block entries (span > 1) never carry segments.
void commitSegments(DeepFrame& frame, const PixelRect& r, int tile, const std::vector<PixelOut>& out,
                    const std::vector<TreeSegment>& segments);

/// Calls f(i) for each pixel index that `o` writes.
template <class F>
void forEachWritten(const PixelOut& o, int width, F&& f) {
    for (uint32_t dy = 0; dy < o.spanY; ++dy)
        for (uint32_t dx = 0; dx < o.spanX; ++dx)
            f(std::size_t(o.index) + std::size_t(dy) * std::size_t(width) + dx);
}

}  // namespace rs
