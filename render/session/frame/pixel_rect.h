// A screen rectangle in pixels: what tiles cover, edits mark and the display copies.
#pragma once

namespace rs {

/// Screen rectangle [x0, x1) x [y0, y1) in pixels.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    int area() const { return empty() ? 0 : (x1 - x0) * (y1 - y0); }
};

}  // namespace rs
