// The one trace path: camera rays in batches, then each level of reflection and refraction
// rays, intersected by the snapshot's ray engine and shaded here (the illumination equation
// of scene-format.md, written once). Full renders, every session pass and single rays use it.
#pragma once

#include "integrator/light_sampling.h"
#include "integrator/whitted.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace rs {

/// Camera rays to trace: origin, direction and light-sampling seed of each.
struct CameraBatch {
    const Vec3* origin;
    const Vec3* dir;
    const uint32_t* seed;
    std::size_t count = 0;
    bool coherent = true;  ///< Neighbouring rays are neighbouring pixels.
};

/// Fixed-capacity lists, one per camera ray: list i is data[i * capacity ...], with its
/// length and an overflow flag (more items than fit: the caller must not trust the list).
template <class T>
struct PerRayLists {
    T* data = nullptr;
    int capacity = 0;
    uint8_t* count = nullptr;
    uint8_t* overflow = nullptr;

    explicit operator bool() const { return data != nullptr; }
    void clear(std::size_t ray) const { count[ray] = 0, overflow[ray] = 0; }
    void append(uint32_t ray, const T& value) const {
        uint8_t& c = count[ray];
        if (c < capacity)
            data[std::size_t(ray) * std::size_t(capacity) + c++] = value;
        else
            overflow[ray] = 1;
    }
};

/// Storage for PerRayLists of `capacity` items for n rays, reused between calls.
template <class T>
struct PerRayStorage {
    std::vector<T> items;
    std::vector<uint8_t> count, overflow;

    PerRayLists<T> lists(std::size_t n, int capacity) {
        items.resize(n * std::size_t(capacity));
        count.resize(n), overflow.resize(n);
        return {items.data(), capacity, count.data(), overflow.data()};
    }
    const T* of(std::size_t ray, int capacity) const { return items.data() + ray * std::size_t(capacity); }
};

/// Where the results of camera ray i go. Only `color` is required.
struct TraceOutput {
    Color* color = nullptr;
    PrimaryInfo* primary = nullptr;  ///< First hit and whether the tree met a mirror or glass.
    uint32_t* rays = nullptr;        ///< Rays of the ray's tree, shadow rays included.
    /// Shading records of Deferred shadows (overflow: the pixel must be re-traced).
    PerRayLists<ShadingRecord> records;
    /// Secondary segments of the tree (overflow: the tree is not known whole).
    PerRayLists<TreeSegment> segments;
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
    /// One level: its closest hits, their shading, the next level's rays. Bookkeeping: any
    /// of out.rays, segments, records is asked for; AsDiffuse: the options show mirror or
    /// glass as Lambert. Both are fixed for a call, so they are template parameters.
    template <bool Bookkeeping, bool AsDiffuse>
    void shadeLevel(Workspace& ws, const Level& level, int depth, Level& next,
                    const TraceOutput& out, TraceCounters& counters) const;

    const CompiledScene& scene_;
    TraceOptions options_;
    float eps_;
    LightSampler sampler_;
    /// Each material's Lambert + Phong terms, and as plain Lambert in its colour (the
    /// interaction policies' mirror and glass shown as diffuse).
    std::vector<SurfaceTerms<float>> surfaces_, lamberts_;
    /// Each material's ambient term (the scene's ambient times colour times diffuse), and
    /// as plain Lambert (ambient times colour).
    std::vector<Color> ambients_, lambertAmbients_;
    bool area_ = false;          ///< Sphere lights are sampled over their disk.
    bool traceShadows_ = false;  ///< Shadow rays are traced now (not Off, not Deferred).
    /// Lights sampled at their centre (four points at a time) and over their disk, in the
    /// scene's order; the most samples one point draws.
    std::vector<uint32_t> centreLights_, sampledLights_;
    std::size_t perPoint_ = 0;
};

}  // namespace rs
