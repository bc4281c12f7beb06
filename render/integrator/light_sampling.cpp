// Light samples and the Lambert + Phong sum over them.
#include "integrator/light_sampling.h"

#include "integrator/sampling.h"

#include <cmath>

namespace rs {

void sampleLights(const CompiledScene& scene, const Vec3& p, const Vec3& n, uint32_t seed,
                  bool area, std::vector<LightSample>& samples, std::vector<LightSpan>& spans) {
    const int shadowSamples = scene.settings().shadowSamples;
    const auto& lights = scene.lights();
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const CompiledLight& light = lights[li];
        const bool sampled = area && light.radius > 0.0f && shadowSamples > 0;
        // A point light's samples all coincide, so one stands for all of them.
        const int count = sampled ? shadowSamples : 1;
        Vec3 axisA(0.0f), axisB(0.0f);
        uint32_t lightSeed = 0;
        if (sampled) {
            const Vec3 w = glm::normalize(light.position - p);
            axisA = glm::normalize(std::abs(w.x) > 0.9f ? glm::cross(w, Vec3(0, 1, 0))
                                                        : glm::cross(w, Vec3(1, 0, 0)));
            axisB = glm::cross(w, axisA);
            lightSeed = hashCombine(seed, uint32_t(li) + 17u);
        }
        LightSpan span{uint32_t(li), uint32_t(samples.size()), 0, uint32_t(count)};
        const DiskStrata strata(count);
        for (int s = 0; s < count; ++s) {
            Vec3 q = light.position;
            if (sampled) {
                const Vec3 d = strata.sample(s, lightSeed);
                q += light.radius * (d.x * axisA + d.y * axisB);
            }
            Vec3 toLight = q - p;
            const float dist = glm::length(toLight);
            if (dist <= 0.0f) continue;
            toLight = divide(toLight, dist);
            // A light below the surface's horizon adds neither term (so no highlight leaks
            // through from behind), and needs no shadow ray.
            const float nl = glm::dot(n, toLight);
            if (nl <= 0.0f) continue;
            samples.push_back({toLight, dist, nl});
            ++span.listed;
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
