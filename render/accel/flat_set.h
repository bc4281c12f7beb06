// The shapes tested without a tree: the unbounded planes (thesis 3.1, 4.1), for every engine,
// and, in a small scene, its few bounded objects too — the thesis's rooms cost least that
// way. Planes and world spheres are tested eight rays at a time with the bits of the scalar
// tests (intersect(PlaneShape), intersect(SphereShape)) lane by lane, so a batch and a single
// ray agree exactly (AVX2 where the processor has it, chosen at run time; SSE2 otherwise);
// before its lanes, each group of eight rays drops the world spheres out of reach of the box
// around its segments, and its shadow rays the planes that box lies wholly on one side of
// (conservative culls: the answers keep their bits); boxes, rectangles
// and framed spheres go through intersectPrimitive ray by ray.
#pragma once

#include <cstdint>
#include <vector>

#include "accel/primitive.h"
#include "accel/ray_engine.h"

namespace rs {

class FlatSet {
public:
    /// At most this many bounded objects are tested flat. Measured on the room's 8 spheres
    /// (and one box): testing every one costs less than a walk of a tree over them.
    static constexpr std::size_t kMaxShapes = 16;

    /// True when there are at most kMaxShapes bounded primitives and none is a mesh.
    static bool suits(const std::vector<Primitive>& primitives);

    FlatSet() = default;
    /// The planes, plus `primitives` when not null (which must suit(), and outlive the set;
    /// the slots answered for them are indices into it).
    explicit FlatSet(const std::vector<PlanePrimitive>& planes,
                     const std::vector<Primitive>* primitives = nullptr);

    /// Which machine code answers: the best the processor has, or the SSE2 baseline (tests
    /// compare the two).
    enum class Lanes { Best, Baseline };

    /// Closest hit of every ray among the flat shapes (RayEngine::closestHit's contract;
    /// among equally near shapes the first plane, then the first world sphere, then the
    /// first other primitive wins).
    void closestHit(const RayBatch& rays, const HitBatch& hits, Lanes lanes = Lanes::Best) const;
    /// occluded[i] = 1 when a flat shape lies within (0, tmax[i]); rays whose occluded[i] is
    /// already 1 on entry are skipped when `skipBlocked` (an engine's tree answered first).
    void anyHit(const RayBatch& rays, uint8_t* occluded, bool skipBlocked = false,
                Lanes lanes = Lanes::Best) const;

    /// The shape tables, structure of arrays (read by the lane loops).
    struct Tables {
        std::vector<float> cx, cy, cz, radius, radius2;
        /// Each world sphere's radius widened by its share of the cull's rounding margin.
        std::vector<float> reach;
        std::vector<uint32_t> prim;  ///< Index into the primitives of each world sphere.
        std::vector<float> px, py, pz, nx, ny, nz;
        std::vector<float> pn, nsum, pmag;  ///< Per plane: p . n, |n| in the 1-norm, max |p.i|.
        int planes = 0;  ///< The plane arrays hold this many, padded to a multiple of 8.
        std::vector<float> lox, loy, loz, hix, hiy, hiz;  ///< Widened bounds of the others.
    };

private:
    Tables tables_;
    const std::vector<Primitive>* primitives_ = nullptr;
    std::vector<uint32_t> others_;  ///< Primitives tested with intersectPrimitive.
};

}  // namespace rs
