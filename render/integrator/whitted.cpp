// Whitted ray tracing: local Phong/Lambert term with shadows, mirror reflection, refraction.
#include "integrator/whitted.h"

#include "integrator/sampling.h"

#include <cmath>

namespace rs {

WhittedIntegrator::WhittedIntegrator(const CompiledScene& scene)
    : scene_(scene),
      maxDepth_(scene.settings().maxDepth),
      shadowSamples_(scene.settings().shadowSamples),
      eps_(scene.epsilon()) {}

Color WhittedIntegrator::traceCamera(const Ray& ray, uint32_t seed, TraceCounters& counters,
                                     PrimaryInfo* primary) const {
    return trace(ray, 0, seed, counters, primary);
}

Color WhittedIntegrator::trace(const Ray& ray, int depth, uint32_t seed, TraceCounters& counters,
                               PrimaryInfo* primary) const {
    ++counters.rays;
    SurfaceHit hit;
    if (!scene_.intersect(ray, 0.0f, kInfinity, hit)) return scene_.settings().background;
    if (primary) *primary = {hit.id, hit.t, hit.n};

    const CompiledMaterial& m = scene_.materials()[hit.material];
    const Vec3 p = ray.at(hit.t);
    // Face the normal toward the incoming ray; `inside` tells glass which way the ratio goes
    // (thesis Algorithm 6).
    const bool inside = glm::dot(hit.n, ray.dir) > 0.0f;
    const Vec3 n = inside ? -hit.n : hit.n;

    Color result(0.0f);
    if (m.localWeight > 0.0f)
        result = m.localWeight * shadeLocal(p, n, -ray.dir, m, seed, counters);

    if (depth >= maxDepth_ || (m.reflectivity <= 0.0f && m.transparency <= 0.0f)) return result;

    // Reflection is traced once and weighted by the mirror part plus the glass part's Fresnel
    // (or all of the glass part on total internal reflection).
    float reflectWeight = m.reflectivity;
    Color refracted(0.0f);
    if (m.transparency > 0.0f) {
        const float eta = inside ? m.ior : 1.0f / m.ior;
        Vec3 t;
        if (refractDir(ray.dir, n, eta, t)) {
            const float f = schlick(-glm::dot(n, ray.dir), m.ior);
            reflectWeight += m.transparency * f;
            Ray refr = Ray::make(p - n * eps_, t);
            refracted = (m.transparency * (1.0f - f)) *
                        trace(refr, depth + 1, hashCombine(seed, 2u), counters, nullptr);
        } else {
            reflectWeight += m.transparency;
        }
    }
    if (reflectWeight > 0.0f) {
        const Vec3 r = ray.dir - 2.0f * glm::dot(ray.dir, n) * n;
        Ray refl = Ray::make(p + n * eps_, r);
        result += reflectWeight * trace(refl, depth + 1, hashCombine(seed, 1u), counters, nullptr);
    }
    return result + refracted;
}

Color WhittedIntegrator::shadeLocal(const Vec3& p, const Vec3& n, const Vec3& toViewer,
                                    const CompiledMaterial& m, uint32_t seed,
                                    TraceCounters& counters) const {
    Color sum = scene_.settings().ambient * m.color * m.diffuse;
    const Vec3 origin = p + n * eps_;
    const Color diffuseColor = m.diffuse * m.color;

    // Unshadowed light term for direction `l` (unit) from the shading point.
    auto lightTerm = [&](const Vec3& l) -> float {
        return std::max(0.0f, glm::dot(n, l));
    };
    auto specularTerm = [&](const Vec3& l, float nl) -> float {
        if (m.specular <= 0.0f) return 0.0f;
        const Vec3 r = 2.0f * nl * n - l;
        const float rv = glm::dot(r, toViewer);
        return rv > 0.0f ? m.specular * std::pow(rv, m.shininess) : 0.0f;
    };

    const auto& lights = scene_.lights();
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const CompiledLight& light = lights[li];
        const bool area = light.radius > 0.0f && shadowSamples_ > 0;
        const int samples = area ? shadowSamples_ : 1;
        // A point light's samples all coincide, so one shadow ray stands for all of them.
        Color lightSum(0.0f);
        Vec3 axisA, axisB;
        if (area) {
            const Vec3 w = glm::normalize(light.position - p);
            axisA = glm::normalize(std::abs(w.x) > 0.9f ? glm::cross(w, Vec3(0, 1, 0))
                                                        : glm::cross(w, Vec3(1, 0, 0)));
            axisB = glm::cross(w, axisA);
        }
        const uint32_t lightSeed = hashCombine(seed, uint32_t(li) + 17u);
        for (int s = 0; s < samples; ++s) {
            Vec3 q = light.position;
            if (area) {
                const Vec3 d = stratifiedDiskSample(s, samples, lightSeed);
                q += light.radius * (d.x * axisA + d.y * axisB);
            }
            Vec3 toLight = q - p;
            const float dist = glm::length(toLight);
            if (dist <= 0.0f) continue;
            toLight /= dist;
            const float nl = lightTerm(toLight);
            const float spec = specularTerm(toLight, nl);
            if (nl <= 0.0f && spec <= 0.0f) continue;  // Nothing to shadow.
            if (shadowSamples_ > 0) {
                ++counters.shadowRays;
                if (scene_.occluded(Ray::make(origin, toLight), 0.0f, dist - eps_)) continue;
            }
            lightSum += diffuseColor * nl + Color(spec);
        }
        sum += lightSum * light.power / float(samples);
    }
    return sum;
}

}  // namespace rs
