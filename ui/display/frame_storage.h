// Frame-sized buffers made ready away from the GUI thread, so that the first copy of a frame
// of a new size does not stop the window while the system hands out fresh pages.
#pragma once

#include <cstddef>
#include <future>

#include "core/large_blocks.h"
#include "scene/document.h"

namespace rs::ui {

/// The per-pixel buffers a DisplayFrame always holds: colour, ids (picking, the outline),
/// depth (picking, orbit pivots) and flags. Listed here once; DisplayFrame is made of them.
struct FrameBuffers {
    LargeVector<Color> color;
    LargeVector<ObjectId> id;
    LargeVector<float> depth;
    LargeVector<uint8_t> flags;

    /// Moves each buffer into `room`'s where that has more capacity, keeping the content, so a
    /// frame of a new size up to that capacity is later copied into memory already written.
    void adopt(FrameBuffers&& room);
};

/// FrameBuffers with room for `pixels` each, every page of them already written once.
struct FrameStorage : FrameBuffers {
    std::size_t pixels = 0;
};

/// Allocates and writes a FrameStorage for `pixels` (any thread). The first write to a fresh
/// page faults; a 1280x976 frame's 25 MB took 75-340 ms of faults on the test machine, which
/// the GUI thread paid, as one stall of the window, when the first frame of that size came.
FrameStorage touchedStorage(std::size_t pixels);

/// Makes FrameStorage on a thread of its own, one request at a time, for the largest frame
/// asked for so far. GUI thread only; destroying it waits for a job still running (at most
/// one frame's worth of page faults).
class FrameStorageMaker {
public:
    FrameStorageMaker() = default;
    FrameStorageMaker(const FrameStorageMaker&) = delete;
    FrameStorageMaker& operator=(const FrameStorageMaker&) = delete;

    /// Frames of `pixels` are coming: storage for them is made unless storage at least that
    /// large was asked for before.
    void request(std::size_t pixels);
    /// The storage made, once it is ready (never waits); empty storage (pixels 0) otherwise.
    FrameStorage take();

private:
    void start(std::size_t pixels);

    std::size_t asked_ = 0;   ///< Largest size asked for.
    std::size_t making_ = 0;  ///< Size of the job running (0: none).
    std::future<FrameStorage> job_;
};

}  // namespace rs::ui
