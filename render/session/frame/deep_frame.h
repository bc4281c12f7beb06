// The session's frame: HDR colour plus per-pixel id, depth, normal, cost, state and records.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <utility>
#include <vector>

#include "image/image.h"
#include "integrator/whitted.h"
#include "scene/document.h"
#include "session/frame/pixel_channels.h"
#include "session/frame/pixel_rect.h"

namespace rs {

/// How far a pixel has got toward the final image.
enum PixelState : uint8_t {
    kStale = 0,        ///< An edit may have changed it: must be traced again.
    kInteractive = 1,  ///< Traced (or filled in) at interaction quality.
    kBase = 2,         ///< Full quality, one sample at the pixel centre.
    kFinal = 3,        ///< As a full render gives it (supersampled where the settings say).
};

/// Per-pixel flags.
enum PixelFlag : uint8_t {
    kTouchedSpecular = 1,   ///< Its ray tree met a reflective or refractive surface.
    kDeferredValid = 2,     ///< Traced with only shadows deferred: records complete the pixel.
    kTracedLastUpdate = 4,  ///< Re-traced by the latest edit (debug overlay).
    kTreeUnknown = 8,       ///< Its secondary segments were not all kept: always re-trace.
    kSampleMissed = 16,     ///< A supersample's camera ray hit nothing (saw the environment).
    /// A supersample's camera ray hit an object other than the one at the pixel's centre.
    kSampleOtherObject = 32,
};

/// The flags of a pixel an edit marks stale: its deferred records no longer hold, and the
/// re-traced overlay shows it.
constexpr uint8_t markedStaleFlags(uint8_t f) {
    return uint8_t((f & ~(kDeferredValid | kTracedLastUpdate)) | kTracedLastUpdate);
}

/// What dirty marking needs to know about a block of pixels without looking at them.
struct TileSummary {
    Aabb hitBox;               ///< Camera-ray hit points of its pixels (with their radii).
    Aabb segmentStarts;        ///< Start points of its pixels' secondary segments.
    Aabb segmentEnds;          ///< End points of the bounded ones (secondary hit points).
    bool anySpecular = false;  ///< Some pixel's ray tree met a mirror or glass.
    bool anyEscape = false;    ///< Some secondary ray left the scene (unbounded).
    bool anyUnknown = false;   ///< Some pixel's tree was not kept.
};

struct TileResult;

/// What the designer's display copy does with a channel (pixel_channels.h).
enum ChannelShown {
    kNotShown,
    kShown,           ///< Compared and copied.
    kShownInDebug,    ///< Compared and copied while a debug view shows it.
    kShownAsOverlay,  ///< The re-traced overlay: changed by edits outside any tile.
};

/// A tile's pool of secondary segments: grown by resize() and then written over, so grown
/// without zero-filling first (a second store to each segment otherwise).
using SegmentVector = std::vector<TreeSegment, DefaultInitAllocator<TreeSegment>>;

/// The number of per-pixel channels.
constexpr int pixelChannelCount() {
    int count = 0;
#define RS_CHANNEL_COUNT(name, Vector, Type, fresh, ahead, shown) ++count;
    RS_DEEP_FRAME_CHANNELS(RS_CHANNEL_COUNT)
#undef RS_CHANNEL_COUNT
    return count;
}

/// The sum of the sizes of the per-pixel channels' elements.
constexpr std::size_t pixelChannelBytes() {
    std::size_t bytes = 0;
#define RS_CHANNEL_BYTES(name, Vector, Type, fresh, ahead, shown) bytes += sizeof(Type);
    RS_DEEP_FRAME_CHANNELS(RS_CHANNEL_BYTES)
#undef RS_CHANNEL_BYTES
    return bytes;
}

// What the list makes of each channel inside DeepFrame (undefined after it).
#define RS_CHANNEL_BUFFER(name, Vector, Type, fresh, ahead, shown) Vector<Type> name##_;
#define RS_CHANNEL_VIEW(name, Vector, Type, fresh, ahead, shown) \
    std::span<const Type> name() const {                         \
        return name##_;                                          \
    }
#define RS_CHANNEL_SHOWN(name, Vector, Type, fresh, ahead, shown) \
    if constexpr (shown == kShown) f(name##_, out.name);          \
    if constexpr (shown == kShownInDebug)                         \
        if (debug) f(name##_, out.name);
#define RS_CHANNEL_OVERLAY(name, Vector, Type, fresh, ahead, shown) \
    if constexpr (shown == kShownAsOverlay) f(name##_, out.name);

/// Structure-of-arrays deep buffer (thesis 3.3), row-major, (0, 0) top left.
///
/// The buffers are the class's own: readers get const views of them (color(), state(), ...),
/// and only these write: resize() allocates; tiles write only through commit(), under the
/// session's shared frame lock, each tile its own pixels; edits (the session's dirty
/// marking) change only `state` and `flags`, through applyBlockMarks(), applyShadowMarks()
/// or markAllStale(), under the exclusive lock. commit() lends its helpers only what each
/// changes: a segment or record pool (tile_pools.h) gets its tile's pool and the channels
/// that index it, and the blocks it wrote (touched_blocks.h) nothing: it says what it knows of
/// their summaries and commit() writes them. commit() keeps these invariants:
/// - a result of another generation than the live one writes nothing;
/// - `base` holds the centre sample of pixels at kBase or above when the scene supersamples
///   (only supersampling reads it), `sampleSum`/`sampleCount` the samples (zero below kBase);
/// - a pixel's records are tileRecords[its tile][recordStart, +recordCount), valid only with
///   kDeferredValid; its segments are tileSegments[its tile][segmentStart, +segmentCount),
///   all of them unless kTreeUnknown;
/// - the summaries of the blocks a commit wrote describe their pixels again, and so does the
///   summary of their tile;
/// - tileStates counts every pixel of its tile by state (setState() keeps it);
/// - a tile whose tileSampled is 0 has no sampleSum or sampleCount other than zero.
class DeepFrame {
public:
    static constexpr int kBlock = 8;  ///< Side of the blocks summaries describe.
    /// Bytes a pixel costs the per-pixel buffers (the tiles' pools and summaries come on top).
    static constexpr std::size_t kBytesPerPixel = pixelChannelBytes();

    int width() const { return width_; }
    int height() const { return height_; }
    int tileSize() const { return tileSize_; }
    /// Each per-pixel channel of pixel_channels.h as a const view, row-major.
    RS_DEEP_FRAME_CHANNELS(RS_CHANNEL_VIEW)
    /// Deferred shading records, pooled per tile; a pixel's are [recordStart, +recordCount).
    std::span<const std::vector<ShadingRecord>> tileRecords() const { return tileRecords_; }
    /// Size of each record pool after its last compaction (commit appends and compacts).
    std::span<const uint32_t> tileRecordsKept() const { return tileRecordsKept_; }
    /// Secondary ray segments of each pixel's ray tree, pooled per tile like the records.
    std::span<const SegmentVector> tileSegments() const { return tileSegments_; }
    /// Segments still referenced in each pool.
    std::span<const uint32_t> tileLiveSegments() const { return tileLiveSegments_; }
    /// Summaries of 8 x 8 blocks (finer than tiles: tighter boxes reject more in marking).
    std::span<const TileSummary> blockSummary() const { return blockSummary_; }
    /// Union of the block summaries of each tile: marking tests a tile before its blocks.
    std::span<const TileSummary> tileSummary() const { return tileSummary_; }
    /// Pixels of each PixelState in each tile: planning, completeness and waiting read these
    /// instead of scanning every pixel's state.
    std::span<const std::array<uint32_t, 4>> tileStates() const { return tileStates_; }
    /// 1 where the tile may hold supersamples (a sampleSum or sampleCount not zero).
    std::span<const uint8_t> tileSampled() const { return tileSampled_; }

    /// Allocates for w x h; every pixel starts stale and black. When an allocation fails the
    /// frame is left empty (0 x 0) and the exception passes on.
    void resize(int w, int h);
    std::size_t index(int x, int y) const {
        return std::size_t(y) * std::size_t(width_) + std::size_t(x);
    }
    std::size_t pixelCount() const { return color_.size(); }
    int tilesX() const { return (width_ + tileSize_ - 1) / tileSize_; }
    int tilesY() const { return (height_ + tileSize_ - 1) / tileSize_; }
    int tileOf(int x, int y) const { return (y / tileSize_) * tilesX() + x / tileSize_; }
    int blocksX() const { return (width_ + kBlock - 1) / kBlock; }
    int blocksY() const { return (height_ + kBlock - 1) / kBlock; }
    /// The tile holding block b (tile sides are whole blocks).
    int tileOfBlock(std::size_t b) const {
        const int bx = int(b % std::size_t(blocksX())), by = int(b / std::size_t(blocksX()));
        return (by * kBlock / tileSize_) * tilesX() + bx * kBlock / tileSize_;
    }
    /// Calls f(i, tile) for every pixel index i of block b, row by row, with b's tile.
    template <class F>
    void forEachPixelOfBlock(std::size_t b, F&& f) const {
        const int bx = int(b % std::size_t(blocksX())) * kBlock;
        const int by = int(b / std::size_t(blocksX())) * kBlock;
        const int tile = tileOfBlock(b);
        for (int y = by; y < std::min(height_, by + kBlock); ++y)
            for (int x = bx; x < std::min(width_, bx + kBlock); ++x) f(index(x, y), tile);
    }
    /// Whether tile t has a pixel whose state is below s.
    bool tileHasBelow(int t, uint8_t s) const {
        const auto& counts = tileStates_[std::size_t(t)];
        uint32_t n = 0;
        for (uint8_t k = 0; k < s && k < 4; ++k) n += counts[k];
        return n > 0;
    }
    /// An edit's marks in block b: pixels whose entry of `mask` (one byte a pixel, row-major
    /// like the frame) is set go stale, lose their deferred records and get the re-traced
    /// overlay flag; the block's other pixels lose that flag. The tile's state counts follow,
    /// updated once for the block.
    void applyBlockMarks(std::size_t b, const std::vector<uint8_t>& mask);
    /// Every pixel goes stale (an edit that changes everything): loses its deferred records
    /// and gets the re-traced overlay flag; the counts follow.
    void markAllStale();
    /// The shadows a drag moved, at its release: pixels of block b whose entry of `mask` is
    /// set and whose state is kBase or above go stale and lose their deferred records (the
    /// re-traced overlay stays as it is); the counts follow.
    void applyShadowMarks(std::size_t b, const std::vector<uint8_t>& mask);
    /// Pixels whose state is below s, from the tile counts.
    std::size_t countBelow(uint8_t s) const;
    /// Whether any pixel's state is below s (stops at the first tile that has one).
    bool anyBelow(uint8_t s) const;
    /// Whether the tile counts and summaries describe the pixels (tests check the invariant).
    bool summariesMatchPixels() const;
    /// Writes a tile's results (tile_output.h): traced pixels get every buffer; blocks of an
    /// undersampled pass every buffer but base and segments (cleared); resolved pixels their
    /// colour, base, state and flags; finished ones state and colour (their base); sampled
    /// ones colour, sums, state, flags, cost, bound and appended segments. False, writing
    /// nothing, when `result` is of another generation than `liveGeneration`.
    bool commit(const TileResult& result, uint64_t liveGeneration);

    /// The designer's copy of the frame: `out` is any object with a buffer of the frame's
    /// size (data(), and assignable from the channel's buffer) for each channel the list
    /// shows, named like it. `debug` adds the channels shown only in debug views; the overlay
    /// (flags) has calls of its own, since edits change it outside any tile.
    ///
    /// Whether a shown channel of `out` differs from the frame's in `r` (inside the frame).
    template <class Out>
    bool displayDiffers(const PixelRect& r, const Out& out, bool debug) const;
    /// Copies the shown channels of each of `rects` (inside the frame) into `out`.
    template <class Out>
    void copyDisplay(const std::vector<PixelRect>& rects, Out& out, bool debug) const {
        for (const PixelRect& r : rects) copyDisplay(r, out, debug);
    }
    template <class Out>
    void copyDisplay(const PixelRect& r, Out& out, bool debug) const;
    /// Whether the overlay of `out` differs from the frame's in `r`, and its copy.
    template <class Out>
    bool overlayDiffers(const PixelRect& r, const Out& out) const;
    template <class Out>
    void copyOverlay(const PixelRect& r, Out& out) const;
    /// Every shown channel (the overlay too) whole, `out`'s buffers taking the frame's sizes.
    template <class Out>
    void copyDisplayWhole(Out& out, bool debug) const;

private:
    friend struct DeepFrameTestAccess;  // Tests that set pixels up by hand.

    /// resize() without the clean-up on failure.
    void allocate(int w, int h);
    /// Sets pixel i, of tile `tile`, to state s and keeps the tile's counts.
    void setState(std::size_t i, int tile, uint8_t s) {
        auto& counts = tileStates_[std::size_t(tile)];
        --counts[state_[i]];
        ++counts[s];
        state_[i] = s;
    }
    /// Recomputes the block summaries inside tile `t` from its pixels.
    void summarizeTile(int t);
    /// Recomputes the summary of the block holding pixel (x, y).
    void summarizeBlock(int x, int y);
    /// Recomputes tile t's summary from its blocks' summaries.
    void uniteTileSummary(int t);
    struct Commit;  // What commit()'s steps share (frame_commit.cpp).
    /// commit()'s steps, each one kind of result (tile_output.h).
    void commitTraced(const TileResult& t, Commit& c);
    void commitRecords(const TileResult& t, const Commit& c);
    void commitBlocks(const TileResult& t, Commit& c);
    void commitResolved(const TileResult& t, Commit& c);
    void commitFinished(const TileResult& t, const Commit& c);
    void commitSampled(const TileResult& t, Commit& c);
    /// Rewrites the summaries of the blocks the commit wrote (from what it knows of them, or
    /// from their pixels), then the tile's.
    void summarizeWritten(const Commit& c);
    /// Asks for the lines of pixels [i, i + n) of the channels a traced run writes, in the
    /// list's `ahead` order; its steps: the channels at positions P + 1, one after the other,
    /// and the one at Position.
    void prefetchRunRow(std::size_t i, std::size_t n) const;
    template <int... P>
    void prefetchInOrder(std::size_t i, std::size_t n, std::integer_sequence<int, P...>) const;
    template <int Position>
    void prefetchAt(std::size_t i, std::size_t n) const;

    /// Calls f(channel, out's buffer) for the display channels `debug` selects.
    template <class Out, class F>
    void forShown(Out& out, bool debug, F&& f) const {
        RS_DEEP_FRAME_CHANNELS(RS_CHANNEL_SHOWN)
    }
    /// Calls f(channel, out's buffer) for the overlay channels.
    template <class Out, class F>
    void forOverlay(Out& out, F&& f) const {
        RS_DEEP_FRAME_CHANNELS(RS_CHANNEL_OVERLAY)
    }
    /// Whether rows of `r` differ between frame-sized buffers a and b.
    template <class A, class B>
    bool rectDiffers(const A& a, const B& b, const PixelRect& r) const {
        const std::size_t n = sizeof(a[0]) * std::size_t(r.x1 - r.x0);
        for (int y = r.y0; y < r.y1; ++y) {
            const std::size_t i = index(r.x0, y);
            if (std::memcmp(a.data() + i, b.data() + i, n) != 0) return true;
        }
        return false;
    }
    /// Copies rows of `r` of frame-sized buffer `from` into `to` (whole rows in one go).
    template <class A, class B>
    void copyRect(const A& from, B& to, const PixelRect& r) const {
        if (r.x0 == 0 && r.x1 == width_) {
            std::memcpy(to.data() + index(0, r.y0), from.data() + index(0, r.y0),
                        sizeof(from[0]) * std::size_t(r.y1 - r.y0) * std::size_t(width_));
            return;
        }
        const std::size_t n = sizeof(from[0]) * std::size_t(r.x1 - r.x0);
        for (int y = r.y0; y < r.y1; ++y) {
            const std::size_t i = index(r.x0, y);
            std::memcpy(to.data() + i, from.data() + i, n);
        }
    }

    int width_ = 0;
    int height_ = 0;
    int tileSize_ = 32;
    /// The per-pixel buffers, one per channel of pixel_channels.h (which says what each holds).
    RS_DEEP_FRAME_CHANNELS(RS_CHANNEL_BUFFER)
    std::vector<std::vector<ShadingRecord>> tileRecords_;
    std::vector<uint32_t> tileRecordsKept_;
    std::vector<SegmentVector> tileSegments_;
    std::vector<uint32_t> tileLiveSegments_;
    std::vector<TileSummary> blockSummary_;
    std::vector<TileSummary> tileSummary_;
    std::vector<std::array<uint32_t, 4>> tileStates_;
    std::vector<uint8_t> tileSampled_;
};

#undef RS_CHANNEL_BUFFER
#undef RS_CHANNEL_VIEW
#undef RS_CHANNEL_SHOWN
#undef RS_CHANNEL_OVERLAY

template <class Out>
bool DeepFrame::displayDiffers(const PixelRect& r, const Out& out, bool debug) const {
    bool differs = false;
    forShown(out, debug, [&](const auto& mine, const auto& theirs) {
        differs = differs || rectDiffers(mine, theirs, r);
    });
    return differs;
}

template <class Out>
void DeepFrame::copyDisplay(const PixelRect& r, Out& out, bool debug) const {
    forShown(out, debug, [&](const auto& mine, auto& theirs) { copyRect(mine, theirs, r); });
}

template <class Out>
bool DeepFrame::overlayDiffers(const PixelRect& r, const Out& out) const {
    bool differs = false;
    forOverlay(out, [&](const auto& mine, const auto& theirs) {
        differs = differs || rectDiffers(mine, theirs, r);
    });
    return differs;
}

template <class Out>
void DeepFrame::copyOverlay(const PixelRect& r, Out& out) const {
    forOverlay(out, [&](const auto& mine, auto& theirs) { copyRect(mine, theirs, r); });
}

template <class Out>
void DeepFrame::copyDisplayWhole(Out& out, bool debug) const {
    const auto whole = [](const auto& mine, auto& theirs) { theirs = mine; };
    forShown(out, debug, whole);
    forOverlay(out, whole);
}

}  // namespace rs
