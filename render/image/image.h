// Linear HDR images: the renderer's output and the tests' references.
#pragma once

#include <memory>
#include <new>
#include <utility>
#include <vector>

#include "core/large_blocks.h"
#include "core/math.h"

namespace rs {

/// An allocator whose value-less construct leaves trivial types uninitialised, so a vector
/// can be sized without writing it first (a renderer that writes every pixel need not clear a
/// 1280x720 float image, 11 MB, before it starts); frame-sized blocks get huge pages.
template <class T>
struct DefaultInitAllocator : LargeBlockAllocator<T> {
    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() = default;
    template <class U>
    DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

/// Row-major linear HDR RGB image, (0, 0) at the top left.
struct ImageRgb {
    int width = 0;
    int height = 0;
    std::vector<Color, DefaultInitAllocator<Color>> pixels;

    ImageRgb() = default;
    /// Black.
    ImageRgb(int w, int h)
        : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), Color(0.0f)) {}
    /// Pixels left unwritten: for a caller that writes every one of them.
    static ImageRgb uninitialized(int w, int h) {
        ImageRgb image;
        image.width = w;
        image.height = h;
        image.pixels.resize(std::size_t(w) * std::size_t(h));
        return image;
    }
    Color& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const Color& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

}  // namespace rs
