// A GUI-side copy of the session's deep frame and the CPU shading of its debug views.
#pragma once

#include <QImage>
#include <QRect>
#include <cstdint>
#include <vector>

#include "core/large_blocks.h"
#include "display/frame_storage.h"
#include "scene/document.h"

namespace rs::ui {

/// What the viewport shows of the deep frame.
enum class ViewMode { Color, ObjectIds, Normals, Depth, Cost, Retraced };

/// Whether `mode` shows normals or ray costs, which are handed over only while shown.
bool showsDebugBuffers(ViewMode mode);

/// The buffers the viewport needs, copied out under the frame lock. The controller keeps one
/// and refreshes it in place, rectangle by rectangle; `damage` tells views what changed.
/// The FrameBuffers (colour, ids, depth, flags) are always there; normals and costs only with
/// `debugBuffers`, else empty: an orbit changes every pixel, and copying buffers no view shows
/// was 16 of every 37 bytes a pixel handed over. FrameBuffers::adopt moves the frame into
/// storage made off the GUI thread before a frame of a new size comes (content and serial
/// stay).
struct DisplayFrame : FrameBuffers {
    int width = 0;
    int height = 0;
    LargeVector<Vec3> normal;
    LargeVector<uint32_t> cost;
    ToneMap tonemap = ToneMap::Clamp;
    float exposure = 0.0f;
    uint64_t generation = 0;  ///< Newest edit whose traced pixels this frame holds.
    uint64_t serial = 0;      ///< Bumped whenever the content changes.
    /// Whether a refresh (adapter/frame_handover.h) copies `normal` and `cost`; turning it on
    /// makes the next refresh copy them whole.
    bool debugBuffers = false;

    /// Pixels a refresh changed, tagged with the serial it gave the frame.
    struct Damage {
        uint64_t serial = 0;
        QRect rect;
    };
    std::vector<Damage> damage;  ///< Recent refreshes' rectangles, oldest first.
    /// A view that last looked at a serial below this one must re-read everything.
    uint64_t damageFloor = 0;

    bool empty() const { return width <= 0 || height <= 0; }
    ObjectId idAt(int x, int y) const {
        return x >= 0 && y >= 0 && x < width && y < height ? id[std::size_t(y) * width + x]
                                                           : kNoObject;
    }
    /// The rectangles that changed after `seen`, or false when that serial is too old to say.
    bool changedSince(uint64_t seen, std::vector<QRect>& rects) const;
};

/// Merges tile rectangles into fewer, larger ones covering the same pixels (or more).
std::vector<QRect> mergeRects(std::vector<QRect> rects, const QSize& frame);

/// Debug views other than Color as 8-bit sRGB-ready RGB (row-major, 3 bytes a pixel).
QImage debugImage(const DisplayFrame& frame, ViewMode mode);
/// The tone-mapped colour view (CPU path of the viewport's shader).
QImage toneMappedImage(const DisplayFrame& frame);
/// Tone maps the pixels of `rect` (inside the frame) into the same pixels of `image`, an
/// RGB888 image of the frame's size. A row whose colours have the bits of the row above's in
/// `rect` copies that row's bytes: an undersampled pass repeats each block's value over its
/// rows, so a quarter-resolution frame maps one row in four.
void toneMapRect(const DisplayFrame& frame, const QRect& rect, QImage& image);
/// The selection outline is drawn about this many objects at most (the first of the
/// selection): the OpenGL view passes them to its shader as a fixed-size uniform array.
inline constexpr std::size_t kMaxOutlined = 32;
/// True when `id` is one of the first kMaxOutlined of `selected`.
bool outlined(const std::vector<ObjectId>& selected, ObjectId id);
/// True when pixel (x, y) lies on the selection outline: its id differs from a 4-neighbour
/// and one of the two is outlined.
bool onOutline(const DisplayFrame& frame, int x, int y, const std::vector<ObjectId>& selected);
/// True when pixel (x, y) has a 4-neighbour of another id: onOutline can hold only there, so
/// loops over many pixels test this cheap condition first (most pixels are inside objects).
inline bool atIdEdge(const DisplayFrame& f, int x, int y) {
    const ObjectId* row = f.id.data() + std::size_t(y) * std::size_t(f.width);
    const ObjectId c = row[x];
    return (x > 0 && row[x - 1] != c) || (x + 1 < f.width && row[x + 1] != c) ||
           (y > 0 && row[x - std::ptrdiff_t(f.width)] != c) ||
           (y + 1 < f.height && row[x + std::ptrdiff_t(f.width)] != c);
}
/// The colour of the selection outline.
inline constexpr uint8_t kOutlineRgb[3] = {255, 160, 32};
/// Paints the selection outline (onOutline) over pixels x0..x1 of row y of an RGB888 `line`.
void drawOutlineRow(const DisplayFrame& frame, int y, int x0, int x1,
                    const std::vector<ObjectId>& selected, uint8_t* line);
/// The smallest rectangle holding every pixel whose id is outlined by `a` or by `b`
/// (outlined()); empty when there is none.
QRect outlinedBounds(const DisplayFrame& frame, const std::vector<ObjectId>& a,
                     const std::vector<ObjectId>& b);
/// The image the viewport shows: view mode plus the selection outline.
QImage viewportImage(const DisplayFrame& frame, ViewMode mode,
                     const std::vector<ObjectId>& selected);
/// A well-spread colour for an object id (hashed), as the id debug view and shader use.
void idColor(ObjectId id, uint8_t rgb[3]);

}  // namespace rs::ui
