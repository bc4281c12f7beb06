// DeepFrame::commit: a tile's results into the frame, with the frame's invariants (which
// buffers each kind of result writes, the record and segment pools, the block summaries).
#include <algorithm>
#include <cstdint>
#include <utility>

#include "session/frame/deep_frame.h"
#include "session/frame/tile_pools.h"
#include "session/frame/touched_blocks.h"
#include "session/tile_output.h"

namespace rs {

namespace {

/// Asks for the cache lines of v[0, n) with the intent to write them. Always inlined: GCC
/// takes a function that only prefetches for one without effects and drops the calls.
template <class T>
[[gnu::always_inline]] inline void prefetchForWrite(const T* v, std::size_t n) {
    const auto last = reinterpret_cast<std::uintptr_t>(v + n);
    for (auto p = reinterpret_cast<std::uintptr_t>(v) & ~std::uintptr_t(63); p < last; p += 64)
        __builtin_prefetch(reinterpret_cast<const void*>(p), 1, 3);
}

/// The frame's columns a run of camera rays writes besides colour, cost and state, through
/// local pointers: the byte-sized stores (flags) may alias anything, which would make the
/// compiler reload every vector's data pointer per pixel. Records and Segments say whether
/// the trace kept them (their overflow flags feed the pixel's flags).
struct TracedColumns {
    ObjectId* id;
    float* depth;
    Vec3* normal;
    uint8_t* flags;
    glm::vec4* bound;

    /// Rays [k0, k0 + n) of `list` into the run's pixels [0, n).
    template <bool Records, bool Segments>
    void write(const RayList& list, std::size_t k0, std::size_t n) const {
        const PrimaryInfo* info = list.info.data() + k0;
        const uint8_t* extra = list.extra.data() + k0;
        const uint8_t* recordOverflow = Records ? list.records.overflow.data() + k0 : nullptr;
        const uint8_t* segmentOverflow = Segments ? list.segments.overflow.data() + k0 : nullptr;
        const Vec3* origin = list.origin.data() + k0;
        const Vec3* dir = list.dir.data() + k0;
        for (std::size_t j = 0; j < n; ++j) {
            const PrimaryInfo& p = info[j];
            id[j] = p.id;
            depth[j] = p.depth;
            normal[j] = p.normal;
            uint8_t f = uint8_t((p.touchedSpecular ? kTouchedSpecular : 0) | extra[j]);
            if constexpr (Records) f |= recordOverflow[j] ? 0 : kDeferredValid;
            if constexpr (Segments) f |= segmentOverflow[j] ? kTreeUnknown : 0;
            flags[j] = f;
            bound[j] = RayList::hitBoundOf(origin[j], dir[j], p);
        }
    }
};

/// What a block ray writes into every pixel of its span.
struct SpanValue {
    Color color;
    ObjectId id;
    float depth;
    Vec3 normal;
    uint32_t cost;
    uint8_t flags;
    glm::vec4 bound;
};

/// The frame's columns a span writes, through local pointers: the byte-sized stores may alias
/// anything, which would make the compiler reload every vector's data pointer per pixel. The
/// old states are counted here (a read-modify-write of the tile's counts per pixel otherwise),
/// unless `countStates` is off: the caller knows them (reading them misses the cache).
struct SpanWriter {
    Color* color;
    ObjectId* id;
    float* depth;
    Vec3* normal;
    uint32_t* cost;
    uint8_t* state;
    uint8_t* flags;
    glm::vec4* bound;
    Color* sampleSum;
    uint16_t* sampleCount;
    bool clearSamples;
    bool countStates;
    uint32_t wasState[4] = {0, 0, 0, 0};

    /// Pixels [i, i + n) of one row get v; N > 0 says n == N, so the loops unroll.
    template <std::size_t N>
    void row(std::size_t i, std::size_t n, const SpanValue& v) {
        if constexpr (N > 0) n = N;
        const SpanValue w = v;  // Local: not reloaded after each byte store.
        Color* const colorOut = color + i;
        ObjectId* const idOut = id + i;
        float* const depthOut = depth + i;
        Vec3* const normalOut = normal + i;
        uint32_t* const costOut = cost + i;
        uint8_t* const stateOut = state + i;
        uint8_t* const flagsOut = flags + i;
        glm::vec4* const boundOut = bound + i;
        uint32_t was[4] = {0, 0, 0, 0};
        if (countStates)
            for (std::size_t k = 0; k < n; ++k) ++was[stateOut[k] & 3];  // States are <= kFinal.
        for (std::size_t k = 0; k < n; ++k) colorOut[k] = w.color;
        for (std::size_t k = 0; k < n; ++k) idOut[k] = w.id;
        for (std::size_t k = 0; k < n; ++k) depthOut[k] = w.depth;
        for (std::size_t k = 0; k < n; ++k) normalOut[k] = w.normal;
        for (std::size_t k = 0; k < n; ++k) costOut[k] = w.cost;
        for (std::size_t k = 0; k < n; ++k) boundOut[k] = w.bound;
        for (std::size_t k = 0; k < n; ++k) stateOut[k] = kInteractive;
        for (std::size_t k = 0; k < n; ++k) flagsOut[k] = w.flags;
        if (clearSamples) {
            for (std::size_t k = 0; k < n; ++k) sampleSum[i + k] = Color(0.0f);
            for (std::size_t k = 0; k < n; ++k) sampleCount[i + k] = 0;
        }
        for (int s = 0; s < 4; ++s) wasState[s] += was[s];
    }
};

}  // namespace

/// What commit()'s steps share.
struct DeepFrame::Commit {
    SegmentPool segments;
    TouchedBlocks touched;
    int tile;
    /// Tiles that never got supersamples hold zero sums already: no need to clear them again.
    bool clearSamples;
    /// Every pixel of the tile traced again (a full pass): the tile's state counts are known
    /// without reading the old states (a dependent read-modify-write per pixel otherwise).
    bool wholeTile;
};

template <int Position>
[[gnu::always_inline]] inline void DeepFrame::prefetchAt(std::size_t i, std::size_t n) const {
#define RS_CHANNEL_AHEAD(name, Vector, Type, fresh, ahead, shown) \
    if constexpr ((ahead) == Position) prefetchForWrite(name##_.data() + i, n);
    RS_DEEP_FRAME_CHANNELS(RS_CHANNEL_AHEAD)
#undef RS_CHANNEL_AHEAD
}

template <int... P>
[[gnu::always_inline]] inline void DeepFrame::prefetchInOrder(
    std::size_t i, std::size_t n, std::integer_sequence<int, P...>) const {
    (prefetchAt<P + 1>(i, n), ...);
}

// Position by position, the channel at each: the same prefetches, in the same order, as
// written out by hand.
[[gnu::always_inline]] inline void DeepFrame::prefetchRunRow(std::size_t i, std::size_t n) const {
    prefetchInOrder(i, n, std::make_integer_sequence<int, pixelChannelCount()>{});
}

bool DeepFrame::commit(const TileResult& t, uint64_t liveGeneration) {
    if (t.generation != liveGeneration) return false;  // Never write a stale tile.
    const auto tile = std::size_t(t.tile);
    Commit c{SegmentPool(tileSegments_[tile], tileLiveSegments_[tile],
                         {segmentStart_.data(), segmentCount_.data(), std::size_t(width_)}),
             TouchedBlocks(*this, t.rect), t.tile, tileSampled_[tile] != 0,
             t.traced.size() == std::size_t(t.rect.area())};
    if (c.wholeTile) {
        c.segments.restart();
        if (t.blocks.size() == 0 && t.resolvedPixel.empty() && t.sampled.empty())
            c.touched.buildWhole();
    }
    commitTraced(t, c);
    if (t.traced.withRecords) commitRecords(t, c);
    if (t.blocks.size() > 0) commitBlocks(t, c);
    commitResolved(t, c);
    commitFinished(t, c);
    commitSampled(t, c);
    c.segments.compactIfWasteful(t.rect);
    summarizeWritten(c);
    return true;
}

// The summaries of the blocks the commit wrote, then the tile's.
void DeepFrame::summarizeWritten(const Commit& c) {
    if (!c.touched.any()) return;
    c.touched.forEachWritten([this](int x, int y, const TileSummary* known) {
        if (known)
            blockSummary_[std::size_t(y / kBlock) * std::size_t(blocksX()) +
                          std::size_t(x / kBlock)] = *known;
        else
            summarizeBlock(x, y);
    });
    uniteTileSummary(c.tile);
}

// Camera rays at pixel centres: every buffer of the pixel. Passes gather a tile's pixels row by
// row, so the rays come in runs of neighbouring pixels (a whole tile's rows in a full pass):
// each run's colours, costs and bases are copied as blocks, and the rest of a pixel's
// bookkeeping works from the run's row instead of dividing its index.
void DeepFrame::commitTraced(const TileResult& t, Commit& c) {
    const int tile = c.tile;
    const bool clearSamples = c.clearSamples, wholeTile = c.wholeTile;
    SegmentPool& segments = c.segments;
    TouchedBlocks& touched = c.touched;
    const RayList& traced = t.traced;
    const bool writeBase = t.tracedState >= kBase && t.keepBase;
    const bool whole = touched.whole();
    const std::size_t rowWidth = std::size_t(t.rect.x1 - t.rect.x0);
    for (std::size_t k0 = 0; k0 < traced.size();) {
        const std::size_t i0 = traced.pixel[k0];
        // Frames hold at most kMaxImagePixels (< 2^32): one 32-bit division, not two 64-bit.
        const uint32_t y = uint32_t(i0) / uint32_t(width_),
                       x0 = uint32_t(i0) - y * uint32_t(width_);
        const std::size_t rowLeft = std::size_t(uint32_t(width_) - x0);
        std::size_t n = 1;  // The run ends with the row.
        if (wholeTile && k0 + rowWidth <= traced.size() && rowWidth <= rowLeft &&
            traced.pixel[k0 + rowWidth - 1] == i0 + rowWidth - 1)
            n = rowWidth;  // Row-major, one ray a pixel: the run is the tile's row.
        while (n < rowLeft && k0 + n < traced.size() && traced.pixel[k0 + n] == i0 + n) ++n;
        const auto from = std::ptrdiff_t(k0), to = std::ptrdiff_t(i0), count = std::ptrdiff_t(n);
        // The next row's run (a whole-tile commit writes every row): its lines asked for now,
        // for writing, so they arrive while this row is written. A tile's rows are a frame row
        // apart in each buffer, too short a stretch for the hardware's prefetchers. Partial
        // commits (drag steps) seldom write the next row.
        if (wholeTile && y + 1 < uint32_t(t.rect.y1)) prefetchRunRow(i0 + std::size_t(width_), n);
        std::copy_n(traced.color.begin() + from, count, color_.begin() + to);
        std::copy_n(traced.rays.begin() + from, count, cost_.begin() + to);
        if (writeBase) std::copy_n(traced.color.begin() + from, count, base_.begin() + to);
        if (clearSamples) {
            std::fill_n(sampleSum_.begin() + to, count, Color(0.0f));
            std::fill_n(sampleCount_.begin() + to, count, uint16_t(0));
        }
        auto& counts = tileStates_[std::size_t(tile)];
        if (!wholeTile)
            for (std::size_t j = 0; j < n; ++j) --counts[state_[i0 + j]];
        const TracedColumns out{id_.data() + i0, depth_.data() + i0, normal_.data() + i0,
                                flags_.data() + i0, hitBound_.data() + i0};
        if (traced.withRecords)
            traced.withSegments ? out.write<true, true>(traced, k0, n)
                                : out.write<true, false>(traced, k0, n);
        else
            traced.withSegments ? out.write<false, true>(traced, k0, n)
                                : out.write<false, false>(traced, k0, n);
        if (!wholeTile) counts[t.tracedState] += uint32_t(n);
        std::fill_n(state_.begin() + to, count, t.tracedState);
        segments.replaceRun(i0, n, traced, k0);
        touched.addRun(int(x0), int(y), int(n));
        if (whole) touched.includeRun(int(x0), int(y), out.bound, out.flags, traced, k0, n);
        k0 += n;
    }
    if (wholeTile && traced.size() > 0) {
        auto& counts = tileStates_[std::size_t(tile)];
        counts = {0, 0, 0, 0};
        counts[t.tracedState] = uint32_t(traced.size());
    }
}

// Traced pixels get new records at the end of the tile's pool; untouched pixels that still wait
// for their deferred shadows keep theirs where they are.
void DeepFrame::commitRecords(const TileResult& t, const Commit& c) {
    const RayList& traced = t.traced;
    const auto tile = std::size_t(c.tile);
    RecordPool records(tileRecords_[tile], tileRecordsKept_[tile],
                       {recordStart_.data(), recordCount_.data(), std::size_t(width_)},
                       flags_.data());
    if (c.wholeTile) records.restart();
    for (std::size_t k = 0; k < traced.size(); ++k) {
        const uint8_t n = traced.records.overflow[k] ? 0 : traced.records.count[k];
        records.append(traced.pixel[k], traced.records.of(k), n);
    }
    records.compactIfWasteful(t.rect);
}

// Undersampled blocks: the block's ray over all its pixels, which keep no segments. Each span
// row is a run of neighbouring pixels that SpanWriter fills buffer by buffer; the segments are
// cleared a span row at a time. An orbit's pass finds every pixel of the tile stale and (after
// its first pass) none keeping segments: then the old states and segment counts are known from
// the tile's counts and are not read: loads that miss the cache, which the commit waited for
// (its stores alone it does not wait for).
void DeepFrame::commitBlocks(const TileResult& t, Commit& c) {
    const int tile = c.tile;
    SegmentPool& segments = c.segments;
    TouchedBlocks& touched = c.touched;
    const RayList& blocks = t.blocks;
    const bool allStale = tileStates_[std::size_t(tile)][kStale] == uint32_t(t.rect.area());
    const bool clearSegments = !segments.noneKept();
    SpanWriter spans{color_.data(),     id_.data(),          depth_.data(),  normal_.data(),
                     cost_.data(),      state_.data(),       flags_.data(),  hitBound_.data(),
                     sampleSum_.data(), sampleCount_.data(), c.clearSamples, !allStale};
    uint32_t spanPixels = 0;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        const PrimaryInfo& info = blocks.info[k];
        const SpanValue v{blocks.color[k],
                          info.id,
                          info.depth,
                          info.normal,
                          blocks.rays[k],
                          uint8_t((info.touchedSpecular ? kTouchedSpecular | kTreeUnknown : 0) |
                                  kTracedLastUpdate),
                          blocks.hitBound(k)};
        const int spanX = blocks.extra[k] & 15, spanY = blocks.extra[k] >> 4;
        {
            // A span (step 2 or 4, aligned) lies in one 8x8 block. Frames hold at most
            // kMaxImagePixels (< 2^32): one 32-bit division, not two 64-bit.
            const uint32_t y = uint32_t(blocks.pixel[k]) / uint32_t(width_);
            const uint32_t x = uint32_t(blocks.pixel[k]) - y * uint32_t(width_);
            touched.addSpan(int(x), int(y), spanX * spanY, v.bound, v.flags);
        }
        for (int dy = 0; dy < spanY; ++dy) {
            const std::size_t i = blocks.pixel[k] + std::size_t(dy) * std::size_t(width_);
            const std::size_t n = std::size_t(spanX);
            if (n == 4)
                spans.row<4>(i, n, v);  // Quarter and half resolution: unrolled.
            else if (n == 2)
                spans.row<2>(i, n, v);
            else
                spans.row<0>(i, n, v);
            spanPixels += uint32_t(spanX);
            if (clearSegments) segments.clearRun(i, n);
        }
    }
    auto& counts = tileStates_[std::size_t(tile)];
    if (allStale) spans.wasState[kStale] = spanPixels;
    for (int s = 0; s < 4; ++s) counts[std::size_t(s)] -= spans.wasState[s];
    counts[kInteractive] += spanPixels;
}

// Deferred shadows resolved: the hit, its tree and its cost stay.
void DeepFrame::commitResolved(const TileResult& t, Commit& c) {
    const int tile = c.tile;
    const bool clearSamples = c.clearSamples;
    for (std::size_t k = 0; k < t.resolvedPixel.size(); ++k) {
        const std::size_t i = t.resolvedPixel[k];
        color_[i] = t.resolvedColor[k];
        if (t.keepBase) base_[i] = color_[i];
        setState(i, tile, t.resolvedState);
        flags_[i] = t.resolvedFlags[k];
        if (clearSamples) {
            sampleSum_[i] = Color(0.0f);
            sampleCount_[i] = 0;
        }
        c.touched.add(i);
    }
}

// Nothing to supersample: the centre sample is final.
void DeepFrame::commitFinished(const TileResult& t, const Commit& c) {
    const int tile = c.tile;
    const bool clearSamples = c.clearSamples;
    for (const std::size_t i : t.finishedPixel) {
        color_[i] = base_[i];
        setState(i, tile, kFinal);
        if (clearSamples) {
            sampleSum_[i] = Color(0.0f);
            sampleCount_[i] = 0;
        }
    }
}

// More samples: new totals, and the new rays' segments after the pixel's old ones.
void DeepFrame::commitSampled(const TileResult& t, Commit& c) {
    const int tile = c.tile;
    SegmentPool& segments = c.segments;
    const RayList& samples = t.samples;
    if (!t.sampled.empty()) tileSampled_[std::size_t(tile)] = 1;
    for (std::size_t k = 0; k < t.sampled.size(); ++k) {
        const TileResult::Sampled& s = t.sampled[k];
        const std::size_t i = s.pixel;
        color_[i] = s.color;
        sampleSum_[i] = s.sum;
        sampleCount_[i] = s.count;
        setState(i, tile, s.state);
        flags_[i] = s.flags;
        cost_[i] = s.cost;
        hitBound_[i] = s.hitBound;
        segments.begin(i, true);
        std::size_t kept = 0;
        for (int j = t.sampleFirst[k]; j < t.sampleFirst[k + 1] && kept < kSegmentsPerPixel; ++j) {
            const std::size_t q = std::size_t(j);
            const std::size_t n =
                std::min<std::size_t>(samples.segments.count[q], kSegmentsPerPixel - kept);
            segments.add(samples.segments.of(q), n);
            kept += n;
        }
        if (!segments.end()) flags_[i] |= kTreeUnknown;  // Too many to index: always re-trace.
        c.touched.add(i);
    }
}

}  // namespace rs
