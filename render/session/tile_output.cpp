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

}  // namespace rs
