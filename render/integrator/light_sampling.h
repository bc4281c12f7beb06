// The light terms of the illumination equation (scene-format.md), written once: where a
// shading point samples each light, and what those samples add given which are shadowed.
// The trace kernel, deferred shadows and every engine's shadow queries go through these.
#pragma once

#include "integrator/sampling.h"
#include "snapshot/compiled_scene.h"

#include <cstdint>
#include <vector>

namespace rs {

/// One light sample seen from a shading point: unit direction and distance to the point of
/// the light, and n . dir (> 0: samples below the horizon are never listed).
struct LightSample {
    Vec3 dir;
    float dist;
    float nl;
};

/// The samples of one light at one shading point: samples [first, first + listed) of the
/// list, and how many were drawn (the average divides by all of them, listed or not).
struct LightSpan {
    uint32_t light;
    uint32_t first;
    uint32_t listed;
    uint32_t drawn;
};

/// Where shading points sample a scene's lights. What depends on the scene alone (the
/// stratification of sphere lights) is worked out once, when the sampler is made, not per
/// point: a trace kernel makes one and samples tens of thousands of points with it.
class LightSampler {
public:
    /// Four: a sphere light's samples are worked out four at a time (the bits of one at a
    /// time, which One does; tests compare the two).
    enum class Lanes { Four, One };

    explicit LightSampler(const CompiledScene& scene, Lanes lanes = Lanes::Four);

    /// Appends the samples of every light seen from point `p` with unit normal `n` (facing
    /// the viewer): `shadowSamples` stratified points of each sphere light when `area`, else
    /// the light's centre; `seed` decorrelates the pattern per camera sample.
    void sample(const Vec3& p, const Vec3& n, uint32_t seed, bool area,
                std::vector<LightSample>& samples, std::vector<LightSpan>& spans) const;

private:
    const CompiledScene& scene_;
    DiskStrata strata_;  ///< The sub-grid of shadow_samples points on a sphere light's disk.
    int shadowSamples_;  ///< The scene's shadow_samples.
    int laned_;          ///< A sphere light's samples [0, laned_) are taken in lanes.
};

/// The format's inner sum over lights: Lambert plus Phong of material `m` for the listed
/// samples, each skipped when `occluded` (indexed like samples; null: none is) says so.
Color shadeLights(const CompiledScene& scene, const CompiledMaterial& m, const Vec3& n,
                  const Vec3& toViewer, const LightSpan* spans, std::size_t spanCount,
                  const LightSample* samples, const uint8_t* occluded);

/// Where a shadow ray toward `s` starts (off the surface along n) and how far it goes: it
/// stops epsilon short of the light's point.
inline Vec3 shadowOrigin(const Vec3& p, const Vec3& n, float eps) { return p + n * eps; }
inline float shadowLength(const LightSample& s, float eps) { return s.dist - eps; }

}  // namespace rs
