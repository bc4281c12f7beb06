// Breadth-first ray trees over the ray engine: closest hits of a level, shading of its hits
// with their shadow rays as one batch, then the next level's reflection and refraction rays.
#include "integrator/trace_kernel.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <optional>
#include <type_traits>

#include "core/scratch_arena.h"
#include "integrator/centre_shadows.h"
#include "integrator/face_hits.h"
#include "integrator/light_sampling.h"
#include "integrator/sampling.h"
#include "integrator/trace_level.h"
#include "integrator/trace_workspace.h"
#include "scene/shading_rules.h"

namespace rs {

namespace {

/// Camera rays taken at a time: one 32 x 32 tile.
constexpr std::size_t kCameraChunk = 1024;
/// Rays of one level kept at once. With the default min_weight a camera ray's level holds at
/// most 255 rays (weights of a level sum to at most 1), so a chunk never reaches this; only
/// min_weight near 0 with wide glass trees does, and then the level is traced in parts.
constexpr std::size_t kLevelCap = std::size_t(1) << 18;
/// Light samples (so shadow rays) gathered before the batch is sent to the engine. Small
/// enough that a batch's samples, shadow rays and answers (about 50 KB) stay in the first-level
/// cache between sampling, tracing and shading: 16384 (800 KB) made the 16-sample sphere
/// light about 7 % slower in wall time for the same instructions.
constexpr std::size_t kSampleCap = 1024;

/// While moving, mirror and glass shares may be shown as plain Lambert (thesis 4.2): what of
/// material `m` is still traced as mirror and glass at a hit on object `id`, and the share
/// shaded as Lambert instead.
struct MovingShares {
    float reflectivity, transparency, asDiffuse;
};
template <bool AsDiffuse>
[[gnu::always_inline]] inline MovingShares movingShares(const CompiledMaterial& m, ObjectId id,
                                                        const TraceOptions& options) {
    MovingShares s{m.reflectivity, m.transparency, 0.0f};
    if (AsDiffuse) {
        if (options.reflectionAsDiffuse && s.reflectivity > 0.0f) {
            s.asDiffuse += s.reflectivity;
            s.reflectivity = 0.0f;
        }
        if (options.refractionAsDiffuse && s.transparency > 0.0f &&
            id != options.refractionExempt) {
            s.asDiffuse += s.transparency;
            s.transparency = 0.0f;
        }
    }
    return s;
}

}  // namespace

TraceKernel::TraceKernel(const CompiledScene& scene, const TraceOptions& options)
    : scene_(scene), options_(options), eps_(scene.epsilon()), sampler_(scene) {
    const RenderSettings& settings = scene.settings();
    for (const CompiledMaterial& m : scene.materials()) {
        // In its flat colour; patterned points take their pattern's colour in the same looks.
        const SurfaceLook look = materialLook(m, m.color, settings.ambient);
        const SurfaceLook lambert = lambertLook(m.color, settings.ambient);
        surfaces_.push_back(look.terms);
        lamberts_.push_back(lambert.terms);
        ambients_.push_back(look.ambient);
        lambertAmbients_.push_back(lambert.ambient);
        specular_.push_back(m.reflectivity > 0.0f || m.transparency > 0.0f);
    }
    // What the options fix for every level: which lights are sampled at their centre alone
    // (four points at a time) and which over their disk (point by point), and how many
    // samples a point draws at most.
    for (const CompiledMaterial& m : scene.materials())
        transmissive_ |= !settings.opaqueShadows && m.transparency > 0.0f;
    // A camera sample's cone: a pixel's angle (perspective) or width (orthographic), shared
    // among the pixel's supersamples.
    const CameraModel& camera = scene.camera();
    const float pixel = 2.0f * camera.halfHeight() * camera.invHeight() /
                        std::sqrt(float(std::max(1, settings.supersampling)));
    (camera.orthographic() ? originWidth_ : spread_) = pixel;
    const int shadowSamples = settings.shadowSamples;
    area_ = shadowSamples > 0 && options_.shadows == ShadowQuality::Full;
    traceShadows_ = shadowSamples > 0 && (options_.shadows == ShadowQuality::Full ||
                                          options_.shadows == ShadowQuality::HardOnly);
    for (std::size_t li = 0; li < scene.lights().size(); ++li) {
        const bool centre = sampler_.centreOnly(li, area_);
        (centre ? centreLights_ : sampledLights_).push_back(uint32_t(li));
        perPoint_ += centre ? 1 : std::size_t(shadowSamples);
    }
}

bool TraceKernel::trace(const CameraBatch& rays, const TraceOutput& out, TraceCounters& counters,
                        const std::function<bool()>& stale) const {
    thread_local Workspace ws;
    for (std::size_t start = 0; start < rays.count; start += kCameraChunk) {
        const std::size_t end = std::min(rays.count, start + kCameraChunk);
        std::fill(out.color + start, out.color + end, Color(0.0f));
        if (out.primary) std::fill(out.primary + start, out.primary + end, PrimaryInfo{});
        if (out.rays) std::fill(out.rays + start, out.rays + end, 1u);  // Each counts itself.
        for (std::size_t i = start; out.records && i < end; ++i) out.records.clear(i);
        for (std::size_t i = start; out.segments && i < end; ++i) out.segments.clear(i);
        ws.ping.setCamera(rays, start, end, originWidth_);
        if (!traceLevels(ws, ws.ping, 0, out, counters, stale)) return false;
    }
    return true;
}

bool TraceKernel::traceLevels(Workspace& ws, Level& start, int depth, const TraceOutput& out,
                              TraceCounters& counters, const std::function<bool()>& stale) const {
    // Settings constant for the whole call pick the instance: no per-hit branch on them.
    const bool bookkeeping = out.primary || out.rays || out.segments || out.records;
    const bool asDiffuse = options_.reflectionAsDiffuse || options_.refractionAsDiffuse;
    const auto shade = bookkeeping ? (asDiffuse ? &TraceKernel::shadeLevel<true, true>
                                                : &TraceKernel::shadeLevel<true, false>)
                                   : (asDiffuse ? &TraceKernel::shadeLevel<false, true>
                                                : &TraceKernel::shadeLevel<false, false>);
    Level* cur = &start;
    while (cur->size() > 0) {
        if (stale && stale()) return false;
        if (cur->size() > kLevelCap) {
            // Too wide to keep with its children: trace it in parts, each to the bottom.
            const Level whole = std::move(*cur);
            cur->clear();
            for (std::size_t b = 0; b < whole.size(); b += kLevelCap / 2) {
                Level part;
                part.append(whole, b, std::min(whole.size(), b + kLevelCap / 2));
                if (!traceLevels(ws, part, depth, out, counters, stale)) return false;
            }
            return true;
        }
        Level* next = cur == &ws.ping ? &ws.pong : &ws.ping;
        next->clear();
        (this->*shade)(ws, *cur, depth, *next, out, counters);
        cur = next;
        ++depth;
    }
    return true;
}

template <bool AsDiffuse>
[[gnu::always_inline]] inline std::size_t TraceKernel::shadeHits(LevelPoints& pts,
                                                                 const Level& level,
                                                                 const HitBatch& hits, int depth,
                                                                 Level& next,
                                                                 const TraceOutput& out) const {
    const RenderSettings& settings = scene_.settings();
    const bool environment = scene_.environment().present;
    const ShadingPoints& sp = pts.shading;
    std::size_t count = 0;  // shading points written
    const bool leaves = !spawnsChildren(depth, options_.maxDepth);
    // The arrays through local pointers: the compiler cannot keep a vector's data pointer in
    // a register across stores it cannot tell apart from it.
    const uint32_t *owners = level.owner.data(), *seeds = level.seed.data(), *slots = hits.slot;
    const float* weights = level.weight.data();
    const CompiledMaterial* materials = scene_.materials().data();
    const SurfaceTerms<float>* surfaces = surfaces_.data();
    uint32_t *pointMaterial = pts.material.data(), *pointSeed = pts.seed.data();
    uint32_t *pointOwner = pts.owner.data(), *pointRay = pts.ray.data();
    float* pointWeight = pts.weight.data();
    // Misses with an environment: gathered, and looked up together after the loop (the only
    // additions to their owners' colours in it, so in the same order).
    EscapedRays& escaped = pts.escaped;
    std::size_t escapes = 0;
    if (environment) escaped.reserve(level.size());
    float *escapedX = escaped.x.data(), *escapedY = escaped.y.data(), *escapedZ = escaped.z.data();
    uint32_t* escapedRay = escaped.ray.data();
    for (std::size_t i = 0, n = level.size(); i < n; ++i) {
        const uint32_t owner = owners[i];
        const float weight = weights[i];
        if (slots[i] == kNoSlot) {  // a miss: the environment or the background
            if (environment) {
                const std::size_t k = escapes++;
                escapedX[k] = level.dx[i], escapedY[k] = level.dy[i], escapedZ[k] = level.dz[i];
                escapedRay[k] = uint32_t(i);
            } else {
                out.color[owner] += weight * settings.background;
            }
            continue;
        }
        uint32_t materialIndex;
        ObjectId id;
        scene_.describe(slots[i], materialIndex, id);
        const CompiledMaterial& m = materials[materialIndex];
        const MovingShares s = movingShares<AsDiffuse>(m, id, options_);
        if (m.localWeight > 0.0f || (AsDiffuse && s.asDiffuse > 0.0f)) {
            const std::size_t j = count++;
            pointRay[j] = uint32_t(i);
            pts.surface.set(j, surfaces[materialIndex]);
            if (AsDiffuse)
                pts.lambert.set(j, lamberts_[materialIndex]), pts.asDiffuse[j] = s.asDiffuse;
            pointMaterial[j] = materialIndex, pointSeed[j] = seeds[i], pointOwner[j] = owner;
            pointWeight[j] = weight;
        }
        if (leaves || (s.reflectivity <= 0.0f && s.transparency <= 0.0f)) continue;
        // The cone's width at the hit: where children start.
        const float width = level.cone[i] + hits.t[i] * spread_;
        spawnChildren(m, s.reflectivity, s.transparency, Vec3(sp.px[i], sp.py[i], sp.pz[i]),
                      Vec3(sp.nx[i], sp.ny[i], sp.nz[i]),
                      Vec3(level.dx[i], level.dy[i], level.dz[i]), pts.inside[i] != 0, weight,
                      seeds[i], owner, width, next);
    }
    if (escapes > 0) {
        scene_.environmentColors(escapes, {escapedX, escapedY, escapedZ}, spread_,
                                 escaped.spot.data(), escaped.color.data());
        for (std::size_t k = 0; k < escapes; ++k) {
            const uint32_t i = escapedRay[k];
            out.color[owners[i]] += weights[i] * escaped.color[k];
        }
    }
    return count;
}

[[gnu::always_inline]] inline void TraceKernel::spawnChildren(
    const CompiledMaterial& m, float reflectivity, float transparency, const Vec3& p,
    const Vec3& nf, const Vec3& d, bool inside, float weight, uint32_t seed, uint32_t owner,
    float width, Level& next) const {
    // Reflection is traced once and weighted by the mirror part plus the glass part's
    // Fresnel (or all of the glass part on total internal reflection). A child whose
    // accumulated weight falls below min_weight is not traced (scenes/FORMAT.md).
    float reflectWeight = reflectivity;
    if (transparency > 0.0f) {
        const float eta = inside ? m.ior : 1.0f / m.ior;
        Vec3 t;
        if (refractDir(d, nf, eta, t)) {
            const float f = schlick(-glm::dot(nf, d), m.ior);
            reflectWeight += transparency * f;
            const float w = weight * (transparency * (1.0f - f));
            if (weightTraced(w, options_.minWeight))
                next.push(p - nf * eps_, t, w, hashCombine(seed, 2u), owner, width);
        } else {
            reflectWeight += transparency;
        }
    }
    if (reflectWeight > 0.0f) {
        const float w = weight * reflectWeight;
        if (weightTraced(w, options_.minWeight))
            next.push(p + nf * eps_, d - 2.0f * glm::dot(d, nf) * nf, w, hashCombine(seed, 1u),
                      owner, width);
    }
}

[[gnu::always_inline]] inline void TraceKernel::closeUpPoints(LevelPoints& pts, std::size_t count,
                                                              std::size_t n) {
    ShadingPoints& sp = pts.shading;
    if (count < n) {  // close up: point j is the j-th shaded hit (ray i >= j, so in place)
        const uint32_t* pointRay = pts.ray.data();
        for (std::size_t j = 0; j < count; ++j) {
            const std::size_t i = pointRay[j];
            if (j != i)
                sp.set(j, Vec3(sp.px[i], sp.py[i], sp.pz[i]), Vec3(sp.nx[i], sp.ny[i], sp.nz[i]),
                       Vec3(sp.vx[i], sp.vy[i], sp.vz[i]));
        }
    }
    sp.count = count;
}

template <bool AsDiffuse>
[[gnu::always_inline]] inline void TraceKernel::patternLooks(LevelPoints& pts, const Level& level,
                                                             const HitBatch& hits) const {
    // Patterned points: the pattern's colour there, filtered over the cone's footprint,
    // in place of the material's colour in every term (scenes/FORMAT.md "color"); every
    // point's ambient terms, which the local sums below then take point by point. Checkered
    // points are gathered and their footprints and box filters run several at a time
    // (CheckerBatch), each giving the colour surfaceColor would.
    const ShadingPoints& sp = pts.shading;
    const CompiledMaterial* materials = scene_.materials().data();
    const uint32_t *pointMaterial = pts.material.data(), *pointRay = pts.ray.data();
    const Color ambient = scene_.settings().ambient;
    const auto setLook = [&](std::size_t j, const CompiledMaterial& m, const Color& c) {
        const SurfaceLook look = materialLook(m, c, ambient);
        pts.surface.r[j] = look.terms.r;
        pts.surface.g[j] = look.terms.g;
        pts.surface.b[j] = look.terms.b;
        pts.ambient[j] = look.ambient;
        if (AsDiffuse) {
            const SurfaceLook lambert = lambertLook(c, ambient);
            pts.lambert.set(j, lambert.terms);
            pts.lambertAmbient[j] = lambert.ambient;
        }
    };
    CheckerBatch& checkers = pts.checkers;
    checkers.reset(sp.count);
    for (std::size_t j = 0, count = sp.count; j < count; ++j) {
        const uint32_t mi = pointMaterial[j];
        const CompiledMaterial& m = materials[mi];
        if (m.pattern.kind == MaterialPattern::Kind::None) {
            pts.ambient[j] = ambients_[mi];
            if (AsDiffuse) pts.lambertAmbient[j] = lambertAmbients_[mi];
            continue;
        }
        const std::size_t i = pointRay[j];
        const Vec3 p(sp.px[j], sp.py[j], sp.pz[j]), d(level.dx[i], level.dy[i], level.dz[i]);
        const Vec3 normal(hits.nx[i], hits.ny[i], hits.nz[i]);
        const float width = level.cone[i] + hits.t[i] * spread_;
        if (m.pattern.kind == MaterialPattern::Kind::Checker) {
            checkers.add(uint32_t(j), scene_.patterns().at(hits.slot[i]), p, d, normal, width,
                         m.pattern.checkerScale);
            continue;
        }
        setLook(j, m, surfaceColor(m, hits.slot[i], p, normal, d, width));
    }
    if (checkers.size() == 0) return;
    const float* odd = checkers.evaluate();
    for (std::size_t k = 0, n = checkers.size(); k < n; ++k) {
        const std::size_t j = checkers.point(k);
        const CompiledMaterial& m = materials[pointMaterial[j]];
        setLook(j, m, checkerColor(m.pattern, odd[k]));
    }
}

/// The shading points [first, end) of a level whose lights one shadow batch serves.
struct TraceKernel::PointGroup {
    std::size_t first, end;
    bool sampled;  ///< Some lights are sphere lights sampled over their disk.
    /// The shadow answers and what passed glass of the sphere lights' samples (null: none
    /// traced, or nothing transmits).
    const uint8_t* areaOccluded = nullptr;
    const Color* areaTransmitted = nullptr;
};

template <bool Bookkeeping, bool AsDiffuse>
[[gnu::always_inline]] inline void TraceKernel::addLocalTerms(Workspace& ws, bool patterns,
                                                              const TraceOutput& out,
                                                              TraceCounters& counters) const {
    // The local terms, light by light over as many points as fit one shadow batch.
    const std::size_t count = ws.points.count();
    const std::size_t lane = std::size_t(kLaneWidth);
    const std::size_t chunk =
        std::max(lane, kSampleCap / std::max<std::size_t>(1, perPoint_) / lane * lane);
    const std::size_t lightCount = scene_.lights().size();
    if (ws.centres.size() < lightCount)
        ws.centres.resize(lightCount), ws.blocked.resize(lightCount);
    ws.sums.zero(count);
    if (AsDiffuse) ws.lambertSums.zero(count);
    for (std::size_t first = 0; first < count; first += chunk) {
        PointGroup g{first, std::min(count, first + chunk), !sampledLights_.empty()};
        sampleGroup(ws, g);
        if (traceShadows_) traceGroupShadows<Bookkeeping>(ws, g, out, counters);
        sumGroupLights<AsDiffuse>(ws, g);
        // Ambient terms per material, or per point when the scene has patterns: a loop for
        // each, so flat-colour scenes run the loop they always did.
        if (patterns)
            addGroupLocal<Bookkeeping, AsDiffuse, true>(ws, g, out);
        else
            addGroupLocal<Bookkeeping, AsDiffuse, false>(ws, g, out);
    }
}

[[gnu::always_inline]] inline void TraceKernel::sampleGroup(Workspace& ws,
                                                            const PointGroup& g) const {
    // Sphere lights' samples, point by point (lanes of samples), in light order.
    const ShadingPoints& sp = ws.points.shading;
    ws.samples.clear();
    ws.spans.clear();
    if (g.sampled) {
        ws.pointSpans.resize(g.end - g.first + 1);
        for (std::size_t j = g.first; j < g.end; ++j) {
            ws.pointSpans[j - g.first] = uint32_t(ws.spans.size());
            const Vec3 p(sp.px[j], sp.py[j], sp.pz[j]), nf(sp.nx[j], sp.ny[j], sp.nz[j]);
            for (const uint32_t li : sampledLights_)
                sampler_.sampleLight(li, p, nf, ws.points.seed[j], area_, ws.samples, ws.spans);
        }
        ws.pointSpans[g.end - g.first] = uint32_t(ws.spans.size());
    }
    for (const uint32_t li : centreLights_)
        sampler_.sampleCentres(li, sp, g.first, g.end, ws.centres[li]);
}

template <bool Bookkeeping>
[[gnu::always_inline]] inline void TraceKernel::traceGroupShadows(Workspace& ws, PointGroup& g,
                                                                  const TraceOutput& out,
                                                                  TraceCounters& counters) const {
    // One shadow batch: every centre-sampled light's listed rays, light by light, then
    // the sphere lights' samples in list order.
    const ShadingPoints& sp = ws.points.shading;
    const std::size_t first = g.first, end = g.end, lightCount = scene_.lights().size();
    const ShadowRayArrays rays = ws.shadows((end - first) * perPoint_);
    if (ws.centreBase.size() < lightCount) ws.centreBase.resize(lightCount);
    for (const uint32_t li : centreLights_) {
        ws.centreBase[li] = uint32_t(ws.shadowCount);
        ws.shadowCount =
            writeCentreShadows(sp, ws.centres[li], first, end, eps_, li, rays, ws.shadowCount);
    }
    const std::size_t areaBase = ws.shadowCount;
    if (g.sampled) ws.shadowRays(sp, first, end - first, eps_, areaBase);
    // One answer past the rays, so the loop below may read it without a branch.
    ws.occluded.resize(ws.shadowCount + 1);
    ws.occluded[ws.shadowCount] = 0;
    if (ws.shadowCount > 0) {
        scene_.engine().anyHit(ws.shadowBatch(area_), ws.occluded.data());
        counters.shadowRays += ws.shadowCount;
        if (transmissive_) transmit(ws);
    }
    // Each centre ray's answer back to its point (flags are 0 or 1).
    std::size_t r = 0;
    for (const uint32_t li : centreLights_) {
        const CentreSamples& c = ws.centres[li];
        ScratchVector<uint8_t>& blocked = ws.blocked[li];
        if (blocked.size() < sp.px.size()) blocked.resize(sp.px.size());
        r = readCentreAnswers(c, first, end, ws.occluded.data(), blocked.data(), r);
        if (Bookkeeping && out.rays)
            for (std::size_t j = first; j < end; ++j) out.rays[ws.points.owner[j]] += c.listed[j];
    }
    g.areaOccluded = ws.occluded.data() + areaBase;
    if (transmissive_) g.areaTransmitted = ws.transmitted.data() + areaBase;
    if (Bookkeeping && out.rays && g.sampled)
        for (std::size_t j = first; j < end; ++j)
            for (uint32_t k = ws.pointSpans[j - first]; k < ws.pointSpans[j - first + 1]; ++k)
                out.rays[ws.points.owner[j]] += ws.spans[k].listed;
}

template <bool AsDiffuse>
[[gnu::always_inline]] inline void TraceKernel::sumGroupLights(Workspace& ws,
                                                               const PointGroup& g) const {
    // Light by light, so each point's sum takes the lights in the scene's order.
    const LevelPoints& pts = ws.points;
    const ShadingPoints& sp = pts.shading;
    const std::size_t first = g.first, end = g.end;
    if (g.sampled) ws.cursor.assign(ws.pointSpans.begin(), ws.pointSpans.end() - 1);
    for (std::size_t li = 0; li < scene_.lights().size(); ++li) {
        if (sampler_.centreOnly(li, area_)) {
            const CompiledLight& light = scene_.lights()[li];
            const uint8_t* blocked = traceShadows_ ? ws.blocked[li].data() : nullptr;
            addCentreLight(light, sp, pts.surface, ws.centres[li], blocked, first, end, ws.sums);
            if (AsDiffuse)
                addCentreLight(light, sp, pts.lambert, ws.centres[li], blocked, first, end,
                               ws.lambertSums);
            if (transmissive_ && traceShadows_) addTransmitted<AsDiffuse>(ws, li, first, end);
            continue;
        }
        for (std::size_t j = first; j < end; ++j) {
            uint32_t& k = ws.cursor[j - first];
            if (k == ws.pointSpans[j - first + 1] || ws.spans[k].light != li) continue;
            const LightSpan& span = ws.spans[k++];
            const Vec3 nf(sp.nx[j], sp.ny[j], sp.nz[j]), v(sp.vx[j], sp.vy[j], sp.vz[j]);
            const Color c = spanShare(scene_, pts.surface.get(j), nf, v, span, ws.samples.data(),
                                      g.areaOccluded, g.areaTransmitted);
            ws.sums.r[j] += c.x, ws.sums.g[j] += c.y, ws.sums.b[j] += c.z;
            if (AsDiffuse) {
                const Color l = spanShare(scene_, pts.lambert.get(j), nf, v, span,
                                          ws.samples.data(), g.areaOccluded, g.areaTransmitted);
                ws.lambertSums.r[j] += l.x, ws.lambertSums.g[j] += l.y, ws.lambertSums.b[j] += l.z;
            }
        }
    }
}

template <bool Bookkeeping, bool AsDiffuse, bool Patterned>
[[gnu::always_inline]] inline void TraceKernel::addGroupLocal(Workspace& ws, const PointGroup& g,
                                                              const TraceOutput& out) const {
    const LevelPoints& pts = ws.points;
    const ShadingPoints& sp = pts.shading;
    const float *sumR = ws.sums.r.data(), *sumG = ws.sums.g.data(), *sumB = ws.sums.b.data();
    const uint32_t *pointMaterial = pts.material.data(), *pointOwner = pts.owner.data();
    const float* pointWeight = pts.weight.data();
    const CompiledMaterial* materials = scene_.materials().data();
    Color* color = out.color;
    std::optional<PerRayAppender<ShadingRecord>> records;
    if (Bookkeeping && options_.shadows == ShadowQuality::Deferred && out.records)
        records.emplace(out.records);
    const Color* ambients = Patterned ? pts.ambient.data() : ambients_.data();
    const Color* lambertAmbients = Patterned ? pts.lambertAmbient.data() : lambertAmbients_.data();
    for (std::size_t j = g.first; j < g.end; ++j) {
        const uint32_t mi = pointMaterial[j], owner = pointOwner[j];
        const std::size_t a = Patterned ? j : mi;
        const float weight = pointWeight[j], localWeight = materials[mi].localWeight;
        if (localWeight > 0.0f) {
            const Color direct(sumR[j], sumG[j], sumB[j]);
            color[owner] += weight * (localWeight * (ambients[a] + direct));
            // Shown unshadowed while moving; the record lets the shadows be added later.
            if (Bookkeeping && records)
                records->append(
                    owner,
                    ShadingRecord{Vec3(sp.px[j], sp.py[j], sp.pz[j]),
                                  Vec3(sp.nx[j], sp.ny[j], sp.nz[j]),
                                  Vec3(sp.vx[j], sp.vy[j], sp.vz[j]), weight * localWeight,
                                  Color(pts.surface.r[j], pts.surface.g[j], pts.surface.b[j]), mi,
                                  pts.seed[j]});
        }
        if (AsDiffuse && pts.asDiffuse[j] > 0.0f) {
            const Color direct(ws.lambertSums.r[j], ws.lambertSums.g[j], ws.lambertSums.b[j]);
            color[owner] += weight * (pts.asDiffuse[j] * (lambertAmbients[a] + direct));
        }
    }
}

template <bool Bookkeeping, bool AsDiffuse>
void TraceKernel::shadeLevel(Workspace& ws, const Level& level, int depth, Level& next,
                             const TraceOutput& out, TraceCounters& counters) const {
    const std::size_t n = level.size();
    next.reserve(kMostChildrenPerHit * n);
    const HitBatch hits = ws.hits(n);
    scene_.engine().closestHit(level.batch(depth == 0), hits);
    counters.rays += n;
    LevelPoints& pts = ws.points;
    // Patterns are looked up only in scenes that have them: a flat-colour scene takes the
    // per-material tables, as it always did.
    const bool patterns = scene_.hasPatterns();
    pts.reserve(n, AsDiffuse, patterns);
    // Where each hit lies and which way it faces, four rays at a time into the points'
    // arrays at the ray's index; what its material makes of it, hit by hit, with the other
    // arrays written at the point's index; then, if some hits are not shaded (misses,
    // surfaces with no local share), the lanes' arrays closed up to match.
    faceHits(level.ox.data(), level.oy.data(), level.oz.data(), level.dx.data(), level.dy.data(),
             level.dz.data(), hits, n, pts.shading, pts.inside.data());
    if (Bookkeeping) keepBooks(level, hits, depth, out);
    const std::size_t count = shadeHits<AsDiffuse>(pts, level, hits, depth, next, out);
    closeUpPoints(pts, count, n);
    if (count == 0) return;
    if (patterns) patternLooks<AsDiffuse>(pts, level, hits);
    addLocalTerms<Bookkeeping, AsDiffuse>(ws, patterns, out, counters);
}

void TraceKernel::resolveDeferred(const ShadingRecord* records, std::size_t count, Color* out,
                                  TraceCounters& counters) const {
    thread_local Workspace ws;
    ShadingPoints& pts = ws.points.shading;
    const bool shadows = scene_.settings().shadowSamples > 0;
    for (std::size_t first = 0; first < count;) {
        ws.samples.clear();
        ws.spans.clear();
        ws.pointSpans.clear();
        ws.centreSamples.clear();
        ws.centreSpans.clear();
        ws.centrePointSpans.clear();
        std::size_t n = 0;
        while (first + n < count && (n == 0 || ws.samples.size() < kSampleCap)) {
            const ShadingRecord& r = records[first + n];
            ws.pointSpans.push_back(uint32_t(ws.spans.size()));
            ws.centrePointSpans.push_back(uint32_t(ws.centreSpans.size()));
            // Shadowed as a full trace samples the lights, unshadowed as the Deferred trace did.
            sampler_.sample(r.p, r.n, r.seed, true, ws.samples, ws.spans);
            sampler_.sample(r.p, r.n, r.seed, false, ws.centreSamples, ws.centreSpans);
            ++n;
        }
        ws.pointSpans.push_back(uint32_t(ws.spans.size()));
        ws.centrePointSpans.push_back(uint32_t(ws.centreSpans.size()));
        const uint8_t* occluded = nullptr;
        const Color* transmitted = nullptr;
        if (shadows && !ws.samples.empty()) {
            pts.resize(n);
            for (std::size_t j = 0; j < n; ++j) {
                const ShadingRecord& r = records[first + j];
                pts.set(j, r.p, r.n, r.toViewer);
            }
            ws.shadowRays(pts, 0, n, eps_);
            ws.occluded.resize(ws.samples.size());
            scene_.engine().anyHit(ws.shadowBatch(true), ws.occluded.data());
            occluded = ws.occluded.data();
            counters.shadowRays += ws.samples.size();
            if (transmissive_) {
                transmit(ws);
                transmitted = ws.transmitted.data();
            }
        }
        for (std::size_t j = 0; j < n; ++j) {
            const ShadingRecord& r = records[first + j];
            const SurfaceTerms<float> terms = recordTerms(r);
            const Color shadowed = shadeLights(
                scene_, terms, r.n, r.toViewer, ws.spans.data() + ws.pointSpans[j],
                ws.pointSpans[j + 1] - ws.pointSpans[j], ws.samples.data(), occluded, transmitted);
            const Color unshadowed = shadeLights(
                scene_, terms, r.n, r.toViewer, ws.centreSpans.data() + ws.centrePointSpans[j],
                ws.centrePointSpans[j + 1] - ws.centrePointSpans[j], ws.centreSamples.data(),
                nullptr);
            out[first + j] = r.weight * (shadowed - unshadowed);
        }
        first += n;
    }
}

void TraceKernel::firstHits(const CameraBatch& rays, ObjectId* ids) const {
    thread_local Workspace ws;
    for (std::size_t start = 0; start < rays.count; start += kCameraChunk) {
        const std::size_t end = std::min(rays.count, start + kCameraChunk);
        ws.ping.setCamera(CameraBatch{rays.origin, rays.dir, nullptr, rays.count, rays.coherent},
                          start, end);
        const HitBatch hits = ws.hits(ws.ping.size());
        scene_.engine().closestHit(ws.ping.batch(rays.coherent), hits);
        for (std::size_t i = start; i < end; ++i) {
            ids[i] = kNoObject;
            uint32_t material;
            if (hits.slot[i - start] != kNoSlot)
                scene_.describe(hits.slot[i - start], material, ids[i]);
        }
    }
}

}  // namespace rs
