// The blocks of one tile a commit wrote (frame_commit.cpp), and what it knows of their
// summaries without reading their pixels back: the frame rewrites those summaries from it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec_lanes.h"
#include "session/frame/deep_frame.h"
#include "session/tile_output.h"

namespace rs {

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

/// The blocks of one tile a commit wrote, so each summary is recomputed once.
class TouchedBlocks {
public:
    TouchedBlocks(const DeepFrame& frame, const PixelRect& r)
        : width_(frame.width()),
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
    /// Whether the commit wrote any block.
    bool any() const { return any_; }
    /// Calls f(x, y, known) for each block the commit wrote, (x, y) its top-left pixel:
    /// `known` is the block's summary built from what the commit wrote, or null where it must
    /// be read back from the block's pixels.
    template <class F>
    void forEachWritten(F&& f) const {
        for (std::size_t b = 0; b < marks_.size(); ++b) {
            if (!marks_[b]) continue;
            const int x = r_.x0 + int(b % std::size_t(perRow_)) * DeepFrame::kBlock;
            const int y = r_.y0 + int(b / std::size_t(perRow_)) * DeepFrame::kBlock;
            const int area = (std::min(r_.x1, x + DeepFrame::kBlock) - x) *
                             (std::min(r_.y1, y + DeepFrame::kBlock) - y);
            if (whole_)
                f(x, y, &sums_[b]);
            else if (marks_[b] == kSpans && spanPixels_[b] == area)
                f(x, y, &spanSums_[b]);
            else
                f(x, y, static_cast<const TileSummary*>(nullptr));
        }
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

}  // namespace rs
