// A tile's segment and record pools as DeepFrame::commit appends to them and compacts them
// (frame_commit.cpp): where a written pixel's secondary segments and deferred records go. The
// frame hands each pool what it may change, a tile's pool and the frame's index of it, and
// nothing else of itself.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "session/frame/deep_frame.h"
#include "session/tile_output.h"

namespace rs {

/// Where each pixel's items lie in its tile's pool: the frame's start and count channels
/// (row-major, `width` pixels a row), which a pool rewrites as it appends and compacts.
struct PoolIndex {
    uint32_t* start;
    uint8_t* count;
    std::size_t width;

    std::size_t at(int x, int y) const { return std::size_t(y) * width + std::size_t(x); }
};

/// A tile's segment pool, append-only: a written pixel's segments go to the end and its old
/// ones become garbage, so a commit costs what it writes, not the whole tile; compact() drops
/// the garbage when it outweighs what is live.
class SegmentPool {
public:
    /// The tile's `pool`, `live` the number of its segments pixels reference, `index` the
    /// frame's segmentStart and segmentCount.
    SegmentPool(SegmentVector& pool, uint32_t& live, const PoolIndex& index)
        : pool_(pool), live_(live), index_(index) {}

    /// Pixel i's segments become its old ones (when `keepOld`) followed by `count` from `first`
    /// (several lists: call add() for each, then end()).
    void begin(std::size_t i, bool keepOld) {
        pixel_ = i;
        oldCount_ = fresh_ ? 0 : index_.count[i];
        start_ = uint32_t(pool_.size());
        if (keepOld) {
            const uint32_t oldStart = index_.start[i];
            for (uint32_t k = 0; k < oldCount_; ++k) pool_.push_back(pool_[oldStart + k]);
        }
    }
    /// Drops every old segment: the commit rewrites each pixel of the tile (a full-tile pass),
    /// so none stays referenced; the pool starts over instead of growing into garbage.
    void restart() {
        pool_.clear();
        live_ = 0;
        fresh_ = true;
    }
    void add(const TreeSegment* first, std::size_t count) {
        pool_.insert(pool_.end(), first, first + count);
    }
    /// Pixels [i, i + n) of one row get the segments of rays [k, k + n) of `list` (none when
    /// the trace kept none) instead of their old ones: a run of traced pixels in one go, the
    /// pool grown once for the run.
    void replaceRun(std::size_t i, std::size_t n, const RayList& list, std::size_t k) {
        uint32_t removed = 0, added = 0;
        if (!fresh_)
            for (std::size_t j = 0; j < n; ++j) removed += index_.count[i + j];
        uint32_t* startOut = index_.start + i;
        uint8_t* countOut = index_.count + i;
        const uint32_t base = uint32_t(pool_.size());
        if (!list.withSegments) {
            std::fill_n(startOut, n, base);
            std::fill_n(countOut, n, uint8_t(0));
        } else {
            // A run's rays are consecutive in the list, so their segments are one stretch of
            // the grouped items: copied in one go.
            const uint8_t* counts = list.segments.count.data() + k;
            const uint32_t* first = list.segments.first.data() + k;
            added = first[n] - first[0];
            pool_.resize(base + added);  // Not zero-filled first (SegmentVector).
            std::copy_n(list.segments.of(k), added, pool_.data() + base);
            const uint32_t shift = base - first[0];
            for (std::size_t j = 0; j < n; ++j) {
                startOut[j] = first[j] + shift;
                countOut[j] = counts[j];
            }
        }
        live_ = live_ - removed + added;
    }
    /// False when the pixel's segments were too many to index: they are forgotten, and the
    /// caller flags its tree unknown (always re-traced).
    [[nodiscard]] bool end() {
        std::size_t count = pool_.size() - start_;
        const bool kept = count <= 255;
        if (!kept) {
            pool_.resize(start_);
            count = 0;
        }
        index_.start[pixel_] = start_;
        index_.count[pixel_] = uint8_t(count);
        live_ = live_ - oldCount_ + uint32_t(count);
        return kept;
    }
    /// Whether no pixel of the tile keeps a segment: every count is 0 (live_ is their sum),
    /// so clearRun() would change nothing. Not after restart(): counts not rewritten yet stay.
    bool noneKept() const { return !fresh_ && live_ == 0; }
    /// Pixels [i, i + n) of one row keep no segments.
    void clearRun(std::size_t i, std::size_t n) {
        uint32_t removed = 0;
        for (std::size_t j = 0; j < n; ++j) removed += index_.count[i + j];
        if (!fresh_) live_ -= removed;
        std::fill_n(index_.start + i, n, uint32_t(pool_.size()));
        std::fill_n(index_.count + i, n, uint8_t(0));
    }
    /// Rewrites the pool with only the segments pixels of `r` still reference, when it is
    /// mostly garbage.
    void compactIfWasteful(const PixelRect& r) {
        if (pool_.size() <= 2 * std::size_t(live_) + 4096) return;
        SegmentVector fresh;
        fresh.reserve(live_);
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) {
                const std::size_t i = index_.at(x, y);
                const uint32_t start = index_.start[i];
                index_.start[i] = uint32_t(fresh.size());
                fresh.insert(fresh.end(), pool_.begin() + start,
                             pool_.begin() + start + index_.count[i]);
            }
        }
        pool_.swap(fresh);
    }

private:
    SegmentVector& pool_;
    uint32_t& live_;
    PoolIndex index_;
    std::size_t pixel_ = 0;
    uint32_t oldCount_ = 0, start_ = 0;
    bool fresh_ = false;
};

/// A tile's record pool, append-only like its segment pool: a traced pixel's records go to
/// the end and its old ones become garbage, so a commit costs what it traces, not the tile.
/// Records stop being referenced in several places (a pixel losing kDeferredValid), so the
/// pool does not count what is live: it is compacted once it has grown by more than it held
/// after the last compaction plus one record a pixel, which bounds it at twice that and
/// keeps a compaction's scan of the tile amortized over as many appended records.
class RecordPool {
public:
    /// The tile's `pool`, `kept` its size after its last compaction, `index` the frame's
    /// recordStart and recordCount, `flags` its flags (whose kDeferredValid says which
    /// pixels' records are still wanted).
    RecordPool(std::vector<ShadingRecord>& pool, uint32_t& kept, const PoolIndex& index,
               const uint8_t* flags)
        : pool_(pool), kept_(kept), index_(index), flags_(flags) {}

    /// Every pixel of the tile is traced again: no old record stays referenced.
    void restart() {
        pool_.clear();
        kept_ = 0;
    }
    void append(std::size_t i, const ShadingRecord* first, uint8_t count) {
        index_.start[i] = uint32_t(pool_.size());
        index_.count[i] = count;
        pool_.insert(pool_.end(), first, first + count);
    }
    /// Keeps only the records of the pixels of `r` that still wait for deferred shadows.
    void compactIfWasteful(const PixelRect& r) {
        if (pool_.size() <= 2 * std::size_t(kept_) + std::size_t(r.area())) return;
        std::vector<ShadingRecord> fresh;
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) {
                const std::size_t i = index_.at(x, y);
                if (!(flags_[i] & kDeferredValid)) continue;
                const uint32_t start = index_.start[i];
                index_.start[i] = uint32_t(fresh.size());
                fresh.insert(fresh.end(), pool_.begin() + start,
                             pool_.begin() + start + index_.count[i]);
            }
        }
        pool_.swap(fresh);
        kept_ = uint32_t(pool_.size());
    }

private:
    std::vector<ShadingRecord>& pool_;
    uint32_t& kept_;
    PoolIndex index_;
    const uint8_t* flags_;
};

}  // namespace rs
