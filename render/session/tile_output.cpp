// A tile's ray lists: tracing them through the kernel.
#include "session/tile_output.h"

#include "integrator/renderer.h"
#include "integrator/sampling.h"

namespace rs {

std::size_t RayList::addCentreRun(const CameraModel& camera, const Vec3* columns, int x0, int y,
                                  std::size_t n, std::size_t i0) {
    const std::size_t k = size();
    origin.resize(k + n), dir.resize(k + n), seed.resize(k + n), pixel.resize(k + n),
        extra.resize(k + n);
    camera.rowRays(columns, n, float(y) + 0.5f, origin.data() + k, dir.data() + k);
    const uint32_t rowKey = hashKey(uint32_t(y)), centreKey = hashKey(0u);
    uint32_t* seeds = seed.data() + k;
    std::size_t* pixels = pixel.data() + k;
    for (std::size_t j = 0; j < n; ++j) {
        seeds[j] = pixelSeedKeyed(x0 + int(j), rowKey, centreKey);
        pixels[j] = i0 + j;
    }
    return k;
}

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
    if (!kernel.trace(CameraBatch{origin.data(), dir.data(), seed.data(), n, true}, out, counters,
                      stale))
        return false;
    if (keepRecords) records.group();
    if (keepSegments) segments.group();
    return true;
}

}  // namespace rs
