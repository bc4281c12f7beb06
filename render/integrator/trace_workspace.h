// The trace kernel's per-thread storage (internal to the integrator's trace_*.cpp and
// filtered_shadows.cpp): a level's shading points, its light samples and shadow rays.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "core/scratch_arena.h"
#include "integrator/centre_shadows.h"
#include "integrator/light_sampling.h"
#include "integrator/trace_level.h"
#include "snapshot/surface_patterns.h"

namespace rs {

/// A level's shading points as structure of arrays: where and how each is lit (the light
/// lanes read these), and what its sum goes back to.
/// A level's rays that escaped to the environment, gathered to look it up four at a time.
struct EscapedRays {
    ScratchVector<float> x, y, z;  ///< Directions.
    ScratchVector<uint32_t> ray;   ///< The level's ray each is.
    ScratchVector<EnvironmentSpot> spot;
    ScratchVector<Color> color;

    void reserve(std::size_t n) {
        if (ray.size() >= n) return;
        x.resize(n), y.resize(n), z.resize(n), ray.resize(n), spot.resize(n), color.resize(n);
    }
};

struct LevelPoints {
    ShadingPoints shading;           ///< Position, faced normal, direction to the viewer.
    SurfaceArrays surface, lambert;  ///< Their materials' terms, and as plain Lambert.
    /// Their ambient terms, likewise: written only when the scene has patterns (a pattern's
    /// colour differs point by point); flat colours take the kernel's per-material table.
    ScratchVector<Color> ambient, lambertAmbient;
    ScratchVector<uint32_t> material, seed, owner;
    ScratchVector<float> weight;     ///< Accumulated weight of the ray that hit there.
    ScratchVector<float> asDiffuse;  ///< Mirror/glass share shown as Lambert while moving.
    ScratchVector<uint32_t> ray;     ///< The level's ray whose hit each point is.
    ScratchVector<uint8_t> inside;   ///< Per ray of the level: whether its normal was turned.
    CheckerBatch checkers;           ///< Checkered points, while their looks are decided.
    EscapedRays escaped;             ///< The level's misses, with an environment.

    /// Room for n points; none written yet (count() is 0 until finish()). `patterns`: room
    /// for the per-point ambient terms too.
    void reserve(std::size_t n, bool lamberts, bool patterns) {
        shading.resize(n);
        surface.resize(n);
        if (lamberts) lambert.resize(n);
        if (material.size() < n)
            for (auto* v : {&material, &seed, &owner, &ray}) v->resize(n);
        if (weight.size() < n) weight.resize(n), asDiffuse.resize(n);
        if (inside.size() < n) inside.resize(n);
        if (patterns && ambient.size() < n) ambient.resize(n), lambertAmbient.resize(n);
    }
    std::size_t count() const { return shading.count; }
};

/// Per-thread storage reused from call to call: no allocation once it has grown. Its arrays
/// (and Level's, LevelPoints') are ScratchVectors, in the thread's huge-page arena: grown on
/// a cold render's first tiles from 4 KiB pages they cost some 600 page faults of ~10 us.
struct TraceKernel::Workspace {
    Level ping, pong;
    ScratchVector<float> t, nx, ny, nz;
    ScratchVector<uint32_t> slot;
    LevelPoints points;  ///< The points of a level being shaded, lane by lane.
    LightSamples samples, centreSamples;
    LightSpans spans, centreSpans;
    ScratchVector<uint32_t> pointSpans;  ///< First span of each point of a group, plus an end.
    ScratchVector<uint32_t> centrePointSpans;
    ScratchVector<float> sox, soy, soz, sdx, sdy, sdz, stmax;
    ScratchVector<uint32_t> slight;
    ScratchVector<uint8_t> occluded;
    ScratchVector<Color> transmitted;      ///< Per shadow ray: what passed glass (0: blocked).
    ScratchVector<uint32_t> centreBase;    ///< Per centre-sampled light: its first shadow ray.
    std::size_t shadowCount = 0;           ///< Shadow rays written by pushShadow.
    ScratchVector<CentreSamples> centres;  ///< Per centre-sampled light.
    ScratchVector<ScratchVector<uint8_t>> blocked;  ///< Per centre-sampled light and point.
    LightSums sums, lambertSums;
    ScratchVector<uint32_t> cursor;  ///< Each point's next sphere-light span.

    HitBatch hits(std::size_t n) {
        for (auto* v : {&t, &nx, &ny, &nz}) v->resize(n);
        slot.resize(n);
        return {t.data(), nx.data(), ny.data(), nz.data(), slot.data()};
    }
    /// Shadow rays for samples [0, samples.size()) of points [first, first + count) of `pts`,
    /// whose spans pointSpans lists. The rays go from index `base` on, after those
    /// pushShadow wrote.
    void shadowRays(const ShadingPoints& pts, std::size_t first, std::size_t count, float eps,
                    std::size_t base = 0) {
        const std::size_t n = base + samples.size(), lane = std::size_t(kLaneWidth);
        // One lane of slack: origins and lights are written a whole lane at a time.
        if (sox.size() < n + lane)
            for (auto* v : {&sox, &soy, &soz, &sdx, &sdy, &sdz, &stmax}) v->resize(n + lane);
        if (slight.size() < n + lane) slight.resize(n + lane);
        shadowCount = n;
        float *ox = sox.data() + base, *oy = soy.data() + base, *oz = soz.data() + base;
        float *dx = sdx.data() + base, *dy = sdy.data() + base, *dz = sdz.data() + base;
        float* tmax = stmax.data() + base;
        uint32_t* light = slight.data() + base;
        // Every sample lies in exactly one span, the spans in sample order: directions and
        // lengths in one pass over the samples, four at a time.
        const LightSample* s = samples.data();
        std::size_t i = 0;
        static_assert(offsetof(LightSample, dir) == 0 && offsetof(LightSample, dist) == 12,
                      "a sample's first four floats are dir.x, dir.y, dir.z, dist");
        for (; i + lane <= samples.size(); i += lane) {
            // Four samples' (dir, dist) as rows, transposed into lanes.
            FloatLanes r0, r1, r2, r3;
            std::memcpy(&r0, &s[i], sizeof r0), std::memcpy(&r1, &s[i + 1], sizeof r1);
            std::memcpy(&r2, &s[i + 2], sizeof r2), std::memcpy(&r3, &s[i + 3], sizeof r3);
            const FloatLanes t0 = __builtin_shufflevector(r0, r1, 0, 4, 1, 5);
            const FloatLanes t1 = __builtin_shufflevector(r2, r3, 0, 4, 1, 5);
            const FloatLanes t2 = __builtin_shufflevector(r0, r1, 2, 6, 3, 7);
            const FloatLanes t3 = __builtin_shufflevector(r2, r3, 2, 6, 3, 7);
            const FloatLanes x = __builtin_shufflevector(t0, t1, 0, 1, 4, 5);
            const FloatLanes y = __builtin_shufflevector(t0, t1, 2, 3, 6, 7);
            const FloatLanes z = __builtin_shufflevector(t2, t3, 0, 1, 4, 5);
            const FloatLanes t = shadowLength(__builtin_shufflevector(t2, t3, 2, 3, 6, 7), eps);
            std::memcpy(dx + i, &x, sizeof x), std::memcpy(dy + i, &y, sizeof y);
            std::memcpy(dz + i, &z, sizeof z), std::memcpy(tmax + i, &t, sizeof t);
        }
        for (; i < samples.size(); ++i) {
            dx[i] = s[i].dir.x, dy[i] = s[i].dir.y, dz[i] = s[i].dir.z;
            tmax[i] = shadowLength(s[i], eps);
        }
        // Each span's origin and light, a lane at a time: a span's last lane may run into the
        // next span, which is written after it, or into the slack.
        for (std::size_t j = 0; j < count; ++j) {
            const std::size_t q = first + j;
            const Vec3 o = shadowOrigin(Vec3(pts.px[q], pts.py[q], pts.pz[q]),
                                        Vec3(pts.nx[q], pts.ny[q], pts.nz[q]), eps);
            const FloatLanes x = splat(o.x), y = splat(o.y), z = splat(o.z);
            for (uint32_t k = pointSpans[j]; k < pointSpans[j + 1]; ++k) {
                const LightSpan& span = spans[k];
                const uint32_t l[kLaneWidth] = {span.light, span.light, span.light, span.light};
                for (uint32_t r = span.first; r < span.first + span.listed; r += uint32_t(lane)) {
                    std::memcpy(ox + r, &x, sizeof x), std::memcpy(oy + r, &y, sizeof y);
                    std::memcpy(oz + r, &z, sizeof z), std::memcpy(light + r, l, sizeof l);
                }
            }
        }
    }
    /// Room for n shadow rays written through shadowArrays(); none written yet.
    ShadowRayArrays shadows(std::size_t n) {
        if (sox.size() < n)
            for (auto* v : {&sox, &soy, &soz, &sdx, &sdy, &sdz, &stmax}) v->resize(n);
        if (slight.size() < n) slight.resize(n);
        shadowCount = 0;
        return {sox.data(), soy.data(), soz.data(),   sdx.data(),
                sdy.data(), sdz.data(), stmax.data(), slight.data()};
    }
    RayBatch shadowBatch(bool coherent) const {
        RayBatch b{sox.data(), soy.data(), soz.data(),   sdx.data(),
                   sdy.data(), sdz.data(), stmax.data(), shadowCount};
        b.light = slight.data();
        b.coherent = coherent;
        return b;
    }
};

}  // namespace rs
