// Light samples and the Lambert + Phong sum over them.
#include "integrator/light_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "integrator/sampling.h"

namespace rs {

namespace {

/// Samples toward light points q from points p with unit normals n (one of each, or a lane of
/// them; q or p may be one for all lanes): unit direction, distance and n . dir, as glm's
/// length, divide and dot have them.
template <class F>
struct TowardLight {
    F x, y, z, dist, nl;

    template <class Q, class P>
    TowardLight(Q qx, Q qy, Q qz, P px, P py, P pz, P nx, P ny, P nz) {
        x = qx - px, y = qy - py, z = qz - pz;
        dist = sqrtLanes((x * x + y * y) + z * z);
        x = x / dist, y = y / dist, z = z / dist;
        nl = (nx * x + ny * y) + nz * z;
    }
    /// A sample is listed unless its point is p itself or lies below the horizon: a light
    /// there adds neither term (so no highlight leaks through from behind), and needs no
    /// shadow ray.
    auto listed() const { return (dist > 0.0f) & (nl > 0.0f); }
};

/// Appends the sample toward q unless it is not listed; true when it was appended.
inline bool appendSample(const Vec3& q, const Vec3& p, const Vec3& n, LightSamples& samples) {
    const TowardLight<float> t(q.x, q.y, q.z, p.x, p.y, p.z, n.x, n.y, n.z);
    if (!t.listed()) return false;
    samples.push_back({Vec3(t.x, t.y, t.z), t.dist, t.nl});
    return true;
}

/// appendSample toward a light's centre; a spot light's sample is not listed outside its
/// falloff cone either (it adds nothing there, so it needs no shadow ray).
inline bool appendCentreSample(const CompiledLight& l, const Vec3& p, const Vec3& n,
                               LightSamples& samples) {
    const Vec3& q = l.position;
    const TowardLight<float> t(q.x, q.y, q.z, p.x, p.y, p.z, n.x, n.y, n.z);
    if (!t.listed()) return false;
    if (l.spot && !(spotFactor(l, -glm::dot(l.axis, Vec3(t.x, t.y, t.z))) > 0.0f)) return false;
    samples.push_back({Vec3(t.x, t.y, t.z), t.dist, t.nl});
    return true;
}

/// Appends the listed ones of a lane of samples toward q, in lane order; returns how many.
inline uint32_t appendSamples(FloatLanes qx, FloatLanes qy, FloatLanes qz, const Vec3& p,
                              const Vec3& n, LightSamples& samples) {
    const TowardLight<FloatLanes> t(qx, qy, qz, p.x, p.y, p.z, n.x, n.y, n.z);
    const MaskLanes listed = t.listed();
    uint32_t count = 0;
    for (int k = 0; k < kLaneWidth; ++k) {
        if (!listed[k]) continue;
        samples.push_back({Vec3(t.x[k], t.y[k], t.z[k]), t.dist[k], t.nl[k]});
        ++count;
    }
    return count;
}

/// One light sample's Lambert + Phong term for `s` at unit normal n, seen from direction v,
/// added to (r, g, b) where `visible` holds: diffuse colour times n . l plus the highlight
/// specular * (R.V)^shininess, R = 2 (n . l) n - l, skipped below the cutoff.
template <class F, class M>
inline void addSampleTerm(const SurfaceTerms<F>& s, F nx, F ny, F nz, F vx, F vy, F vz, F dx, F dy,
                          F dz, F nl, M visible, F& r, F& g, F& b) {
    F spec{};
    const auto shiny = s.specular > 0.0f;
    if (anyLane(shiny)) {  // most surfaces of a room have no highlight
        const F twoNl = 2.0f * nl;
        const F rv = ((twoNl * nx - dx) * vx + (twoNl * ny - dy) * vy) + (twoNl * nz - dz) * vz;
        spec = scaledPowWhere(shiny & (rv > s.cutoff) & (rv > 0.0f), s.specular, rv, s.shininess);
    }
    r += select(visible, s.r * nl + spec, F{});
    g += select(visible, s.g * nl + spec, F{});
    b += select(visible, s.b * nl + spec, F{});
}

/// A light's share of the sum: the sum of its samples' terms times its power, over the
/// samples drawn.
template <class F>
inline F share(F termSum, float power, float drawn) {
    return termSum * power / drawn;
}

template <class V>
inline V load(const ScratchVector<float>& v, std::size_t i) {
    V out;
    std::memcpy(&out, v.data() + i, sizeof out);
    return out;
}
inline void store(ScratchVector<float>& v, std::size_t i, FloatLanes x) {
    std::memcpy(v.data() + i, &x, sizeof x);
}
/// Lanes of a byte flag per point: all ones where the byte is not 0 (one compare of the
/// four widened bytes, no branch per lane).
inline MaskLanes flags(const uint8_t* f, std::size_t i) {
    const MaskLanes m{f[i], f[i + 1], f[i + 2], f[i + 3]};
    return m != 0;
}

/// Rounded up to whole lanes, plus one lane of slack.
std::size_t padded(std::size_t n) {
    return (n + 2 * std::size_t(kLaneWidth) - 1) / std::size_t(kLaneWidth) *
           std::size_t(kLaneWidth);
}

}  // namespace

void ShadingPoints::resize(std::size_t n) {
    const std::size_t p = padded(n);
    for (auto* v : {&px, &py, &pz, &nx, &ny, &nz, &vx, &vy, &vz})
        if (v->size() < p) v->resize(p);
    count = n;
}

void SurfaceArrays::resize(std::size_t n) {
    const std::size_t p = padded(n);
    for (auto* v : {&r, &g, &b, &specular, &cutoff, &shininess})
        if (v->size() < p) v->resize(p);
}

void LightSums::zero(std::size_t n) {
    const std::size_t p = padded(n);
    for (auto* v : {&r, &g, &b}) {
        if (v->size() < p) v->resize(p);
        std::memset(v->data(), 0, p * sizeof(float));  // all-zero bits are +0.0f
    }
}

SurfaceTerms<float> surfaceTerms(const CompiledMaterial& m) {
    return materialLook(m, m.color, Color(0.0f)).terms;
}

LightSampler::LightSampler(const CompiledScene& scene, Lanes lanes)
    : scene_(scene),
      strata_(std::max(1, scene.settings().shadowSamples)),
      shadowSamples_(scene.settings().shadowSamples),
      // Lanes of strata where the strata are tabled; the rest one by one.
      laned_(lanes == Lanes::Four ? std::min(shadowSamples_, strata_.laned()) : 0) {}

void LightSampler::sample(const Vec3& p, const Vec3& n, uint32_t seed, bool area,
                          LightSamples& samples, LightSpans& spans) const {
    for (std::size_t li = 0; li < scene_.lights().size(); ++li)
        sampleLight(li, p, n, seed, area, samples, spans);
}

void LightSampler::sampleLight(std::size_t li, const Vec3& p, const Vec3& n, uint32_t seed,
                               bool area, LightSamples& samples, LightSpans& spans) const {
    const int shadowSamples = shadowSamples_, laned = laned_;
    const CompiledLight& light = scene_.lights()[li];
    LightSpan span{uint32_t(li), uint32_t(samples.size()), 0, 1};
    if (centreOnly(li, area)) {
        // A point light's samples all coincide, so one stands for all of them.
        span.listed = appendCentreSample(light, p, n, samples) ? 1 : 0;
    } else {
        const Vec3 w = glm::normalize(light.position - p);
        const Vec3 axisA = glm::normalize(std::abs(w.x) > 0.9f ? glm::cross(w, Vec3(0, 1, 0))
                                                               : glm::cross(w, Vec3(1, 0, 0)));
        const Vec3 axisB = glm::cross(w, axisA);
        const uint32_t lightSeed = hashCombine(seed, uint32_t(li) + 17u);
        const Vec3& c = light.position;
        const float r = light.radius;
        span.drawn = uint32_t(shadowSamples);
        // The disk point q = c + r (d.x axisA + d.y axisB), as glm evaluates it.
        int s = 0;
        for (; s + kLaneWidth <= laned; s += kLaneWidth) {
            FloatLanes dx, dy;
            strata_.sampleLanes(s, lightSeed, dx, dy);
            span.listed += appendSamples(c.x + r * (dx * axisA.x + dy * axisB.x),
                                         c.y + r * (dx * axisA.y + dy * axisB.y),
                                         c.z + r * (dx * axisA.z + dy * axisB.z), p, n, samples);
        }
        for (; s < shadowSamples; ++s) {
            const Vec3 d = strata_.sample(s, lightSeed);
            if (appendSample(c + r * (d.x * axisA + d.y * axisB), p, n, samples)) ++span.listed;
        }
    }
    if (span.listed) spans.push_back(span);
}

void LightSampler::sampleCentres(std::size_t li, const ShadingPoints& pts, std::size_t first,
                                 std::size_t end, CentreSamples& out) const {
    const CompiledLight& light = scene_.lights()[li];
    const Vec3& c = light.position;
    const FloatLanes qx = splat(c.x), qy = splat(c.y), qz = splat(c.z);
    const std::size_t p = padded(pts.count);
    for (auto* v : {&out.dx, &out.dy, &out.dz, &out.dist, &out.nl})
        if (v->size() < p) v->resize(p);
    if (out.listed.size() < p) out.listed.resize(p);
    // Local pointers: the flags' byte stores could alias a vector's data pointer.
    const float *px = pts.px.data(), *py = pts.py.data(), *pz = pts.pz.data();
    const float *nx = pts.nx.data(), *ny = pts.ny.data(), *nz = pts.nz.data();
    float *dx = out.dx.data(), *dy = out.dy.data(), *dz = out.dz.data();
    float *dist = out.dist.data(), *nl = out.nl.data();
    uint8_t* listedFlags = out.listed.data();
    using Bytes = uint8_t __attribute__((vector_size(kLaneWidth)));
    for (std::size_t i = first; i < end; i += kLaneWidth) {
        const TowardLight<FloatLanes> t(qx, qy, qz, loadLanes(px + i), loadLanes(py + i),
                                        loadLanes(pz + i), loadLanes(nx + i), loadLanes(ny + i),
                                        loadLanes(nz + i));
        storeLanes(dx + i, t.x), storeLanes(dy + i, t.y), storeLanes(dz + i, t.z);
        storeLanes(dist + i, t.dist), storeLanes(nl + i, t.nl);
        MaskLanes inside = t.listed();
        if (light.spot)  // appendCentreSample's rule: nothing outside the falloff cone
            inside &= spotFactor(light, -((light.axis.x * t.x + light.axis.y * t.y) +
                                          light.axis.z * t.z)) > 0.0f;
        const Bytes listed = __builtin_convertvector(inside & 1, Bytes);  // 0 or 1
        std::memcpy(listedFlags + i, &listed, sizeof listed);
    }
}

Color spanShare(const CompiledScene& scene, const SurfaceTerms<float>& surface, const Vec3& n,
                const Vec3& toViewer, const LightSpan& span, const LightSample* samples,
                const uint8_t* occluded, const Color* transmitted) {
    const CompiledLight& light = scene.lights()[span.light];
    float r = 0.0f, g = 0.0f, b = 0.0f;
    for (uint32_t i = span.first; i < span.first + span.listed; ++i) {
        const bool blocked = occluded && occluded[i];
        if (blocked && !(transmitted && transmitted[i] != Color(0.0f))) continue;
        const LightSample& s = samples[i];
        if (!blocked && !light.spot) {
            addSampleTerm(surface, n.x, n.y, n.z, toViewer.x, toViewer.y, toViewer.z, s.dir.x,
                          s.dir.y, s.dir.z, s.nl, true, r, g, b);
            continue;
        }
        // Through glass, or a spot light's cone: the term scaled per channel.
        float tr = 0.0f, tg = 0.0f, tb = 0.0f;
        addSampleTerm(surface, n.x, n.y, n.z, toViewer.x, toViewer.y, toViewer.z, s.dir.x, s.dir.y,
                      s.dir.z, s.nl, true, tr, tg, tb);
        Color scale(lightFactor(light, s.dir));
        if (blocked) scale *= transmitted[i];
        r += tr * scale.x, g += tg * scale.y, b += tb * scale.z;
    }
    const Color& power = light.power;
    const float drawn = float(span.drawn);
    return Color(share(r, power.x, drawn), share(g, power.y, drawn), share(b, power.z, drawn));
}

Color sampleShare(const CompiledLight& light, const SurfaceTerms<float>& surface, const Vec3& n,
                  const Vec3& toViewer, const LightSample& s, float drawn) {
    float r = 0.0f, g = 0.0f, b = 0.0f;
    addSampleTerm(surface, n.x, n.y, n.z, toViewer.x, toViewer.y, toViewer.z, s.dir.x, s.dir.y,
                  s.dir.z, s.nl, true, r, g, b);
    const float f = lightFactor(light, s.dir);
    return Color(share(r * f, light.power.x, drawn), share(g * f, light.power.y, drawn),
                 share(b * f, light.power.z, drawn));
}

Color shadeLights(const CompiledScene& scene, const SurfaceTerms<float>& surface, const Vec3& n,
                  const Vec3& toViewer, const LightSpan* spans, std::size_t spanCount,
                  const LightSample* samples, const uint8_t* occluded, const Color* transmitted) {
    Color sum(0.0f);
    for (std::size_t k = 0; k < spanCount; ++k)
        sum += spanShare(scene, surface, n, toViewer, spans[k], samples, occluded, transmitted);
    return sum;
}

void addCentreLight(const CompiledLight& light, const ShadingPoints& pts,
                    const SurfaceArrays& surface, const CentreSamples& centres,
                    const uint8_t* blocked, std::size_t first, std::size_t end, LightSums& sums) {
    using L = FloatLanes;
    for (std::size_t i = first; i < end; i += kLaneWidth) {
        const SurfaceTerms<L> s{load<L>(surface.r, i),      load<L>(surface.g, i),
                                load<L>(surface.b, i),      load<L>(surface.specular, i),
                                load<L>(surface.cutoff, i), load<L>(surface.shininess, i)};
        const MaskLanes listed = flags(centres.listed.data(), i);
        const MaskLanes visible = blocked ? listed & ~flags(blocked, i) : listed;
        L r{}, g{}, b{};
        addSampleTerm(s, load<L>(pts.nx, i), load<L>(pts.ny, i), load<L>(pts.nz, i),
                      load<L>(pts.vx, i), load<L>(pts.vy, i), load<L>(pts.vz, i),
                      load<L>(centres.dx, i), load<L>(centres.dy, i), load<L>(centres.dz, i),
                      load<L>(centres.nl, i), visible, r, g, b);
        if (light.spot) {
            const L f = spotFactor(light, -((light.axis.x * load<L>(centres.dx, i) +
                                             light.axis.y * load<L>(centres.dy, i)) +
                                            light.axis.z * load<L>(centres.dz, i)));
            r *= f, g *= f, b *= f;
        }
        // A light with no listed sample has no span: nothing is added (spanShare's callers).
        const L sr = load<L>(sums.r, i), sg = load<L>(sums.g, i), sb = load<L>(sums.b, i);
        store(sums.r, i, select(listed, sr + share(r, light.power.x, 1.0f), sr));
        store(sums.g, i, select(listed, sg + share(g, light.power.y, 1.0f), sg));
        store(sums.b, i, select(listed, sb + share(b, light.power.z, 1.0f), sb));
    }
}

}  // namespace rs
