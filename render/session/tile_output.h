// Internal to the session: what one tile of a pass writes back, as columns the frame's commit
// copies from (structure of arrays; no per-pixel record in between).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/vec_lanes.h"
#include "integrator/trace_kernel.h"
#include "session/dirty_region.h"
#include "session/frame/deep_frame.h"
#include "snapshot/camera_model.h"

namespace rs {

/// Per-pixel capacities of the kernel's record and segment lists.
constexpr int kRecordsPerPixel = 16;
constexpr int kSegmentsPerPixel = 24;

/// Camera rays of one list of a tile and everything the kernel writes back for them.
struct RayList {
    /// Grown without zero-filling first: every new entry is written before it is read (the
    /// kernel fills its outputs; addCentreRun() its rays).
    template <class T>
    using Column = std::vector<T, DefaultInitAllocator<T>>;
    Column<Vec3> origin, dir;
    Column<uint32_t> seed;
    Column<std::size_t> pixel;  ///< Frame index (block entries: the block's top-left).
    Column<uint8_t> extra;      ///< Flags or span packed by the pass.
    Column<Color> color;
    Column<PrimaryInfo> info;
    Column<uint32_t> rays;
    PerRayStorage<ShadingRecord> records;
    PerRayStorage<TreeSegment> segments;
    bool withRecords = false, withSegments = false;  ///< What the latest trace kept.

    void clear() {
        origin.clear(), dir.clear(), seed.clear(), pixel.clear(), extra.clear();
        withRecords = withSegments = false;
    }
    void add(const Ray& ray, uint32_t s, std::size_t i, uint8_t e) {
        origin.push_back(ray.origin);
        dir.push_back(ray.dir);
        seed.push_back(s);
        pixel.push_back(i);
        extra.push_back(e);
    }
    /// Appends the centre rays of pixels [x0, x0 + n) of row y, frame indices from i0, with the
    /// bits camera.generateRay() and pixelSeed(x, y, 0) give them: one rowRays() call for the
    /// run, `columns` holding the columnTerm() of each of its pixels. Returns the first new
    /// ray's index; the caller sets the new rays' `extra`.
    std::size_t addCentreRun(const CameraModel& camera, const Vec3* columns, int x0, int y,
                             std::size_t n, std::size_t i0);
    std::size_t size() const { return origin.size(); }
    /// Traces the list; false when the generation went stale meanwhile.
    bool trace(const TraceKernel& kernel, bool keepRecords, bool keepSegments,
               TraceCounters& counters, const std::function<bool()>& stale);
    /// The hit point of ray k as a bounding sphere of radius 0 (radius < 0 for a miss).
    glm::vec4 hitBound(std::size_t k) const { return hitBoundOf(origin[k], dir[k], info[k]); }

    /// The same for a camera ray and what it hit. Always inlined: the commit's per-pixel loop
    /// called it out of line (1.4-1.8 % of a drag run's samples). With SSE the hit point's
    /// lanes are one multiply and one add (the same bits: lane by lane the same operations,
    /// and a hit's depth is finite, so lane 3 is 0 * depth + 0 = 0).
    [[gnu::always_inline]] static glm::vec4 hitBoundOf(const Vec3& origin, const Vec3& dir,
                                                       const PrimaryInfo& info) {
        if (info.id == kNoObject) return glm::vec4(0.0f, 0.0f, 0.0f, -1.0f);
#if defined(__SSE2__)
        glm::vec4 bound;
        _mm_storeu_ps(&bound.x,
                      _mm_add_ps(lanes(origin), _mm_mul_ps(lanes(dir), _mm_set1_ps(info.depth))));
        return bound;
#else
        return glm::vec4(origin + dir * info.depth, 0.0f);
#endif
    }
};

/// What one tile of a pass writes. Each group is one kind of write, and DeepFrame::commit
/// decides which buffers it touches (deep_frame.h says which); a pixel is in one group.
struct TileResult {
    uint64_t generation = 0;  ///< The pass's generation: a stale result is never written.
    int tile = 0;
    PixelRect rect;
    /// Whether `base` is written: only supersampling reads it, so a scene that does not
    /// supersample leaves it alone (its colour is the centre sample already).
    bool keepBase = true;

    /// Camera rays at pixel centres (Interactive at full resolution, Base), in `tracedState`.
    RayList traced;
    uint8_t tracedState = kBase;
    /// One ray per undersampled block (extra: spanX | spanY << 4), shown over the block.
    RayList blocks;
    /// Deferred shadows resolved: the pixels' full colour and flags, in `resolvedState`.
    std::vector<std::size_t> resolvedPixel;
    std::vector<Color> resolvedColor;
    std::vector<uint8_t> resolvedFlags;
    uint8_t resolvedState = kBase;
    /// Supersampling found nothing to add: the centre sample is final.
    std::vector<std::size_t> finishedPixel;
    /// More samples: each pixel's new totals; its new rays are samples[sampleFirst[k],
    /// sampleFirst[k + 1]) (their segments are appended to the pixel's).
    struct Sampled {
        std::size_t pixel;
        Color color, sum;
        uint16_t count;
        uint8_t state, flags;
        uint32_t cost;
        glm::vec4 hitBound;
    };
    std::vector<Sampled> sampled;
    std::vector<int> sampleFirst;
    RayList samples;

    void clear() {
        traced.clear(), blocks.clear(), samples.clear();
        resolvedPixel.clear(), resolvedColor.clear(), resolvedFlags.clear();
        finishedPixel.clear(), sampled.clear(), sampleFirst.clear();
    }
    /// Pixels whose camera rays were traced (or whose shadows were resolved).
    std::size_t tracedPixels() const {
        return traced.size() + blocks.size() + resolvedPixel.size() + sampled.size();
    }
};

}  // namespace rs
