// The light terms of the illumination equation (scenes/FORMAT.md), written once: where a
// shading point samples each light, and what those samples add given which are shadowed.
// The trace kernel, deferred shadows and every engine's shadow queries go through these.
#pragma once

#include <cstdint>
#include <vector>

#include "core/lanes.h"
#include "core/scratch_arena.h"
#include "integrator/sampling.h"
#include "snapshot/compiled_scene.h"

namespace rs {

/// POV-Ray's spotlight fall-off with tightness 0: 1 inside the radius cone, 0 outside the
/// falloff cone, the cubic 3t^2 - 2t^3 of t = (cos - cosFalloff) / (cosRadius - cosFalloff)
/// between. `cosTheta` is the cosine of the angle between the light's axis and the direction
/// from the light to the point. (One value, or a lane of them.)
template <class F>
inline F spotFactor(const CompiledLight& l, F cosTheta) {
    const float width = l.cosRadius - l.cosFalloff;
    if (!(width > 0.0f)) return select(cosTheta >= l.cosRadius, F{} + 1.0f, F{});
    F t = (cosTheta - l.cosFalloff) * (1.0f / width);
    t = select(t < 0.0f, F{}, select(t > 1.0f, F{} + 1.0f, t));
    return (3.0f - 2.0f * t) * t * t;
}
/// The light's factor for a unit direction `toLight` from the shaded point: spotFactor for
/// spot lights, else 1.
inline float lightFactor(const CompiledLight& l, const Vec3& toLight) {
    return l.spot ? spotFactor(l, -glm::dot(l.axis, toLight)) : 1.0f;
}

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

/// A shading point's light samples and their spans, per-thread scratch (the trace kernel's
/// workspace keeps them from call to call). The structures of arrays below are scratch too
/// (core/scratch_arena.h): kept in a thread's workspace or on its stack, never past its end.
using LightSamples = ScratchVector<LightSample>;
using LightSpans = ScratchVector<LightSpan>;

/// Shading points as structure of arrays, padded to whole lanes (so lane loops may read the
/// last group whole): position, unit normal facing the viewer, unit direction to the viewer.
struct ShadingPoints {
    ScratchVector<float> px, py, pz, nx, ny, nz, vx, vy, vz;
    std::size_t count = 0;

    /// Room for n points (and the padding); count becomes n, the contents are to be written.
    void resize(std::size_t n);
    void set(std::size_t i, const Vec3& p, const Vec3& n, const Vec3& toViewer) {
        px[i] = p.x, py[i] = p.y, pz[i] = p.z;
        nx[i] = n.x, ny[i] = n.y, nz[i] = n.z;
        vx[i] = toViewer.x, vy[i] = toViewer.y, vz[i] = toViewer.z;
    }
};

/// What Lambert + Phong need of a material (one, or a lane of them): diffuse * colour, the
/// specular coefficient, the R.V below which the highlight is skipped, and the shininess.
template <class F>
struct SurfaceTerms {
    F r, g, b, specular, cutoff, shininess;
};
SurfaceTerms<float> surfaceTerms(const CompiledMaterial& m);

/// What shading takes of a surface seen in colour `c` (a material's flat colour, or its
/// pattern's colour at a point): its Lambert + Phong terms and its ambient term.
struct SurfaceLook {
    SurfaceTerms<float> terms;
    Color ambient;
};
/// Material `m` in colour `c` under the scene's `ambient`: diffuse x colour, the material's
/// highlight, ambient x colour x diffuse.
inline SurfaceLook materialLook(const CompiledMaterial& m, const Color& c, const Color& ambient) {
    const Color diffuseColor = m.diffuse * c;
    return {
        {diffuseColor.x, diffuseColor.y, diffuseColor.z, m.specular, m.specularCutoff, m.shininess},
        ambient * c * m.diffuse};
}
/// Any material in colour `c` as plain Lambert (diffuse 1, no highlight): how the interaction
/// policies show mirror and glass shares while moving (thesis 4.2).
inline SurfaceLook lambertLook(const Color& c, const Color& ambient) {
    return {{c.x, c.y, c.z, 0.0f, 0.0f, 0.0f}, ambient * c};
}

/// SurfaceTerms of each shading point of a ShadingPoints, structure of arrays, padded alike.
struct SurfaceArrays {
    ScratchVector<float> r, g, b, specular, cutoff, shininess;

    void resize(std::size_t n);
    void set(std::size_t i, const SurfaceTerms<float>& t) {
        r[i] = t.r, g[i] = t.g, b[i] = t.b;
        specular[i] = t.specular, cutoff[i] = t.cutoff, shininess[i] = t.shininess;
    }
    SurfaceTerms<float> get(std::size_t i) const {
        return {r[i], g[i], b[i], specular[i], cutoff[i], shininess[i]};
    }
};

/// One light's sample toward its centre from each of a ShadingPoints' points (a point light,
/// or any light when sphere lights are not sampled): LightSample's fields and whether it is
/// listed, structure of arrays.
struct CentreSamples {
    ScratchVector<float> dx, dy, dz, dist, nl;
    ScratchVector<uint8_t> listed;
};

/// Sums of light terms (r, g, b) of each point of a ShadingPoints, padded alike.
struct LightSums {
    ScratchVector<float> r, g, b;
    /// n points, all sums 0.
    void zero(std::size_t n);
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
    void sample(const Vec3& p, const Vec3& n, uint32_t seed, bool area, LightSamples& samples,
                LightSpans& spans) const;

    /// True when light `li` is sampled at its centre alone (sample()'s rule): a point light,
    /// or any light when not `area` or when the scene asks for no shadow samples.
    bool centreOnly(std::size_t li, bool area) const {
        return !(area && scene_.lights()[li].radius > 0.0f && shadowSamples_ > 0);
    }
    /// sample()'s samples of light `li` alone, appended with their span when any is listed.
    void sampleLight(std::size_t li, const Vec3& p, const Vec3& n, uint32_t seed, bool area,
                     LightSamples& samples, LightSpans& spans) const;
    /// Light `li`'s centre sample from points [first, end) of `points` (first a multiple of
    /// kLaneWidth), four points at a time: the bits sample() gives for each point alone.
    void sampleCentres(std::size_t li, const ShadingPoints& points, std::size_t first,
                       std::size_t end, CentreSamples& out) const;

private:
    const CompiledScene& scene_;
    DiskStrata strata_;  ///< The sub-grid of shadow_samples points on a sphere light's disk.
    int shadowSamples_;  ///< The scene's shadow_samples.
    int laned_;          ///< A sphere light's samples [0, laned_) are taken in lanes.
};

/// The format's inner sum over lights: Lambert plus Phong of surface terms `surface` for the
/// listed samples. A sample that `occluded` (indexed like samples; null: none is) says is
/// blocked adds nothing, unless `transmitted` (indexed alike; null: nothing is) gives the
/// colour that passed the glass on its way: then it adds its term times that colour.
Color shadeLights(const CompiledScene& scene, const SurfaceTerms<float>& surface, const Vec3& n,
                  const Vec3& toViewer, const LightSpan* spans, std::size_t spanCount,
                  const LightSample* samples, const uint8_t* occluded,
                  const Color* transmitted = nullptr);

/// What one span of samples adds to shadeLights' sum: its unshadowed (or transmitted)
/// samples' Lambert + Phong terms for `surface`, times the light's power and spot factor,
/// over the samples drawn.
Color spanShare(const CompiledScene& scene, const SurfaceTerms<float>& surface, const Vec3& n,
                const Vec3& toViewer, const LightSpan& span, const LightSample* samples,
                const uint8_t* occluded, const Color* transmitted = nullptr);

/// One unshadowed sample's share of light `light` (one of `drawn`): its term for `surface`
/// times power and spot factor over drawn. The kernel adds it times the colour a shadow ray
/// kept through glass.
Color sampleShare(const CompiledLight& light, const SurfaceTerms<float>& surface, const Vec3& n,
                  const Vec3& toViewer, const LightSample& s, float drawn);

/// shadeLights' term of centre-sampled light `light` for points [first, end) of `points`
/// (first a multiple of kLaneWidth), four at a time, added to `sums`: the samples `centres`,
/// each skipped where `blocked` (indexed by point; null: none is). The bits of spanShare.
void addCentreLight(const CompiledLight& light, const ShadingPoints& points,
                    const SurfaceArrays& surface, const CentreSamples& centres,
                    const uint8_t* blocked, std::size_t first, std::size_t end, LightSums& sums);

/// Where a shadow ray toward `s` starts (off the surface along n) and how far it goes: it
/// stops epsilon short of the light's point. (A point, or one coordinate of one or of a lane
/// of them: each coordinate is p + n eps.)
template <class V>
inline V shadowOrigin(const V& p, const V& n, float eps) {
    return p + n * eps;
}
/// (One distance, or a lane of them.)
template <class F>
inline F shadowLength(F dist, float eps) {
    return dist - eps;
}
inline float shadowLength(const LightSample& s, float eps) {
    return shadowLength(s.dist, eps);
}

}  // namespace rs
