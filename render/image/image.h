// Linear HDR images: the renderer's output and the tests' references.
#pragma once

#include "core/math.h"

#include <vector>

namespace rs {

/// Row-major linear HDR RGB image, (0, 0) at the top left.
struct ImageRgb {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels;

    ImageRgb() = default;
    ImageRgb(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h)) {}
    Color& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const Color& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

}  // namespace rs
