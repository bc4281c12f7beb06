// Full-quality tracing of flat scenes eight rays at a time, bit-identical to the integrator.
#pragma once

#include "integrator/whitted.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace rs {

struct PacketTables;

/// One pixel from PacketTracer::tracePixels: what traceCamera gives with a PrimaryInfo and a
/// SegmentSink, and the rays it traced (shadow rays included).
struct PacketPixel {
    Color color{0.0f};
    PrimaryInfo info;
    Vec3 hitPoint{0.0f};  ///< The camera ray's Ray::at(info.depth) when it hit something.
    uint32_t rays = 0;
    uint32_t segmentOffset = 0;    ///< Its secondary segments in tracePixels' `segments`...
    uint32_t segmentCount = 0;     ///< ...at most the capacity asked for,
    bool segmentOverflow = false;  ///< and whether more were dropped (SegmentSink::overflow).
};

/// Traces camera rays in packets of eight (a tile's centre rays, a list of pixels, or each
/// sample of supersampled pixels): the camera rays first, then each level of their reflection
/// and refraction rays, every level intersected and shaded in eight-lane SIMD. Each lane does
/// WhittedIntegrator's operations in the same order, and the ray trees are summed leaves-up
/// the way trace() adds them, so every colour, id, normal, ray count and segment is
/// bit-identical to traceCamera's at the scene's render settings (tested). Full renders use
/// it, and so do the session's full-quality passes; the session's reduced-quality passes
/// (deferred shadows, diffuse mirrors, ...) keep the scalar integrator.
///
/// Why: the scalar integrator walks one ray tree after another, and its data-dependent
/// branches (which shape, which material, shadowed or not) leave the core waiting on one
/// chain of divisions and square roots at a time. Eight neighbouring rays share those steps.
class PacketTracer {
public:
    /// True when `scene` qualifies: its bounded objects are tested flat (a few world spheres)
    /// and no light is sampled as a sphere (point lights, or no shadow samples).
    static bool supports(const CompiledScene& scene);

    /// True when this CPU runs the eight-lane kernel in single registers (AVX2 on x86-64), so
    /// it beats the scalar integrator; elsewhere the kernel is still exact, only slower.
    static bool profitable();

    /// Which machine code traces: the fastest this CPU runs, or the baseline build (so tests
    /// check both on an AVX2 machine).
    enum class Kernel { Fastest, Baseline };

    explicit PacketTracer(const CompiledScene& scene, Kernel kernel = Kernel::Fastest);
    ~PacketTracer();
    PacketTracer(const PacketTracer&) = delete;
    PacketTracer& operator=(const PacketTracer&) = delete;

    /// Traces the centre ray of each pixel in [x0, x1) x [y0, y1) at the scene's render
    /// settings. Writes the colour and, when `ids` and `normals` are not null, the first
    /// hit's id and normal as traceCamera's PrimaryInfo has them, into image-sized row-major
    /// arrays of width `stride`. `subset` is cullTile's for the same pixels.
    void traceTile(int x0, int y0, int x1, int y1, const RaySubset& subset, std::size_t stride,
                   Color* colors, ObjectId* ids, Vec3* normals, TraceCounters& counters) const;

    /// Traces the centre rays of pixels (xs[i], ys[i]), i < count, into out[i], appending each
    /// pixel's secondary segments to `segments` as a SegmentSink of `segmentCapacity` would
    /// hold them. For the interactive session's full-quality passes. `subset` is cullTile's for
    /// a rectangle holding the pixels.
    void tracePixels(const int32_t* xs, const int32_t* ys, std::size_t count,
                     const RaySubset& subset, int segmentCapacity, PacketPixel* out,
                     std::vector<TreeSegment>& segments, TraceCounters& counters) const;

    /// renderPixel's colours for pixels (xs[i], ys[i]) with `spp` samples each (its pattern,
    /// its seeds, its order of summing) into out[i].
    void traceSamples(const int32_t* xs, const int32_t* ys, std::size_t count, int spp,
                      const RaySubset& subset, Color* out, TraceCounters& counters) const;

    /// The id of what the centre ray of pixel (xs[i], ys[i]) hits first (kNoObject for
    /// nothing) into out[i], without shading: renderImage's ids when it supersamples.
    void firstHits(const int32_t* xs, const int32_t* ys, std::size_t count,
                   const RaySubset& subset, ObjectId* out) const;

private:
    const CompiledScene& scene_;
    std::unique_ptr<PacketTables> tables_;  ///< What the kernel gathers per lane.
    Kernel kernel_;
    int maxDepth_;
    bool shadows_;  ///< Shadow rays are traced (shadow_samples > 0).
    float eps_;
};

}  // namespace rs
