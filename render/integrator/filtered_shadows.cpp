// Shadows through glass (scenes/FORMAT.md "Shadows"): a shadow ray the engine reports
// blocked walks on by closest hits, keeping transparency x colour at each transparent
// surface (its colour there from surfaceColor), and what it kept is added to the light's term.
#include "integrator/trace_kernel.h"
#include "integrator/trace_workspace.h"

namespace rs {

Color TraceKernel::transmission(const Vec3& origin, const Vec3& dir, float tmax) const {
    // A shadow ray through glass (scenes/FORMAT.md "Shadows"): each transparent surface it
    // crosses keeps transparency x colour of the light, no bending; anything opaque stops it.
    constexpr int kMostCrossings = 64;
    Color kept(1.0f);
    Vec3 o = origin;
    float left = tmax;
    // The walk counts as the one shadow ray it continues (per-pixel counts stay exact).
    for (int crossing = 0; crossing < kMostCrossings; ++crossing) {
        EngineHit hit;
        if (!scene_.engine().closestHit(Ray::make(o, dir), left, hit)) return kept;
        uint32_t mi;
        ObjectId id;
        scene_.describe(hit.slot, mi, id);
        const CompiledMaterial& m = scene_.materials()[mi];
        if (!(m.transparency > 0.0f)) return Color(0.0f);
        const Vec3 p = o + dir * hit.t;
        // The tint is filtered as finely as the camera sees that point of the glass: a pixel's
        // cone there (a shadow carries no cone of its own, and point samples of a texture
        // alias and read its finest level at random).
        const float width = originWidth_ + spread_ * glm::length(p - scene_.camera().origin());
        kept *= m.transparency * surfaceColor(m, hit.slot, p, hit.n, dir, width);
        if (kept == Color(0.0f)) return kept;
        o = p + dir * eps_;
        left -= hit.t + eps_;
        if (!(left > 0.0f)) return kept;
    }
    return Color(0.0f);  // More glass than that: treated as blocking.
}

SurfaceTerms<float> TraceKernel::recordTerms(const ShadingRecord& r) const {
    const CompiledMaterial& m = scene_.materials()[r.material];
    return {r.diffuse.x, r.diffuse.y, r.diffuse.z, m.specular, m.specularCutoff, m.shininess};
}

void TraceKernel::transmit(Workspace& ws) const {
    const std::size_t n = ws.shadowCount;
    if (ws.transmitted.size() < n) ws.transmitted.resize(n);
    for (std::size_t r = 0; r < n; ++r)
        ws.transmitted[r] = ws.occluded[r]
                                ? transmission(Vec3(ws.sox[r], ws.soy[r], ws.soz[r]),
                                               Vec3(ws.sdx[r], ws.sdy[r], ws.sdz[r]), ws.stmax[r])
                                : Color(0.0f);
}

template <bool AsDiffuse>
void TraceKernel::addTransmitted(Workspace& ws, uint32_t li, std::size_t first,
                                 std::size_t end) const {
    // Centre rays were written for the listed points in point order (writeCentreShadows).
    const CompiledLight& light = scene_.lights()[li];
    const CentreSamples& c = ws.centres[li];
    const ShadingPoints& sp = ws.points.shading;
    uint32_t r = ws.centreBase[li];
    for (std::size_t j = first; j < end; ++j) {
        if (!c.listed[j]) continue;
        const Color kept = ws.transmitted[r++];
        if (kept == Color(0.0f)) continue;
        const LightSample s{Vec3(c.dx[j], c.dy[j], c.dz[j]), c.dist[j], c.nl[j]};
        const Vec3 n(sp.nx[j], sp.ny[j], sp.nz[j]), v(sp.vx[j], sp.vy[j], sp.vz[j]);
        const Color add = kept * sampleShare(light, ws.points.surface.get(j), n, v, s, 1.0f);
        ws.sums.r[j] += add.x, ws.sums.g[j] += add.y, ws.sums.b[j] += add.z;
        if (AsDiffuse) {
            const Color l = kept * sampleShare(light, ws.points.lambert.get(j), n, v, s, 1.0f);
            ws.lambertSums.r[j] += l.x, ws.lambertSums.g[j] += l.y, ws.lambertSums.b[j] += l.z;
        }
    }
}

template void TraceKernel::addTransmitted<true>(Workspace&, uint32_t, std::size_t,
                                                std::size_t) const;
template void TraceKernel::addTransmitted<false>(Workspace&, uint32_t, std::size_t,
                                                 std::size_t) const;

}  // namespace rs
