// The Whitted integrator: the illumination equation of scenes/FORMAT.md, recursively.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>

#include "core/math.h"
#include "snapshot/compiled_scene.h"

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
    bool touchedSpecular = false;  ///< The ray tree met a reflective or refractive surface.
};

/// How shadows are traced.
enum class ShadowQuality {
    Full,      ///< As the scene says: shadow_samples rays per light, sphere lights sampled.
    HardOnly,  ///< One shadow ray to each light's centre.
    Off,       ///< No shadow rays: every light is visible.
    Deferred,  ///< Unshadowed now; shading points are recorded to add the shadows later.
};

/// Quality knobs the interactive session turns down while the user drags (thesis 4.2).
struct TraceOptions {
    int maxDepth = 3;
    ShadowQuality shadows = ShadowQuality::Full;
    bool reflectionAsDiffuse = false;  ///< Mirror share shaded as Lambert in the surface colour.
    bool refractionAsDiffuse = false;  ///< Glass share shaded as Lambert in the surface colour.
    ObjectId refractionExempt = kNoObject;  ///< Keeps real refraction on this object.
    /// Reflection and refraction rays with a smaller accumulated weight are not traced.
    float minWeight = 1.0f / 255.0f;
    /// The full quality the scene's render settings ask for.
    static TraceOptions fromSettings(const RenderSettings& s) {
        TraceOptions o;
        // Documents built in code skip the reader's limit; never recurse past it.
        o.maxDepth = std::min(s.maxDepth, kMaxDepthLimit);
        o.minWeight = std::max(0.0f, s.minWeight);
        return o;
    }
};

/// A shading point whose light terms were deferred: enough to add them without re-tracing
/// the camera or secondary rays (thesis 3.3).
struct ShadingRecord {
    Vec3 p, n, toViewer;
    float weight;   ///< Path throughput times the material's local share.
    Color diffuse;  ///< Diffuse times the surface's colour there (its pattern's, if any).
    uint32_t material;
    uint32_t seed;  ///< Light-sampling seed, so the deferred samples equal a full trace's.
};

/// Fixed-capacity destination for shading records of one camera ray; no allocation.
struct RecordSink {
    ShadingRecord* data = nullptr;
    int capacity = 0;
    int count = 0;
    bool overflow = false;  ///< More points than capacity: the pixel must be re-traced.
};

/// One secondary ray of a pixel's ray tree: from `a` to the hit point `b`, or, when it hit
/// nothing, from `a` along direction `b` to infinity. Dirty regions test these against an
/// edit's bounds (thesis 3.2: only pixels whose secondary rays can reach the edit).
struct TreeSegment {
    Vec3 a;
    Vec3 b;
    uint32_t escapes;  ///< 1: `b` is a direction and the ray is unbounded.
};

/// Fixed-capacity destination for the secondary segments of one pixel; no allocation.
struct SegmentSink {
    TreeSegment* data = nullptr;
    int capacity = 0;
    int count = 0;
    bool overflow = false;  ///< The tree did not fit: treat the pixel as always affected.
};

class TraceKernel;

/// One camera ray at a time through the trace kernel: for picking, tests and anything that
/// needs a single pixel. The same path (TraceKernel) as every batch, so the same bits.
class WhittedIntegrator {
public:
    /// Full quality, as the scene's render settings say.
    explicit WhittedIntegrator(const CompiledScene& scene);
    WhittedIntegrator(const CompiledScene& scene, const TraceOptions& options);

    /// Radiance arriving along a camera ray. `seed` decorrelates light sampling per pixel
    /// sample; `primary` (optional) receives the first hit and whether the tree met a mirror
    /// or glass; `sink` receives shading records when shadows are Deferred; `segments` the
    /// tree's secondary segments.
    Color traceCamera(const Ray& ray, uint32_t seed, TraceCounters& counters,
                      PrimaryInfo* primary = nullptr, RecordSink* sink = nullptr,
                      SegmentSink* segments = nullptr) const;

    /// What a Deferred trace's unshadowed light terms at `record` are off by: shadowed minus
    /// unshadowed, added to the pixel to finish it.
    Color resolveDeferred(const ShadingRecord& record, TraceCounters& counters) const;

private:
    /// Built once: a kernel works out each material's terms and the lights' split when made.
    std::shared_ptr<const TraceKernel> kernel_;
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
