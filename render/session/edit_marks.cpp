// An edit's marks applied to the frame's states and flags, a block at a time.
#include "session/edit_marks.h"

#include <algorithm>

namespace rs {

void applyBlockMarks(DeepFrame& frame, std::size_t b, const std::vector<uint8_t>& mask) {
    constexpr int kBlock = DeepFrame::kBlock;
    const int width = frame.width, height = frame.height;
    const int bx = int(b % std::size_t(frame.blocksX())) * kBlock;
    const int by = int(b / std::size_t(frame.blocksX())) * kBlock;
    const std::size_t n = std::size_t(std::min(width, bx + kBlock) - bx);
    uint32_t was[3] = {0, 0, 0}, marked = 0;
    // Row by row through local pointers (the byte-sized stores may alias anything, which would
    // make the compiler reload each vector's data pointer per pixel), without branches, so the
    // row's bytes are handled together.
    for (int y = by; y < std::min(height, by + kBlock); ++y) {
        const std::size_t i = frame.index(bx, y);
        const uint8_t* m = mask.data() + i;
        uint8_t* s = frame.state.data() + i;
        uint8_t* f = frame.flags.data() + i;
        for (std::size_t k = 0; k < n; ++k) {
            const uint8_t hit = m[k] ? 1 : 0, old = s[k];
            was[0] += hit & uint8_t(old == kStale);
            was[1] += hit & uint8_t(old == kInteractive);
            was[2] += hit & uint8_t(old == kBase);
            marked += hit;
            s[k] = hit ? uint8_t(kStale) : old;
            const uint8_t dropped = uint8_t(kTracedLastUpdate | (hit ? kDeferredValid : 0));
            f[k] = uint8_t((f[k] & ~dropped) | (hit ? kTracedLastUpdate : 0));
        }
    }
    if (marked == 0) return;
    auto& counts = frame.tileStates[std::size_t(frame.tileOfBlock(b))];
    counts[kStale] += marked - was[0];
    counts[kInteractive] -= was[1];
    counts[kBase] -= was[2];
    counts[kFinal] -= marked - was[0] - was[1] - was[2];
}

}  // namespace rs
