// The one trace path: camera rays in batches, then each level of reflection and refraction
// rays, intersected by the snapshot's ray engine and shaded here (the illumination equation
// of scenes/FORMAT.md, written once). Full renders, every session pass and single rays use it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "image/image.h"
#include "integrator/light_sampling.h"
#include "integrator/whitted.h"
#include "snapshot/footprint.h"
#include "snapshot/surface_patterns.h"

namespace rs {

struct LevelPoints;

/// Camera rays to trace: origin, direction and light-sampling seed of each.
struct CameraBatch {
    const Vec3* origin;
    const Vec3* dir;
    const uint32_t* seed;
    std::size_t count = 0;
    bool coherent = true;  ///< Neighbouring rays are neighbouring pixels.
};

/// Lists of up to `capacity` items, one per camera ray, appended densely in the order the
/// trace makes them (level by level), each item with its ray: what a tile keeps stays a few
/// cache lines instead of `capacity` slots a ray. Ray i's list has count[i] items; overflow[i]
/// says more did not fit (the caller must not trust the list). PerRayStorage::group() puts
/// each ray's items together for reading.
template <class T>
struct PerRayLists {
    T* data = nullptr;
    uint32_t* ray = nullptr;  ///< The ray of each appended item.
    std::size_t* used = nullptr;
    bool* unordered = nullptr;  ///< Set when an item's ray is below the one before it.
    int capacity = 0;
    uint8_t* count = nullptr;
    uint8_t* overflow = nullptr;

    explicit operator bool() const { return data != nullptr; }
    void clear(std::size_t r) const { count[r] = 0, overflow[r] = 0; }
};

/// Appends to PerRayLists: the one rule for it (an item a ray up to `capacity`, then the
/// ray's overflow flag; "unordered" once a ray comes below the one before it). The number of
/// items and the latest ray are held here, in registers across a loop of appends, and
/// written back by the destructor: through the lists' pointers, every byte-sized count store
/// would make the compiler reload them.
template <class T>
class PerRayAppender {
public:
    explicit PerRayAppender(const PerRayLists<T>& lists)
        : data_(lists.data),
          ray_(lists.ray),
          count_(lists.count),
          overflow_(lists.overflow),
          capacity_(lists.capacity),
          usedOut_(lists.used),
          unorderedOut_(lists.unordered),
          used_(*lists.used),
          last_(used_ > 0 ? lists.ray[used_ - 1] : 0) {}
    PerRayAppender(const PerRayAppender&) = delete;
    PerRayAppender& operator=(const PerRayAppender&) = delete;
    ~PerRayAppender() {
        *usedOut_ = used_;
        if (unordered_) *unorderedOut_ = true;
    }
    void append(uint32_t r, const T& value) {
        if (count_[r] >= capacity_) {
            overflow_[r] = 1;
            return;
        }
        ++count_[r];
        data_[used_] = value;
        ray_[used_++] = r;
        unordered_ |= r < last_;
        last_ = r;
    }

private:
    T* const data_;
    uint32_t* const ray_;
    uint8_t* const count_;
    uint8_t* const overflow_;
    const int capacity_;
    std::size_t* const usedOut_;  ///< Where the lists keep these (the destructor writes them).
    bool* const unorderedOut_;
    std::size_t used_;
    uint32_t last_;
    bool unordered_ = false;
};

/// Storage for PerRayLists of n rays, reused between calls (grown, never zero-filled).
template <class T>
struct PerRayStorage {
    using Items = std::vector<T, DefaultInitAllocator<T>>;
    Items appended;  ///< In the order the trace made them.
    std::vector<uint32_t, DefaultInitAllocator<uint32_t>> ray;
    std::size_t used = 0;
    bool unordered = false;
    Items items;  ///< Grouped by ray when `appended` is not.
    std::vector<uint32_t>
        first;  ///< Ray i's items are of(i)[0, count[i]): [first[i], first[i + 1]).
    std::vector<uint8_t> count, overflow;

    /// Empty lists for n rays of at most `capacity` items each.
    PerRayLists<T> lists(std::size_t n, int capacity) {
        const std::size_t most = n * std::size_t(capacity);
        if (appended.size() < most) appended.resize(most), ray.resize(most);
        count.resize(n), overflow.resize(n);
        used = 0;
        unordered = false;
        return {appended.data(), ray.data(),   &used,          &unordered,
                capacity,        count.data(), overflow.data()};
    }
    /// After the lists are written: each ray's items together, in the order they were
    /// appended (a stable counting sort by ray).
    void group() {
        const std::size_t n = count.size();
        first.resize(n + 1);
        uint32_t at = 0;
        for (std::size_t i = 0; i < n; ++i) first[i] = at, at += count[i];
        first[n] = at;
        if (!unordered) return;  // A tree of one level: in ray order already, not copied.
        // Out of order (a deeper level's items after a later ray's): scattered to their rays'
        // places.
        items.resize(used);
        thread_local std::vector<uint32_t> next;
        next.assign(first.begin(), first.end() - 1);
        for (std::size_t j = 0; j < used; ++j) items[next[ray[j]]++] = appended[j];
    }
    /// Ray r's items (count[r] of them), after group().
    const T* of(std::size_t r) const { return (unordered ? items : appended).data() + first[r]; }
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
    // shadeLevel's steps, each inlined into it (the shading loop is the hot path).
    struct PointGroup;
    /// Each hit of `level`: a miss's environment or background added to its camera ray, a
    /// shaded hit's point written to `pts`, its reflection and refraction rays to `next`.
    /// Returns the points written.
    template <bool AsDiffuse>
    std::size_t shadeHits(LevelPoints& pts, const Level& level, const HitBatch& hits, int depth,
                          Level& next, const TraceOutput& out) const;
    /// The reflection and refraction rays of a hit at p (faced normal nf, ray direction d).
    void spawnChildren(const CompiledMaterial& m, float reflectivity, float transparency,
                       const Vec3& p, const Vec3& nf, const Vec3& d, bool inside, float weight,
                       uint32_t seed, uint32_t owner, float width, Level& next) const;
    /// Shading point j takes the place and facing of its ray's hit (points are `count` of
    /// the level's `n` rays).
    static void closeUpPoints(LevelPoints& pts, std::size_t count, std::size_t n);
    /// Patterned points' colours, and every point's ambient terms.
    template <bool AsDiffuse>
    void patternLooks(LevelPoints& pts, const Level& level, const HitBatch& hits) const;
    /// The lights' terms of every shading point, group by group, added to the outputs.
    template <bool Bookkeeping, bool AsDiffuse>
    void addLocalTerms(Workspace& ws, bool patterns, const TraceOutput& out,
                       TraceCounters& counters) const;
    /// A group's light samples: sphere lights' point by point, centre lights' in lanes.
    void sampleGroup(Workspace& ws, const PointGroup& g) const;
    /// A group's shadow rays as one batch, and their answers back to its points.
    template <bool Bookkeeping>
    void traceGroupShadows(Workspace& ws, PointGroup& g, const TraceOutput& out,
                           TraceCounters& counters) const;
    /// A group's light sums, light by light in the scene's order.
    template <bool AsDiffuse>
    void sumGroupLights(Workspace& ws, const PointGroup& g) const;
    /// A group's local terms (ambient plus its light sums) added to its camera rays.
    template <bool Bookkeeping, bool AsDiffuse, bool Patterned>
    void addGroupLocal(Workspace& ws, const PointGroup& g, const TraceOutput& out) const;
    /// What a level adds to the outputs besides colour: each ray counted to its camera ray,
    /// its segment (below the camera level), the first hit and whether a mirror or glass was
    /// met. A loop of its own, so the shading loop is the one a colour-only trace runs.
    void keepBooks(const Level& level, const HitBatch& hits, int depth,
                   const TraceOutput& out) const;

    /// The colour a shadow ray keeps from `origin` along unit `dir` to `tmax` through
    /// transparent surfaces (0 when something opaque blocks it), by closest hits.
    Color transmission(const Vec3& origin, const Vec3& dir, float tmax) const;
    /// transmission() of each occluded shadow ray of the workspace's batch, into
    /// ws.transmitted (0 for the rays that were not occluded).
    void transmit(Workspace& ws) const;
    /// Adds what centre-sampled light `li` gives points [first, end) through glass.
    template <bool AsDiffuse>
    void addTransmitted(Workspace& ws, uint32_t li, std::size_t first, std::size_t end) const;
    /// Material `m`'s colour at world point p (unit normal n) of engine slot `slot`, reached
    /// along `dir` by a cone `width` wide: the one place a surface's colour at a point is
    /// decided (its checker or image, else its flat colour); patternLooks gathers a level's
    /// checkered points to run their filters together, to the same bits.
    Color surfaceColor(const CompiledMaterial& m, uint32_t slot, const Vec3& p, const Vec3& n,
                       const Vec3& dir, float width) const {
        if (m.pattern.kind == MaterialPattern::Kind::None) return m.color;
        return patternColor(m.pattern, scene_.patterns().at(slot), p, n, dir, width);
    }
    /// A deferred shading record's Lambert + Phong terms.
    SurfaceTerms<float> recordTerms(const ShadingRecord& r) const;

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
    /// 1 for each material that reflects or refracts (a pixel's tree that meets it is marked).
    std::vector<uint8_t> specular_;
    bool area_ = false;          ///< Sphere lights are sampled over their disk.
    bool transmissive_ = false;  ///< Shadow rays pass transparent surfaces (filtered).
    float spread_ = 0.0f;        ///< A cone's growth in width per unit travelled (perspective).
    float originWidth_ = 0.0f;   ///< A camera ray's cone width at its origin (orthographic).
    bool traceShadows_ = false;  ///< Shadow rays are traced now (not Off, not Deferred).
    /// Lights sampled at their centre (four points at a time) and over their disk, in the
    /// scene's order; the most samples one point draws.
    std::vector<uint32_t> centreLights_, sampledLights_;
    std::size_t perPoint_ = 0;
};

}  // namespace rs
