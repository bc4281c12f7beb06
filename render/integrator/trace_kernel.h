// The one trace path: camera rays in batches, then each level of reflection and refraction
// rays, intersected by the snapshot's ray engine and shaded here (the illumination equation
// of scene-format.md, written once). Full renders, every session pass and single rays use it.
#pragma once

#include "integrator/whitted.h"

#include <cstddef>
#include <cstdint>
#include <functional>

namespace rs {

/// Camera rays to trace: origin, direction and light-sampling seed of each.
struct CameraBatch {
    const Vec3* origin;
    const Vec3* dir;
    const uint32_t* seed;
    std::size_t count = 0;
    bool coherent = true;  ///< Neighbouring rays are neighbouring pixels.
};

/// Where the results of camera ray i go. Only `color` is required.
struct TraceOutput {
    Color* color = nullptr;
    PrimaryInfo* primary = nullptr;  ///< First hit and whether the tree met a mirror or glass.
    uint32_t* rays = nullptr;        ///< Rays of the ray's tree, shadow rays included.
    /// Shading records of Deferred shadows: recordCapacity per camera ray at records +
    /// i * recordCapacity; count and overflow per ray (overflow: the pixel must be re-traced).
    ShadingRecord* records = nullptr;
    int recordCapacity = 0;
    uint8_t* recordCount = nullptr;
    uint8_t* recordOverflow = nullptr;
    /// Secondary segments of the tree, as records are stored.
    TreeSegment* segments = nullptr;
    int segmentCapacity = 0;
    uint8_t* segmentCount = nullptr;
    uint8_t* segmentOverflow = nullptr;
};

/// Traces ray trees breadth first through the scene's engine. Each ray carries its camera
/// ray, its accumulated weight and its seed; contributions are added to the camera ray's
/// colour level by level, in the order its own tree spawns them, so a pixel's bits do not
/// depend on which other rays share its batch, on the batch size or on the thread. Work per
/// call is bounded: camera rays are taken a chunk at a time and each level's width is capped.
class TraceKernel {
public:
    TraceKernel(const CompiledScene& scene, const TraceOptions& options);

    /// Traces `rays` into `out`. `stale` (may be empty) is polled between levels; when it
    /// says true the trace stops and returns false, leaving the outputs undefined.
    bool trace(const CameraBatch& rays, const TraceOutput& out, TraceCounters& counters,
               const std::function<bool()>& stale = {}) const;

    /// What Deferred traces' unshadowed light terms at `records` are off by (shadowed minus
    /// unshadowed, times the record's weight), into out[i].
    void resolveDeferred(const ShadingRecord* records, std::size_t count, Color* out,
                         TraceCounters& counters) const;

    /// The id of what each camera ray hits first (kNoObject for nothing), without shading.
    void firstHits(const CameraBatch& rays, ObjectId* ids) const;

    const CompiledScene& scene() const { return scene_; }
    const TraceOptions& options() const { return options_; }

private:
    struct Workspace;
    struct Level;
    bool traceLevels(Workspace& ws, Level& level, int depth, const TraceOutput& out,
                     TraceCounters& counters, const std::function<bool()>& stale) const;
    void shadeLevel(Workspace& ws, const Level& level, int depth, Level& next,
                    const TraceOutput& out, TraceCounters& counters) const;

    const CompiledScene& scene_;
    TraceOptions options_;
    float eps_;
};

}  // namespace rs
