// Deep frame allocation, the edits' marks, state counts and block summaries.
#include "session/frame/deep_frame.h"

#include <algorithm>
#include <cstring>

#include "session/frame/byte_lanes.h"

namespace rs {

void DeepFrame::resize(int w, int h) {
    try {
        allocate(w, h);
    } catch (...) {
        // Half-sized buffers under the new sides would send readers (the display copies under
        // the frame lock the throw releases) past their ends or into huge copies: empty instead.
        const int tile = tileSize_;
        *this = DeepFrame{};
        tileSize_ = tile;
        throw;
    }
}

void DeepFrame::allocate(int w, int h) {
    width_ = w;
    height_ = h;
    const std::size_t n = std::size_t(w) * std::size_t(h);
#define RS_CHANNEL_ASSIGN(name, Vector, Type, fresh, ahead, shown) name##_.assign(n, fresh);
    RS_DEEP_FRAME_CHANNELS(RS_CHANNEL_ASSIGN)
#undef RS_CHANNEL_ASSIGN
    const std::size_t tiles = std::size_t(tilesX()) * std::size_t(tilesY());
    tileRecords_.assign(tiles, {});
    tileRecordsKept_.assign(tiles, 0);
    tileSegments_.assign(tiles, {});
    tileLiveSegments_.assign(tiles, 0);
    blockSummary_.assign(std::size_t(blocksX()) * std::size_t(blocksY()), {});
    tileSummary_.assign(tileRecords_.size(), {});
    tileStates_.assign(tileRecords_.size(), {});
    for (int t = 0; t < tilesX() * tilesY(); ++t) {
        const int tx = t % tilesX(), ty = t / tilesX();
        const int tw = std::min(width_, (tx + 1) * tileSize_) - tx * tileSize_;
        const int th = std::min(height_, (ty + 1) * tileSize_) - ty * tileSize_;
        tileStates_[std::size_t(t)][kStale] = uint32_t(tw) * uint32_t(th);
    }
    tileSampled_.assign(tileRecords_.size(), 0);
}

using lanes::kEachByte;
using lanes::nonZeroBytes;
using lanes::sumOfBytes;

void DeepFrame::applyBlockMarks(std::size_t b, const std::vector<uint8_t>& mask) {
    const int bx = int(b % std::size_t(blocksX())) * kBlock;
    const int by = int(b / std::size_t(blocksX())) * kBlock;
    const std::size_t n = std::size_t(std::min(width_, bx + kBlock) - bx);
    uint32_t was[4] = {0, 0, 0, 0};  // Old states of the marked pixels (was[0] unused).
    for (int y = by; y < std::min(height_, by + kBlock); ++y) {
        const std::size_t i = index(bx, y);
        const uint8_t* m = mask.data() + i;
        uint8_t* st = state_.data() + i;
        uint8_t* f = flags_.data() + i;
        if (n == 8) {
            // A block row is eight bytes of each buffer: all eight pixels at once, each byte a
            // lane (states are <= kFinal, two bits; the flags' other bits pass through).
            static_assert(kBlock == 8);
            uint64_t m8, s8, f8;
            std::memcpy(&m8, m, 8);
            std::memcpy(&s8, st, 8);
            std::memcpy(&f8, f, 8);
            const uint64_t one = nonZeroBytes(m8), all = one * 0xff;
            const uint64_t lo = s8 & one, hi = (s8 >> 1) & one;  // The marked pixels' states.
            was[1] += sumOfBytes(lo & ~hi);
            was[2] += sumOfBytes(hi & ~lo);
            was[3] += sumOfBytes(lo & hi);
            s8 &= ~all;
            // Marked: markedStaleFlags; the others lose the overlay flag.
            const uint64_t clear =
                kTracedLastUpdate * kEachByte | (all & kDeferredValid * kEachByte);
            f8 = (f8 & ~clear) | (all & kTracedLastUpdate * kEachByte);
            std::memcpy(st, &s8, 8);
            std::memcpy(f, &f8, 8);
            continue;
        }
        // A block cut by the frame's right edge: pixel by pixel.
        for (std::size_t k = 0; k < n; ++k) {
            if (m[k]) {
                ++was[st[k] & 3];
                st[k] = kStale;
                f[k] = markedStaleFlags(f[k]);
            } else {
                f[k] = uint8_t(f[k] & ~kTracedLastUpdate);
            }
        }
    }
    // Marked pixels that were stale already leave the counts as they are.
    const uint32_t moved = was[1] + was[2] + was[3];
    if (moved == 0) return;
    auto& counts = tileStates_[std::size_t(tileOfBlock(b))];
    for (int s = 1; s < 4; ++s) counts[std::size_t(s)] -= was[s];
    counts[kStale] += moved;
}

void DeepFrame::markAllStale() {
    std::fill(state_.begin(), state_.end(), uint8_t(kStale));
    for (uint8_t& f : flags_) f = markedStaleFlags(f);
    for (auto& counts : tileStates_) {
        counts = {counts[0] + counts[1] + counts[2] + counts[3], 0, 0, 0};
    }
}

void DeepFrame::applyShadowMarks(std::size_t b, const std::vector<uint8_t>& mask) {
    forEachPixelOfBlock(b, [&](std::size_t i, int tile) {
        if (mask[i] && state_[i] >= kBase) {
            setState(i, tile, kStale);
            flags_[i] = uint8_t(flags_[i] & ~kDeferredValid);
        }
    });
}

std::size_t DeepFrame::countBelow(uint8_t s) const {
    std::size_t n = 0;
    for (const auto& counts : tileStates_)
        for (uint8_t k = 0; k < s && k < 4; ++k) n += counts[k];
    return n;
}

bool DeepFrame::anyBelow(uint8_t s) const {
    for (int t = 0; t < int(tileStates_.size()); ++t)
        if (tileHasBelow(t, s)) return true;
    return false;
}

namespace {
bool sameBox(const Aabb& a, const Aabb& b) {
    return (a.empty() && b.empty()) || (a.min == b.min && a.max == b.max);
}
bool sameSummary(const TileSummary& a, const TileSummary& b) {
    return sameBox(a.hitBox, b.hitBox) && sameBox(a.segmentStarts, b.segmentStarts) &&
           sameBox(a.segmentEnds, b.segmentEnds) && a.anySpecular == b.anySpecular &&
           a.anyEscape == b.anyEscape && a.anyUnknown == b.anyUnknown;
}
}  // namespace

bool DeepFrame::summariesMatchPixels() const {
    DeepFrame copy = *this;
    for (int t = 0; t < tilesX() * tilesY(); ++t) copy.summarizeTile(t);
    for (std::size_t b = 0; b < blockSummary_.size(); ++b)
        if (!sameSummary(blockSummary_[b], copy.blockSummary_[b])) return false;
    for (std::size_t t = 0; t < tileSummary_.size(); ++t)
        if (!sameSummary(tileSummary_[t], copy.tileSummary_[t])) return false;
    std::vector<std::array<uint32_t, 4>> counts(tileStates_.size(), std::array<uint32_t, 4>{});
    // A tile's live segments are its pixels' counts summed: commit skips clearing the counts
    // of a tile that has none.
    std::vector<uint32_t> live(tileLiveSegments_.size(), 0);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const std::size_t i = index(x, y);
            if (state_[i] > kFinal) return false;
            ++counts[std::size_t(tileOf(x, y))][state_[i]];
            live[std::size_t(tileOf(x, y))] += segmentCount_[i];
            if (!tileSampled_[std::size_t(tileOf(x, y))] &&
                (sampleCount_[i] != 0 || sampleSum_[i] != Color(0.0f)))
                return false;
        }
    return counts == tileStates_ && live == tileLiveSegments_;
}

void DeepFrame::summarizeTile(int t) {
    const int tx = t % tilesX(), ty = t / tilesX();
    const int x1 = std::min(width_, (tx + 1) * tileSize_),
              y1 = std::min(height_, (ty + 1) * tileSize_);
    for (int by = ty * tileSize_; by < y1; by += kBlock)
        for (int bx = tx * tileSize_; bx < x1; bx += kBlock) summarizeBlock(bx, by);
    uniteTileSummary(t);
}

void DeepFrame::uniteTileSummary(int t) {
    const int tx = t % tilesX(), ty = t / tilesX();
    const int bx0 = tx * tileSize_ / kBlock, by0 = ty * tileSize_ / kBlock;
    const int bx1 = std::min(blocksX(), (tx + 1) * tileSize_ / kBlock);
    const int by1 = std::min(blocksY(), (ty + 1) * tileSize_ / kBlock);
    TileSummary sum;
    for (int by = by0; by < by1; ++by) {
        for (int bx = bx0; bx < bx1; ++bx) {
            const TileSummary& b =
                blockSummary_[std::size_t(by) * std::size_t(blocksX()) + std::size_t(bx)];
            sum.hitBox.expand(b.hitBox);
            sum.segmentStarts.expand(b.segmentStarts);
            sum.segmentEnds.expand(b.segmentEnds);
            sum.anySpecular |= b.anySpecular;
            sum.anyEscape |= b.anyEscape;
            sum.anyUnknown |= b.anyUnknown;
        }
    }
    tileSummary_[std::size_t(t)] = sum;
}

void DeepFrame::summarizeBlock(int px, int py) {
    const int bx = px / kBlock * kBlock, by = py / kBlock * kBlock;
    const auto& pool = tileSegments_[std::size_t(tileOf(bx, by))];
    TileSummary sum;
    for (int y = by; y < std::min(height_, by + kBlock); ++y) {
        for (int x = bx; x < std::min(width_, bx + kBlock); ++x) {
            const std::size_t i = index(x, y);
            const glm::vec4 b = hitBound_[i];
            if (b.w >= 0.0f) {
                sum.hitBox.expand(Vec3(b) - Vec3(b.w));
                sum.hitBox.expand(Vec3(b) + Vec3(b.w));
            }
            if (!(flags_[i] & kTouchedSpecular)) continue;
            sum.anySpecular = true;
            if (flags_[i] & kTreeUnknown) sum.anyUnknown = true;
            for (uint32_t k = 0; k < segmentCount_[i]; ++k) {
                const TreeSegment& s = pool[segmentStart_[i] + k];
                sum.segmentStarts.expand(s.a);
                if (s.escapes)
                    sum.anyEscape = true;
                else
                    sum.segmentEnds.expand(s.b);
            }
        }
    }
    blockSummary_[std::size_t(by / kBlock) * std::size_t(blocksX()) + std::size_t(bx / kBlock)] =
        sum;
}

}  // namespace rs
