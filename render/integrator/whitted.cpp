// Whitted ray tracing: local Phong/Lambert term with shadows, mirror reflection, refraction.
#include "integrator/whitted.h"

#include "integrator/sampling.h"

#include <cmath>

namespace rs {

WhittedIntegrator::WhittedIntegrator(const CompiledScene& scene)
    : WhittedIntegrator(scene, TraceOptions::fromSettings(scene.settings())) {}

WhittedIntegrator::WhittedIntegrator(const CompiledScene& scene, const TraceOptions& options)
    : scene_(scene),
      options_(options),
      shadowSamples_(scene.settings().shadowSamples),
      eps_(scene.epsilon()) {}

Color WhittedIntegrator::traceCamera(const Ray& ray, uint32_t seed, TraceCounters& counters,
                                     PrimaryInfo* primary, RecordSink* sink,
                                     SegmentSink* segments, const RaySubset* subset) const {
    return trace(ray, 0, 1.0f, seed, counters, Outputs{primary, sink, segments, subset});
}

Color WhittedIntegrator::resolveDeferred(const ShadingRecord& record,
                                         TraceCounters& counters) const {
    // The interactive trace showed the lights unshadowed; swap that for the shadowed terms.
    const CompiledMaterial& m = scene_.materials()[record.material];
    TraceCounters unshadowedCounters;
    const Color shadowed = directLight(record.p, record.n, record.toViewer, m, record.seed,
                                       ShadowQuality::Full, counters);
    const Color unshadowed = directLight(record.p, record.n, record.toViewer, m, record.seed,
                                         ShadowQuality::Off, unshadowedCounters);
    return record.weight * (shadowed - unshadowed);
}

Color WhittedIntegrator::trace(const Ray& ray, int depth, float weight, uint32_t seed,
                               TraceCounters& counters, const Outputs& out) const {
    ++counters.rays;
    SurfaceHit hit;
    const bool found = scene_.intersect(ray, 0.0f, kInfinity, hit,
                                        depth == 0 ? out.cameraSubset : nullptr);
    if (out.segments && depth > 0) {
        SegmentSink& s = *out.segments;
        if (s.count < s.capacity)
            s.data[s.count++] = found ? TreeSegment{ray.origin, ray.at(hit.t), 0u}
                                      : TreeSegment{ray.origin, ray.dir, 1u};
        else
            s.overflow = true;
    }
    if (!found) return scene_.settings().background;

    PrimaryInfo* primary = out.primary;
    RecordSink* sink = out.records;
    const CompiledMaterial& m = scene_.materials()[hit.material];
    if (primary) {
        if (depth == 0) {
            primary->id = hit.id;
            primary->depth = hit.t;
            primary->normal = hit.n;
        }
        if (m.reflectivity > 0.0f || m.transparency > 0.0f) primary->touchedSpecular = true;
    }
    const Vec3 p = ray.at(hit.t);
    // Face the normal toward the incoming ray; `inside` tells glass which way the ratio goes
    // (thesis Algorithm 6).
    const bool inside = glm::dot(hit.n, ray.dir) > 0.0f;
    const Vec3 n = inside ? -hit.n : hit.n;
    const Vec3 toViewer = -ray.dir;

    // While moving, mirror and glass shares may be shown as plain Lambert (thesis 4.2).
    float reflectivity = m.reflectivity, transparency = m.transparency, asDiffuse = 0.0f;
    if (options_.reflectionAsDiffuse && reflectivity > 0.0f) {
        asDiffuse += reflectivity;
        reflectivity = 0.0f;
    }
    if (options_.refractionAsDiffuse && transparency > 0.0f && hit.id != options_.refractionExempt) {
        asDiffuse += transparency;
        transparency = 0.0f;
    }

    Color result(0.0f);
    if (m.localWeight > 0.0f) {
        const Color ambient = scene_.settings().ambient * m.color * m.diffuse;
        if (options_.shadows == ShadowQuality::Deferred) {
            // Shown unshadowed while moving; the record lets the shadows be added later.
            result = m.localWeight * (ambient + directLight(p, n, toViewer, m, seed,
                                                            ShadowQuality::Off, counters));
            if (sink) {
                if (sink->count < sink->capacity)
                    sink->data[sink->count++] = {p,    n, toViewer, weight * m.localWeight,
                                                 hit.material, seed};
                else
                    sink->overflow = true;
            }
        } else {
            result = m.localWeight *
                     (ambient + directLight(p, n, toViewer, m, seed, options_.shadows, counters));
        }
    }
    if (asDiffuse > 0.0f) {
        CompiledMaterial lambert{};
        lambert.color = m.color;
        lambert.diffuse = 1.0f;
        const ShadowQuality shadows = options_.shadows == ShadowQuality::Deferred
                                          ? ShadowQuality::Off
                                          : options_.shadows;
        result += asDiffuse * (scene_.settings().ambient * m.color +
                               directLight(p, n, toViewer, lambert, seed, shadows, counters));
    }

    if (depth >= options_.maxDepth || (reflectivity <= 0.0f && transparency <= 0.0f))
        return result;

    // Reflection is traced once and weighted by the mirror part plus the glass part's Fresnel
    // (or all of the glass part on total internal reflection).
    float reflectWeight = reflectivity;
    Color refracted(0.0f);
    if (transparency > 0.0f) {
        const float eta = inside ? m.ior : 1.0f / m.ior;
        Vec3 t;
        if (refractDir(ray.dir, n, eta, t)) {
            const float f = schlick(-glm::dot(n, ray.dir), m.ior);
            reflectWeight += transparency * f;
            const float w = transparency * (1.0f - f);
            refracted = w * trace(Ray::make(p - n * eps_, t), depth + 1, weight * w,
                                  hashCombine(seed, 2u), counters, out);
        } else {
            reflectWeight += transparency;
        }
    }
    if (reflectWeight > 0.0f) {
        const Vec3 r = ray.dir - 2.0f * glm::dot(ray.dir, n) * n;
        result += reflectWeight * trace(Ray::make(p + n * eps_, r), depth + 1,
                                        weight * reflectWeight, hashCombine(seed, 1u), counters,
                                        out);
    }
    return result + refracted;
}

Color WhittedIntegrator::directLight(const Vec3& p, const Vec3& n, const Vec3& toViewer,
                                     const CompiledMaterial& m, uint32_t seed,
                                     ShadowQuality shadows, TraceCounters& counters) const {
    const Vec3 origin = p + n * eps_;
    const Color diffuseColor = m.diffuse * m.color;
    const bool traceShadows = shadowSamples_ > 0 && shadows != ShadowQuality::Off;
    const bool sampleArea = shadowSamples_ > 0 && shadows == ShadowQuality::Full;

    Color sum(0.0f);
    const auto& lights = scene_.lights();
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const CompiledLight& light = lights[li];
        const bool area = light.radius > 0.0f && sampleArea;
        // A point light's samples all coincide, so one shadow ray stands for all of them.
        const int samples = area ? shadowSamples_ : 1;
        Vec3 axisA(0.0f), axisB(0.0f);
        if (area) {
            const Vec3 w = glm::normalize(light.position - p);
            axisA = glm::normalize(std::abs(w.x) > 0.9f ? glm::cross(w, Vec3(0, 1, 0))
                                                        : glm::cross(w, Vec3(1, 0, 0)));
            axisB = glm::cross(w, axisA);
        }
        const uint32_t lightSeed = hashCombine(seed, uint32_t(li) + 17u);
        Color lightSum(0.0f);
        for (int s = 0; s < samples; ++s) {
            Vec3 q = light.position;
            if (area) {
                const Vec3 d = stratifiedDiskSample(s, samples, lightSeed);
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
            float spec = 0.0f;
            if (m.specular > 0.0f) {
                const float rv = glm::dot(2.0f * nl * n - toLight, toViewer);
                if (rv > m.specularCutoff && rv > 0.0f) spec = m.specular * std::pow(rv, m.shininess);
            }
            if (traceShadows) {
                ++counters.shadowRays;
                if (scene_.occludedToLight(li, origin, toLight, 0.0f, dist - eps_))
                    continue;
            }
            lightSum += diffuseColor * nl + Color(spec);
        }
        sum += lightSum * light.power / float(samples);
    }
    return sum;
}

}  // namespace rs
