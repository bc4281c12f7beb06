// Deep frame allocation.
#include "session/deep_frame.h"

#include <algorithm>

namespace rs {

void DeepFrame::resize(int w, int h) {
    try {
        allocate(w, h);
    } catch (...) {
        // Half-sized buffers under the new sides would send readers (the display copies under
        // the frame lock the throw releases) past their ends or into huge copies: empty instead.
        const int tile = tileSize;
        *this = DeepFrame{};
        tileSize = tile;
        throw;
    }
}

void DeepFrame::allocate(int w, int h) {
    width = w;
    height = h;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    color.assign(n, Color(0.0f));
    base.assign(n, Color(0.0f));
    sampleSum.assign(n, Color(0.0f));
    sampleCount.assign(n, 0);
    id.assign(n, kNoObject);
    depth.assign(n, kInfinity);
    normal.assign(n, Vec3(0.0f));
    cost.assign(n, 0);
    state.assign(n, kStale);
    flags.assign(n, 0);
    hitBound.assign(n, glm::vec4(0.0f, 0.0f, 0.0f, -1.0f));
    tileRecords.assign(std::size_t(tilesX()) * std::size_t(tilesY()), {});
    recordStart.assign(n, 0);
    recordCount.assign(n, 0);
    tileSegments.assign(tileRecords.size(), {});
    segmentStart.assign(n, 0);
    segmentCount.assign(n, 0);
    tileLiveSegments.assign(tileRecords.size(), 0);
    blockSummary.assign(std::size_t(blocksX()) * std::size_t(blocksY()), {});
}

void DeepFrame::summarizeTile(int t) {
    const int tx = t % tilesX(), ty = t / tilesX();
    const int x1 = std::min(width, (tx + 1) * tileSize), y1 = std::min(height, (ty + 1) * tileSize);
    for (int by = ty * tileSize; by < y1; by += kBlock)
        for (int bx = tx * tileSize; bx < x1; bx += kBlock) summarizeBlock(bx, by);
}

void DeepFrame::summarizeBlock(int px, int py) {
    const int bx = px / kBlock * kBlock, by = py / kBlock * kBlock;
    const auto& pool = tileSegments[std::size_t(tileOf(bx, by))];
    TileSummary sum;
    for (int y = by; y < std::min(height, by + kBlock); ++y) {
        for (int x = bx; x < std::min(width, bx + kBlock); ++x) {
            const std::size_t i = index(x, y);
            const glm::vec4 b = hitBound[i];
            if (b.w >= 0.0f) {
                sum.hitBox.expand(Vec3(b) - Vec3(b.w));
                sum.hitBox.expand(Vec3(b) + Vec3(b.w));
            }
            if (!(flags[i] & kTouchedSpecular)) continue;
            sum.anySpecular = true;
            if (flags[i] & kTreeUnknown) sum.anyUnknown = true;
            for (uint32_t k = 0; k < segmentCount[i]; ++k) {
                const TreeSegment& s = pool[segmentStart[i] + k];
                sum.segmentStarts.expand(s.a);
                if (s.escapes) sum.anyEscape = true;
                else sum.segmentEnds.expand(s.b);
            }
        }
    }
    blockSummary[std::size_t(by / kBlock) * std::size_t(blocksX()) + std::size_t(bx / kBlock)] = sum;
}

}  // namespace rs
