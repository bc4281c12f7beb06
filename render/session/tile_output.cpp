// Committing a tile's secondary ray segments into the frame's per-tile pools.
#include "session/tile_output.h"

#include <algorithm>

namespace rs {

namespace {

/// Rewrites tile `tile`'s pool with only the segments pixels still reference.
void compact(DeepFrame& frame, const PixelRect& r, int tile) {
    auto& pool = frame.tileSegments[std::size_t(tile)];
    std::vector<TreeSegment> fresh;
    fresh.reserve(frame.tileLiveSegments[std::size_t(tile)]);
    for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
            const std::size_t i = frame.index(x, y);
            const uint32_t start = frame.segmentStart[i];
            frame.segmentStart[i] = uint32_t(fresh.size());
            fresh.insert(fresh.end(), pool.begin() + start, pool.begin() + start + frame.segmentCount[i]);
        }
    }
    pool.swap(fresh);
}

}  // namespace

void commitSegments(DeepFrame& frame, const PixelRect& r, int tile, const std::vector<PixelOut>& out,
                    const std::vector<TreeSegment>& segments) {
    // Append-only: a written pixel's segments go to the end of the pool and its old ones
    // become garbage, so a commit costs what it writes, not the whole tile.
    auto& pool = frame.tileSegments[std::size_t(tile)];
    uint32_t& live = frame.tileLiveSegments[std::size_t(tile)];
    for (const PixelOut& o : out) {
        if (o.segmentMode == kKeep) continue;
        if (o.spanX != 1 || o.spanY != 1) {
            // An undersampled block: its pixels keep no segments.
            forEachWritten(o, frame.width, [&](std::size_t i) {
                live -= frame.segmentCount[i];
                frame.segmentStart[i] = uint32_t(pool.size());
                frame.segmentCount[i] = 0;
            });
            continue;
        }
        const std::size_t i = o.index;
        const uint32_t oldStart = frame.segmentStart[i], oldCount = frame.segmentCount[i];
        const uint32_t start = uint32_t(pool.size());
        if (o.segmentMode == kAppend)
            for (uint32_t k = 0; k < oldCount; ++k) pool.push_back(pool[oldStart + k]);
        pool.insert(pool.end(), segments.begin() + o.segmentOffset,
                    segments.begin() + o.segmentOffset + o.segmentCount);
        std::size_t count = pool.size() - start;
        if (count > 255) {  // Too many to index: forget them and always re-trace.
            pool.resize(start);
            count = 0;
            frame.flags[i] |= kTreeUnknown;
        }
        frame.segmentStart[i] = start;
        frame.segmentCount[i] = uint8_t(count);
        live = live - oldCount + uint32_t(count);
    }
    if (pool.size() > 2 * std::size_t(live) + 4096) compact(frame, r, tile);
    // Refresh the summaries of the blocks this tile wrote (each block once).
    uint32_t done = 0;  // Bit per block of the tile (a 32x32 tile holds 16 8x8 blocks).
    const int perRow = (r.x1 - r.x0 + DeepFrame::kBlock - 1) / DeepFrame::kBlock;
    for (const PixelOut& o : out) {
        forEachWritten(o, frame.width, [&](std::size_t i) {
            const int x = int(i % std::size_t(frame.width)), y = int(i / std::size_t(frame.width));
            const int bit =
                ((y - r.y0) / DeepFrame::kBlock) * perRow + (x - r.x0) / DeepFrame::kBlock;
            if (bit < 32 && (done >> bit) & 1u) return;
            if (bit < 32) done |= 1u << bit;
            frame.summarizeBlock(x, y);
        });
    }
}

}  // namespace rs
