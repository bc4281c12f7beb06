// A tile's ray lists: tracing them through the kernel.
#include "session/tile_output.h"

namespace rs {

bool RayList::trace(const TraceKernel& kernel, bool keepRecords, bool keepSegments,
                    TraceCounters& counters, const std::function<bool()>& stale) {
    withRecords = keepRecords;
    withSegments = keepSegments;
    const std::size_t n = size();
    if (n == 0) return true;
    color.resize(n), info.resize(n), rays.resize(n);
    TraceOutput out;
    out.color = color.data();
    out.primary = info.data();
    out.rays = rays.data();
    if (keepRecords) out.records = records.lists(n, kRecordsPerPixel);
    if (keepSegments) out.segments = segments.lists(n, kSegmentsPerPixel);
    return kernel.trace(CameraBatch{origin.data(), dir.data(), seed.data(), n, true}, out, counters,
                        stale);
}

glm::vec4 RayList::hitBound(std::size_t k) const {
    if (info[k].id == kNoObject) return glm::vec4(0.0f, 0.0f, 0.0f, -1.0f);
    return glm::vec4(origin[k] + dir[k] * info[k].depth, 0.0f);
}

}  // namespace rs
