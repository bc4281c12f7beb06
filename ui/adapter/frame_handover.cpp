// Handing the session's deep frame to the display: the whole frame at once, or the tiles
// committed since the last hand-over, copied block by block where the values differ.
#include "adapter/frame_handover.h"

#include <algorithm>

#include "session/frame/deep_frame.h"
#include "session/render_session.h"

namespace rs::ui {

namespace {

/// Rectangles remembered: enough for several refreshes of scattered tiles (a 1280x720 frame
/// has 920); a view that fell further behind redoes everything.
constexpr std::size_t kDamageKept = 4096;

/// Edge of the blocks a tile is split into to find what really changed.
constexpr int kDamageBlock = 8;

PixelRect pixelRect(const QRect& r) {
    return {r.left(), r.top(), r.right() + 1, r.bottom() + 1};
}

}  // namespace

DisplayFrame wholeFrame(const RenderSession& session) {
    DisplayFrame d;
    session.withFrame([&d](const DeepFrame& f, const std::shared_ptr<const CompiledScene>& s) {
        d.width = f.width();
        d.height = f.height();
        d.debugBuffers = true;
        f.copyDisplayWhole(d, d.debugBuffers);
        if (s) {
            d.tonemap = s->settings().tonemap;
            d.exposure = s->settings().exposure;
        }
    });
    return d;
}

void refreshFrame(DisplayFrame& d, const DeepFrame& f, const std::vector<QRect>& rects,
                  bool allFlags) {
    const QRect all(0, 0, f.width(), f.height());
    if (!d.debugBuffers && (!d.normal.empty() || !d.cost.empty())) {
        // No view shows them any more: nothing keeps them current.
        d.normal = {};
        d.cost = {};
    }
    if (f.width() != d.width || f.height() != d.height || d.color.size() != f.color().size() ||
        (d.debugBuffers &&
         (d.normal.size() != f.normal().size() || d.cost.size() != f.cost().size()))) {
        d.width = f.width();
        d.height = f.height();
        f.copyDisplayWhole(d, d.debugBuffers);
        ++d.serial;
        d.damage.clear();
        d.damageFloor = d.serial;
        return;
    }
    if (rects.empty() && !allFlags) return;
    // A tile is announced whole though an edit may re-trace a few of its pixels: only blocks
    // whose values differ are copied and reported, so views re-shade and upload just those.
    std::vector<QRect> changed;
    bool flagsChanged = allFlags;  // Only the debug views show flags: a new serial, no damage.
    for (const QRect& raw : rects) {
        const QRect r = raw & all;
        if (r.isEmpty()) continue;
        if (!allFlags && f.overlayDiffers(pixelRect(r), d)) {
            f.copyOverlay(pixelRect(r), d);
            flagsChanged = true;
        }
        const int bx0 = r.left() / kDamageBlock * kDamageBlock;
        const int by0 = r.top() / kDamageBlock * kDamageBlock;
        for (int by = by0; by <= r.bottom(); by += kDamageBlock) {
            // The band's changed blocks are copied as runs, a row of a run at a time: a pass
            // that re-traced everything copies whole rows instead of 8-pixel pieces (under
            // the frame lock, which the tracers' commits wait for).
            int runStart = -1;
            for (int bx = bx0;; bx += kDamageBlock) {
                bool changedBlock = false;
                if (bx <= r.right()) {
                    const QRect b = QRect(bx, by, kDamageBlock, kDamageBlock) & r;
                    changedBlock = f.displayDiffers(pixelRect(b), d, d.debugBuffers);
                }
                if (changedBlock && runStart < 0) runStart = std::max(bx, r.left());
                if (changedBlock || runStart < 0) {
                    if (bx > r.right()) break;
                    continue;
                }
                // The run ends before this block (or at the rectangle's edge).
                const QRect run = QRect(QPoint(runStart, std::max(by, r.top())),
                                        QPoint(std::min(bx - 1, r.right()),
                                               std::min(by + kDamageBlock - 1, r.bottom())));
                f.copyDisplay(pixelRect(run), d, d.debugBuffers);
                changed.push_back(run);
                runStart = -1;
                if (bx > r.right()) break;
            }
        }
    }
    if (allFlags) f.copyOverlay(PixelRect{0, 0, d.width, d.height}, d);
    if (changed.empty() && !flagsChanged) return;
    ++d.serial;
    for (const QRect& r : mergeRects(std::move(changed), QSize(d.width, d.height)))
        d.damage.push_back({d.serial, r});
    if (d.damage.size() > kDamageKept) {
        const std::size_t n = d.damage.size() - kDamageKept;
        d.damageFloor = std::max(d.damageFloor, d.damage[n - 1].serial);
        d.damage.erase(d.damage.begin(), d.damage.begin() + std::ptrdiff_t(n));
    }
}

}  // namespace rs::ui
