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
    uint32_t was[4] = {0, 0, 0, 0}, marked = 0;
    // Row by row through local pointers: the byte-sized stores may alias anything, which would
    // make the compiler reload each vector's data pointer per pixel. (A version without
    // branches took twice the instructions: marks come in long runs, so the branch predicts.)
    for (int y = by; y < std::min(height, by + kBlock); ++y) {
        const std::size_t i = frame.index(bx, y);
        const uint8_t* m = mask.data() + i;
        uint8_t* s = frame.state.data() + i;
        uint8_t* f = frame.flags.data() + i;
        for (std::size_t k = 0; k < n; ++k) {
            if (m[k]) {
                ++was[s[k] & 3];  // States are <= kFinal.
                ++marked;
                s[k] = kStale;
                f[k] = markedStaleFlags(f[k]);
            } else {
                f[k] = uint8_t(f[k] & ~kTracedLastUpdate);
            }
        }
    }
    if (marked == 0) return;
    auto& counts = frame.tileStates[std::size_t(frame.tileOfBlock(b))];
    for (int s = 0; s < 4; ++s) counts[std::size_t(s)] -= was[s];
    counts[kStale] += marked;
}

}  // namespace rs
