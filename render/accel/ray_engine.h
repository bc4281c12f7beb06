// The ray-engine layer: geometric queries for batches of rays, nothing about materials or
// light. Two engines answer them: Embree (the default) and the thesis's own BVH.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

#include "accel/primitive.h"
#include "core/math.h"

namespace rs {

/// Which engine a snapshot traces with; a setting of the program, not of the scene.
enum class EngineKind { Embree, Builtin };

/// "embree" or "builtin".
const char* engineName(EngineKind kind);
/// Parses engineName's words; false for anything else.
bool parseEngineKind(std::string_view text, EngineKind& kind);

/// Rays of one batch as structure of arrays: origins, directions (any length), and the far
/// end of each ray's open range (0, tmax). Origins are already offset off their surfaces.
struct RayBatch {
    const float *ox, *oy, *oz, *dx, *dy, *dz, *tmax;
    std::size_t count = 0;
    /// Shadow rays: the light each goes toward (index into SceneGeometry::lights), which an
    /// engine may use to narrow its candidates; null for other rays.
    const uint32_t* light = nullptr;
    /// Neighbouring rays travel alike (a tile's camera rays, one point's samples of a light).
    bool coherent = false;
};

/// Marks a plane in HitBatch::slot; the other bits are its index into SceneGeometry::planes.
inline constexpr uint32_t kPlaneSlot = 0x80000000u;
/// No hit.
inline constexpr uint32_t kNoSlot = 0xffffffffu;

/// Closest-hit answers, one per ray: distance, unit outward world normal (not faced toward
/// the ray) and what was hit: an index into primitives, kPlaneSlot | plane index, or kNoSlot.
struct HitBatch {
    float *t, *nx, *ny, *nz;
    uint32_t* slot;
};

/// One ray's closest hit (single-ray queries: picking, tests, the dirty-region code).
struct EngineHit {
    float t = kInfinity;
    Vec3 n{0.0f};
    uint32_t slot = kNoSlot;
};

/// Answers closest-hit and any-hit queries over one SceneGeometry. Immutable once built and
/// safe to query from any number of threads. Every engine answers with the same rule for
/// planes (FlatSet) and for spheres, boxes and rectangles (intersectPrimitive); meshes may
/// differ in the last bits of t. Answers do not depend on batch size or thread count.
class RayEngine {
public:
    virtual ~RayEngine() = default;
    virtual EngineKind kind() const = 0;

    /// Closest hit of every ray of `rays` into `hits`.
    virtual void closestHit(const RayBatch& rays, const HitBatch& hits) const = 0;
    /// occluded[i] = 1 when anything lies on ray i within (0, tmax[i]), else 0.
    virtual void anyHit(const RayBatch& rays, uint8_t* occluded) const = 0;

    /// One ray: closest hit with t in (0, tmax).
    bool closestHit(const Ray& ray, float tmax, EngineHit& hit) const;
    /// One ray: anything within (0, tmax).
    bool anyHit(const Ray& ray, float tmax) const;

    /// An engine for `geometry`, which differs from this engine's only in the primitives
    /// listed in `moved` (same count and order): refitted or re-committed, not rebuilt.
    virtual std::shared_ptr<const RayEngine> updated(const SceneGeometry& geometry,
                                                     std::span<const uint32_t> moved) const = 0;
};

/// Builds an engine of `kind` over `geometry`. `previous` (may be null, of any kind) lends
/// what can be shared, e.g. the per-mesh structures of meshes both scenes show.
std::shared_ptr<const RayEngine> buildEngine(EngineKind kind, const SceneGeometry& geometry,
                                             const RayEngine* previous = nullptr);

}  // namespace rs
