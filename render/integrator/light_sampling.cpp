// Light samples and the Lambert + Phong sum over them.
#include "integrator/light_sampling.h"

#include "integrator/sampling.h"

#include <algorithm>
#include <cmath>

namespace rs {

namespace {

/// Appends the sample toward light point q from p (unit normal n) unless q is p itself or lies
/// below the horizon; true when it was appended.
inline bool appendSample(const Vec3& q, const Vec3& p, const Vec3& n,
                         std::vector<LightSample>& samples) {
    Vec3 toLight = q - p;
    const float dist = glm::length(toLight);
    if (dist <= 0.0f) return false;
    toLight = divide(toLight, dist);
    // A light below the surface's horizon adds neither term (so no highlight leaks through
    // from behind), and needs no shadow ray.
    const float nl = glm::dot(n, toLight);
    if (nl <= 0.0f) return false;
    samples.push_back({toLight, dist, nl});
    return true;
}

}  // namespace

LightSampler::LightSampler(const CompiledScene& scene)
    : scene_(scene), strata_(std::max(1, scene.settings().shadowSamples)) {}

void LightSampler::sample(const Vec3& p, const Vec3& n, uint32_t seed, bool area,
                          std::vector<LightSample>& samples, std::vector<LightSpan>& spans) const {
    const int shadowSamples = scene_.settings().shadowSamples;
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
            span.drawn = uint32_t(shadowSamples);
            for (int s = 0; s < shadowSamples; ++s) {
                const Vec3 d = strata_.sample(s, lightSeed);
                const Vec3 q = light.position + light.radius * (d.x * axisA + d.y * axisB);
                if (appendSample(q, p, n, samples)) ++span.listed;
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
