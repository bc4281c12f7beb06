// The shapes tested without a tree, eight rays at a time: the unbounded planes (thesis 3.1,
// 4.1), for every engine, and, in a small scene, its few world spheres too — the thesis's
// rooms cost least that way. Answers are the bits of the scalar tests (intersect(PlaneShape),
// intersect(SphereShape)) lane by lane, so a batch and a single ray agree exactly. AVX2 where
// the processor has it, chosen at run time; SSE2 otherwise.
#pragma once

#include "accel/primitive.h"
#include "accel/ray_engine.h"

#include <cstdint>
#include <vector>

namespace rs {

class FlatSet {
public:
    /// At most this many world spheres are tested flat. Measured on the room's 8 spheres:
    /// eight lanes against every sphere cost less than a walk of a tree over them.
    static constexpr std::size_t kMaxSpheres = 16;

    /// True when every bounded primitive is a world-space sphere and there are at most
    /// kMaxSpheres of them.
    static bool suits(const std::vector<Primitive>& primitives);

    FlatSet() = default;
    /// The planes, plus `spheres` when not null (which must suit(); the slots answered for
    /// them are indices into it).
    explicit FlatSet(const std::vector<PlanePrimitive>& planes,
                     const std::vector<Primitive>* spheres = nullptr);

    /// Which machine code answers: the best the processor has, or the SSE2 baseline (tests
    /// compare the two).
    enum class Lanes { Best, Baseline };

    /// Closest hit of every ray among the flat shapes (RayEngine::closestHit's contract;
    /// among equally near shapes the first plane, then the first sphere, wins).
    void closestHit(const RayBatch& rays, const HitBatch& hits, Lanes lanes = Lanes::Best) const;
    /// occluded[i] = 1 when a flat shape lies within (0, tmax[i]); rays whose occluded[i] is
    /// already 1 on entry are skipped when `skipBlocked` (an engine's tree answered first).
    void anyHit(const RayBatch& rays, uint8_t* occluded, bool skipBlocked = false,
                Lanes lanes = Lanes::Best) const;

    bool hasSpheres() const { return !tables_.cx.empty(); }
    bool empty() const { return tables_.cx.empty() && tables_.px.empty(); }

    /// The shape tables, structure of arrays (read by the lane loops).
    struct Tables {
        std::vector<float> cx, cy, cz, radius, radius2;
        std::vector<uint32_t> prim;  ///< Index into the primitives of each sphere.
        std::vector<float> px, py, pz, nx, ny, nz;
    };

private:
    Tables tables_;
};

}  // namespace rs
