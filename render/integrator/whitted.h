// The Whitted integrator: the illumination equation of scene-format.md, recursively.
#pragma once

#include "core/math.h"
#include "snapshot/compiled_scene.h"

#include <cstdint>

namespace rs {

/// Counters a trace accumulates; kept per tile, never shared between threads.
struct TraceCounters {
    uint64_t rays = 0;        ///< Camera, reflection and refraction rays.
    uint64_t shadowRays = 0;  ///< Shadow rays.
    uint64_t total() const { return rays + shadowRays; }
};

/// What a camera sample saw first: for the deep frame, picking and adaptive supersampling.
struct PrimaryInfo {
    ObjectId id = kNoObject;
    float depth = kInfinity;
    Vec3 normal{0.0f};
};

/// Traces rays through a compiled scene. Stateless apart from the scene it reads.
class WhittedIntegrator {
public:
    explicit WhittedIntegrator(const CompiledScene& scene);

    /// Radiance arriving along a camera ray. `seed` decorrelates light sampling per pixel
    /// sample; `primary` (optional) receives the first hit.
    Color traceCamera(const Ray& ray, uint32_t seed, TraceCounters& counters,
                      PrimaryInfo* primary = nullptr) const;

private:
    Color trace(const Ray& ray, int depth, uint32_t seed, TraceCounters& counters,
                PrimaryInfo* primary) const;
    Color shadeLocal(const Vec3& p, const Vec3& n, const Vec3& toViewer, const CompiledMaterial& m,
                     uint32_t seed, TraceCounters& counters) const;

    const CompiledScene& scene_;
    int maxDepth_;
    int shadowSamples_;
    float eps_;
};

/// Schlick's approximation of Fresnel reflectance for cosine `cosIncident` on the incident side.
inline float schlick(float cosIncident, float ior) {
    float r0 = (1.0f - ior) / (1.0f + ior);
    r0 *= r0;
    float c = 1.0f - cosIncident;
    float c2 = c * c;
    return r0 + (1.0f - r0) * c2 * c2 * c;
}

/// Snell refraction of unit `d` at unit normal `n` facing the incident side, eta = n1 / n2.
/// Returns false on total internal reflection.
inline bool refractDir(const Vec3& d, const Vec3& n, float eta, Vec3& out) {
    float cosi = -glm::dot(n, d);
    float k = 1.0f - eta * eta * (1.0f - cosi * cosi);
    if (k < 0.0f) return false;
    out = glm::normalize(eta * d + (eta * cosi - std::sqrt(k)) * n);
    return true;
}

}  // namespace rs
