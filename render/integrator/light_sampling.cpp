// Light samples and the Lambert + Phong sum over them.
#include "integrator/light_sampling.h"

#include "integrator/sampling.h"

#include <algorithm>
#include <cmath>

namespace rs {

namespace {

/// Samples toward light points q (one, or a lane of them) from p with unit normal n: unit
/// direction, distance and n . dir, as glm's length, divide and dot have them.
template <class F>
struct TowardLight {
    F x, y, z, dist, nl;

    TowardLight(F qx, F qy, F qz, const Vec3& p, const Vec3& n) {
        x = qx - p.x, y = qy - p.y, z = qz - p.z;
        dist = sqrtLanes((x * x + y * y) + z * z);
        x = x / dist, y = y / dist, z = z / dist;
        nl = (n.x * x + n.y * y) + n.z * z;
    }
    /// A sample is listed unless its point is p itself or lies below the horizon: a light
    /// there adds neither term (so no highlight leaks through from behind), and needs no
    /// shadow ray.
    static bool listed(float dist, float nl) { return dist > 0.0f && nl > 0.0f; }
};

/// Appends the sample toward q unless it is not listed; true when it was appended.
inline bool appendSample(const Vec3& q, const Vec3& p, const Vec3& n,
                         std::vector<LightSample>& samples) {
    const TowardLight<float> t(q.x, q.y, q.z, p, n);
    if (!TowardLight<float>::listed(t.dist, t.nl)) return false;
    samples.push_back({Vec3(t.x, t.y, t.z), t.dist, t.nl});
    return true;
}

/// Appends the listed ones of a lane of samples toward q, in lane order; returns how many.
inline uint32_t appendSamples(FloatLanes qx, FloatLanes qy, FloatLanes qz, const Vec3& p,
                              const Vec3& n, std::vector<LightSample>& samples) {
    const TowardLight<FloatLanes> t(qx, qy, qz, p, n);
    uint32_t listed = 0;
    for (int k = 0; k < kLaneWidth; ++k) {
        if (!TowardLight<float>::listed(t.dist[k], t.nl[k])) continue;
        samples.push_back({Vec3(t.x[k], t.y[k], t.z[k]), t.dist[k], t.nl[k]});
        ++listed;
    }
    return listed;
}

}  // namespace

LightSampler::LightSampler(const CompiledScene& scene, Lanes lanes)
    : scene_(scene),
      strata_(std::max(1, scene.settings().shadowSamples)),
      shadowSamples_(scene.settings().shadowSamples),
      // Lanes of strata where the strata are tabled; the rest one by one.
      laned_(lanes == Lanes::Four ? std::min(shadowSamples_, strata_.laned()) : 0) {}

void LightSampler::sample(const Vec3& p, const Vec3& n, uint32_t seed, bool area,
                          std::vector<LightSample>& samples, std::vector<LightSpan>& spans) const {
    const int shadowSamples = shadowSamples_, laned = laned_;
    const auto& lights = scene_.lights();
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const CompiledLight& light = lights[li];
        LightSpan span{uint32_t(li), uint32_t(samples.size()), 0, 1};
        if (!(area && light.radius > 0.0f && shadowSamples > 0)) {
            // A point light's samples all coincide, so one stands for all of them.
            span.listed = appendSample(light.position, p, n, samples) ? 1 : 0;
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
}

Color shadeLights(const CompiledScene& scene, const CompiledMaterial& m, const Vec3& n,
                  const Vec3& toViewer, const LightSpan* spans, std::size_t spanCount,
                  const LightSample* samples, const uint8_t* occluded) {
    const Color diffuseColor = m.diffuse * m.color;
    Color sum(0.0f);
    for (std::size_t k = 0; k < spanCount; ++k) {
        const LightSpan& span = spans[k];
        Color lightSum(0.0f);
        for (uint32_t i = span.first; i < span.first + span.listed; ++i) {
            if (occluded && occluded[i]) continue;
            const LightSample& s = samples[i];
            float spec = 0.0f;
            if (m.specular > 0.0f) {
                const float rv = glm::dot(2.0f * s.nl * n - s.dir, toViewer);
                if (rv > m.specularCutoff && rv > 0.0f) spec = m.specular * std::pow(rv, m.shininess);
            }
            lightSum += diffuseColor * s.nl + Color(spec);
        }
        sum += lightSum * scene.lights()[span.light].power / float(span.drawn);
    }
    return sum;
}

}  // namespace rs
