// Deep frame allocation.
#include "session/deep_frame.h"

namespace rs {

void DeepFrame::resize(int w, int h) {
    width = w;
    height = h;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    color.assign(n, Color(0.0f));
    base.assign(n, Color(0.0f));
    sampleSum.assign(n, Color(0.0f));
    sampleCount.assign(n, 0);
    id.assign(n, kNoObject);
    depth.assign(n, kInfinity);
    normal.assign(n, Vec3(0.0f));
    cost.assign(n, 0);
    state.assign(n, kStale);
    flags.assign(n, 0);
    hitBound.assign(n, glm::vec4(0.0f, 0.0f, 0.0f, -1.0f));
    tileRecords.assign(std::size_t(tilesX()) * std::size_t(tilesY()), {});
    recordStart.assign(n, 0);
    recordCount.assign(n, 0);
}

}  // namespace rs
