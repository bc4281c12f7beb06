// DeepFrame::commit: a tile's results into the frame, with the frame's invariants (which
// buffers each kind of result writes, the record and segment pools, the block summaries).
#include <algorithm>
#include <cstdint>
#include <utility>

#include "core/vec_lanes.h"
#include "session/frame/deep_frame.h"
#include "session/tile_output.h"
#include "session/tile_pools.h"

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

/// An Aabb of points held in registers (an Aabb's vectors the compiler kept on the stack, a
/// load and a store per point and axis), with Aabb::expand's comparisons (p < min ? p : min,
/// max < p ? p : max: what minps and maxps compute), so the same bits.
struct BoxOfPoints {
#if defined(__SSE2__)
    __m128 lo = _mm_set1_ps(kInfinity), hi = _mm_set1_ps(-kInfinity);
    void add(__m128 p) {
        lo = _mm_min_ps(p, lo), hi = _mm_max_ps(p, hi);
    }
    void add(const Vec3& p) {
        add(lanes(p));
    }
    /// The centre of a bound of radius 0, unless its radius is < 0.
    void addBound(const glm::vec4& b) {
        const __m128 v = _mm_loadu_ps(&b.x);
        if (_mm_comige_ss(_mm_shuffle_ps(v, v, 3), _mm_setzero_ps())) add(v);
    }
    Aabb box() const {
        alignas(16) float l[4], h[4];
        _mm_store_ps(l, lo), _mm_store_ps(h, hi);
        return Aabb{Vec3(l[0], l[1], l[2]), Vec3(h[0], h[1], h[2])};
    }
#else
    Aabb b;
    void add(const Vec3& p) {
        b.expand(p);
    }
    void addBound(const glm::vec4& v) {
        if (v.w >= 0.0f) b.expand(Vec3(v));
    }
    Aabb box() const {
        return b;
    }
#endif
};

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

/// The blocks of one tile a commit wrote, so each summary is recomputed once.
class TouchedBlocks {
public:
    TouchedBlocks(const DeepFrame& frame, const PixelRect& r)
        : width_(frame.width_),
          r_(r),
          perRow_((r.x1 - r.x0 + DeepFrame::kBlock - 1) / DeepFrame::kBlock),
          marks_(std::size_t(perRow_) *
                     std::size_t((r.y1 - r.y0 + DeepFrame::kBlock - 1) / DeepFrame::kBlock),
                 0) {}
    void add(std::size_t i) {
        // Frames hold at most kMaxImagePixels (< 2^32): one 32-bit division, not two 64-bit.
        const uint32_t y = uint32_t(i) / uint32_t(width_), x = uint32_t(i) - y * uint32_t(width_);
        add(int(x), int(y));
    }
    void add(int x, int y) {
        marks_[blockOf(x, y)] = kReadBack;
        any_ = true;
    }
    /// Pixels [x, x + n) of row y (inside the tile).
    void addRun(int x, int y, int n) {
        const std::size_t row = std::size_t((y - r_.y0) / DeepFrame::kBlock) * std::size_t(perRow_);
        for (int b = (x - r_.x0) / DeepFrame::kBlock; b <= (x + n - 1 - r_.x0) / DeepFrame::kBlock;
             ++b)
            marks_[row + std::size_t(b)] = kReadBack;
        any_ = true;
    }
    /// The span of a block ray at pixel (x, y) (`pixels` of them, in one block), each pixel
    /// with the ray's hit point (radius 0) and flags and no segments. A block that spans cover
    /// whole, and nothing else of the commit wrote, gets its summary from them instead of
    /// reading its pixels back.
    void addSpan(int x, int y, int pixels, const glm::vec4& hit, uint8_t flags) {
        const std::size_t b = blockOf(x, y);
        if (spanPixels_.empty()) {
            spanPixels_.assign(marks_.size(), 0);
            spanSums_.assign(marks_.size(), TileSummary{});
        }
        if (marks_[b] != kReadBack) marks_[b] = kSpans;
        any_ = true;
        spanPixels_[b] += pixels;
        TileSummary& sum = spanSums_[b];
        if (hit.w >= 0.0f) sum.hitBox.expand(Vec3(hit));
        if (flags & kTouchedSpecular) {
            sum.anySpecular = true;
            if (flags & kTreeUnknown) sum.anyUnknown = true;
        }
    }
    /// The commit rewrites every pixel of the tile (one camera ray each): the summaries are
    /// built from what it writes (includeRun()) instead of read back from the frame.
    void buildWhole() {
        sums_.assign(marks_.size(), TileSummary{});
        whole_ = true;
    }
    bool whole() const { return whole_; }
    /// Adds pixels [x0, x0 + n) of row y, which rays [k0, k0 + n) of `list` wrote, as
    /// summarizeBlock reads them: their hit bounds and flags (the run's `bound` and `flags`,
    /// just written: still in the cache, one vector load a pixel) and, for a pixel whose tree
    /// met a mirror or glass, its segments (from the list, grouped by ray: a block's are one
    /// stretch).
    void includeRun(int x0, int y, const glm::vec4* bound, const uint8_t* flags,
                    const RayList& list, std::size_t k0, std::size_t n) {
        const bool withSegments = list.withSegments;
        const uint32_t* first = withSegments ? list.segments.first.data() + k0 : nullptr;
        const TreeSegment* items = withSegments ? list.segments.of(0) : nullptr;
        for (std::size_t j0 = 0; j0 < n;) {
            const int x = x0 + int(j0);
            const std::size_t end =
                std::min(n, j0 + std::size_t(DeepFrame::kBlock - (x - r_.x0) % DeepFrame::kBlock));
            // The hit points (a camera ray's bound has radius 0, or < 0 for a miss), and
            // which pixels met a mirror or glass with a tree not known.
            BoxOfPoints hits;
            uint8_t any = 0;
            for (std::size_t j = j0; j < end; ++j) {
                any |= flags[j];
                hits.addBound(bound[j]);
            }
            const bool specular = any & kTouchedSpecular;
            bool unknown = false;
            if (any & kTreeUnknown)
                for (std::size_t j = j0; j < end; ++j)
                    unknown |= (flags[j] & (kTouchedSpecular | kTreeUnknown)) ==
                               (kTouchedSpecular | kTreeUnknown);
            TileSummary& sum = sums_[blockOf(x, y)];
            sum.hitBox.expand(hits.box());
            if (specular) {
                sum.anySpecular = true;
                if (unknown) sum.anyUnknown = true;
            }
            // Only a tree that met a mirror or glass has secondary segments, and the grouped
            // list keeps neighbouring rays' segments together: the block's are one stretch.
            if (specular && withSegments) {
                BoxOfPoints starts, ends;
                bool escape = false;
                for (uint32_t q = first[j0]; q < first[end]; ++q) {
                    const TreeSegment& segment = items[q];
                    starts.add(segment.a);
                    if (segment.escapes)
                        escape = true;
                    else
                        ends.add(segment.b);
                }
                sum.segmentStarts.expand(starts.box());
                sum.segmentEnds.expand(ends.box());
                if (escape) sum.anyEscape = true;
            }
            j0 = end;
        }
    }
    /// Block summaries of the marked blocks, then the tile's.
    void summarize(DeepFrame& frame, int tile) const {
        if (!any_) return;
        for (std::size_t b = 0; b < marks_.size(); ++b) {
            if (!marks_[b]) continue;
            const int x = r_.x0 + int(b % std::size_t(perRow_)) * DeepFrame::kBlock;
            const int y = r_.y0 + int(b / std::size_t(perRow_)) * DeepFrame::kBlock;
            TileSummary& summary = frame.blockSummary_[std::size_t(y / DeepFrame::kBlock) *
                                                           std::size_t(frame.blocksX()) +
                                                       std::size_t(x / DeepFrame::kBlock)];
            const int area = (std::min(r_.x1, x + DeepFrame::kBlock) - x) *
                             (std::min(r_.y1, y + DeepFrame::kBlock) - y);
            if (whole_)
                summary = sums_[b];
            else if (marks_[b] == kSpans && spanPixels_[b] == area)
                summary = spanSums_[b];
            else
                frame.summarizeBlock(x, y);
        }
        frame.uniteTileSummary(tile);
    }

private:
    std::size_t blockOf(int x, int y) const {
        return std::size_t((y - r_.y0) / DeepFrame::kBlock) * std::size_t(perRow_) +
               std::size_t((x - r_.x0) / DeepFrame::kBlock);
    }

    /// marks_: a block the commit did not write, one read back from its pixels, or one only
    /// block rays' spans wrote.
    enum : uint8_t { kUntouched = 0, kReadBack = 1, kSpans = 2 };

    int width_;
    PixelRect r_;
    int perRow_;
    std::vector<uint8_t> marks_;
    std::vector<TileSummary> sums_;
    std::vector<int> spanPixels_;        ///< Pixels spans wrote in each block.
    std::vector<TileSummary> spanSums_;  ///< Their summary.
    bool any_ = false, whole_ = false;
};

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
    Commit c{SegmentPool(*this, t.tile), TouchedBlocks(*this, t.rect), t.tile,
             tileSampled_[std::size_t(t.tile)] != 0, t.traced.size() == std::size_t(t.rect.area())};
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
    c.touched.summarize(*this, c.tile);
    return true;
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
    RecordPool records(*this, c.tile);
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
        segments.end();
        c.touched.add(i);
    }
}

}  // namespace rs
