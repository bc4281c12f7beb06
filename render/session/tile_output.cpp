// Committing a tile's secondary ray segments into the frame's per-tile pools.
#include "session/tile_output.h"

namespace rs {

/// Rebuilds tile `tile`'s segment pool: written pixels get their new segments (or keep or
/// extend their old ones), untouched pixels keep theirs; then refreshes the tile summary.
void commitSegments(DeepFrame& frame, const PixelRect& r, int tile, const std::vector<PixelOut>& out,
                    const std::vector<TreeSegment>& segments) {
    thread_local std::vector<int> written;
    const int rw = r.x1 - r.x0;
    written.assign(std::size_t(rw) * std::size_t(r.y1 - r.y0), -1);
    for (std::size_t k = 0; k < out.size(); ++k) {
        const int px = int(out[k].index % uint32_t(frame.width));
        const int py = int(out[k].index / uint32_t(frame.width));
        written[std::size_t(py - r.y0) * std::size_t(rw) + std::size_t(px - r.x0)] = int(k);
    }
    auto& pool = frame.tileSegments[std::size_t(tile)];
    std::vector<TreeSegment> fresh;
    fresh.reserve(pool.size() + segments.size());
    for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
            const std::size_t i = frame.index(x, y);
            const int k = written[std::size_t(y - r.y0) * std::size_t(rw) + std::size_t(x - r.x0)];
            const uint32_t start = uint32_t(fresh.size());
            const bool keepOld = k < 0 || out[std::size_t(k)].segmentMode != kReplace;
            if (keepOld)
                fresh.insert(fresh.end(), pool.begin() + frame.segmentStart[i],
                             pool.begin() + frame.segmentStart[i] + frame.segmentCount[i]);
            if (k >= 0 && out[std::size_t(k)].segmentMode != kKeep) {
                const PixelOut& o = out[std::size_t(k)];
                fresh.insert(fresh.end(), segments.begin() + o.segmentOffset,
                             segments.begin() + o.segmentOffset + o.segmentCount);
            }
            std::size_t count = fresh.size() - start;
            if (count > 255) {  // Too many to index: forget them and always re-trace.
                fresh.resize(start);
                count = 0;
                frame.flags[i] |= kTreeUnknown;
            }
            frame.segmentStart[i] = start;
            frame.segmentCount[i] = uint8_t(count);
        }
    }
    pool.swap(fresh);
    frame.summarizeTile(tile);
}

}  // namespace rs
