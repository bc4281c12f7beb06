// FrameStorage: the buffers of a frame of a new size, allocated and written off the GUI thread.
#include "display/frame_storage.h"

#include <chrono>
#include <new>
#include <utility>

namespace rs::ui {

namespace {
template <class T>
void adoptBuffer(LargeVector<T>& mine, LargeVector<T>& room) {
    if (room.capacity() <= mine.capacity()) return;
    room.assign(mine.begin(), mine.end());  // Within its capacity: no new allocation.
    mine.swap(room);
}
}  // namespace

void FrameBuffers::adopt(FrameBuffers&& room) {
    adoptBuffer(color, room.color);
    adoptBuffer(id, room.id);
    adoptBuffer(depth, room.depth);
    adoptBuffer(flags, room.flags);
}

FrameStorage touchedStorage(std::size_t pixels) {
    FrameStorage s;
    s.pixels = pixels;
    // resize() value-initialises: every page is written, so the kernel backs it now.
    s.color.resize(pixels);
    s.id.resize(pixels);
    s.depth.resize(pixels);
    s.flags.resize(pixels);
    return s;
}

void FrameStorageMaker::request(std::size_t pixels) {
    if (pixels <= asked_) return;
    asked_ = pixels;
    if (making_ == 0) start(pixels);
}

void FrameStorageMaker::start(std::size_t pixels) {
    making_ = pixels;
    job_ = std::async(std::launch::async, [pixels] {
        try {
            return touchedStorage(pixels);
        } catch (const std::bad_alloc&) {
            return FrameStorage{};  // The frame's own copy will say so, if it fails too.
        }
    });
}

FrameStorage FrameStorageMaker::take() {
    if (making_ == 0 || job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return {};
    FrameStorage s = job_.get();
    making_ = 0;
    // A larger frame was asked for meanwhile: its storage comes next.
    if (asked_ > s.pixels) start(asked_);
    return s;
}

}  // namespace rs::ui
