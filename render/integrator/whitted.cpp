// Single camera rays through the trace kernel.
#include "integrator/whitted.h"

#include <algorithm>

#include "integrator/trace_kernel.h"

namespace rs {

namespace {
constexpr int kSinkLimit = 255;  // the kernel counts a ray's records and segments in a byte
}

WhittedIntegrator::WhittedIntegrator(const CompiledScene& scene)
    : WhittedIntegrator(scene, TraceOptions::fromSettings(scene.settings())) {}

WhittedIntegrator::WhittedIntegrator(const CompiledScene& scene, const TraceOptions& options)
    : kernel_(std::make_shared<const TraceKernel>(scene, options)) {}

Color WhittedIntegrator::traceCamera(const Ray& ray, uint32_t seed, TraceCounters& counters,
                                     PrimaryInfo* primary, RecordSink* sink,
                                     SegmentSink* segments) const {
    Color color;
    PrimaryInfo info;
    uint8_t recordCount = 0, recordOverflow = 0, segmentCount = 0, segmentOverflow = 0;
    // One ray: its lists, appended densely, are the sinks as they are (every item is ray 0's).
    uint32_t rayOf[kSinkLimit];
    std::size_t records = 0, segmentsUsed = 0;
    bool unordered = false;  // One ray: never.
    TraceOutput out;
    out.color = &color;
    out.primary = &info;
    if (sink && sink->capacity > 0)
        out.records = {sink->data,
                       rayOf,
                       &records,
                       &unordered,
                       std::min(sink->capacity, kSinkLimit),
                       &recordCount,
                       &recordOverflow};
    if (segments && segments->capacity > 0)
        out.segments = {segments->data,
                        rayOf,
                        &segmentsUsed,
                        &unordered,
                        std::min(segments->capacity, kSinkLimit),
                        &segmentCount,
                        &segmentOverflow};
    kernel_->trace(CameraBatch{&ray.origin, &ray.dir, &seed, 1, true}, out, counters);
    if (primary) *primary = info;
    if (sink) {
        sink->count = recordCount;
        sink->overflow = recordOverflow != 0;
    }
    if (segments) {
        segments->count = segmentCount;
        segments->overflow = segmentOverflow != 0;
    }
    return color;
}

Color WhittedIntegrator::resolveDeferred(const ShadingRecord& record,
                                         TraceCounters& counters) const {
    Color out;
    kernel_->resolveDeferred(&record, 1, &out, counters);
    return out;
}

}  // namespace rs
