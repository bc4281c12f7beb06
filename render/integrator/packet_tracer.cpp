// Eight-lane ray packets for flat scenes: camera rays, then each level of reflections and
// refractions, intersected and shaded with the integrator's operations lane by lane.
#include "integrator/packet_tracer.h"

#include "integrator/renderer.h"
#include "integrator/sampling.h"

#include <cmath>
#include <cstring>
#include <memory>
#include <span>
#include <vector>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RS_PACKET_DISPATCH 1
#include <immintrin.h>
#elif defined(__SSE2__)
#include <immintrin.h>
#endif

namespace rs {

namespace {

/// Where a level's rays live: structure of arrays, so a batch loads with six plain loads.
struct RayArrays {
    float *ox, *oy, *oz, *dx, *dy, *dz;
    void set(std::size_t i, const Vec3& o, const Vec3& d) const {
        ox[i] = o.x, oy[i] = o.y, oz[i] = o.z;
        dx[i] = d.x, dy[i] = d.y, dz[i] = d.z;
    }
};

}  // namespace

/// The scene as the kernel reads it per lane: structure-of-arrays tables to gather from,
/// built once per PacketTracer. Each table has at least one entry, so index 0 is always
/// safe to gather for lanes that did not hit that kind of shape.
struct PacketTables {
    // Flat spheres, in primitives() order.
    std::vector<float> sphereX, sphereY, sphereZ, sphereRadius;
    std::vector<int32_t> sphereMaterial;
    std::vector<ObjectId> sphereId;
    // Planes, in planes() order.
    std::vector<float> planeNx, planeNy, planeNz;
    std::vector<int32_t> planeMaterial;
    std::vector<ObjectId> planeId;
    // Materials.
    std::vector<float> red, green, blue, diffuse, specular, cutoff, localWeight;

    explicit PacketTables(const CompiledScene& scene) {
        const auto& spheres = scene.flatSpheres();
        for (std::size_t i = 0; i < spheres.size(); ++i) {
            sphereX.push_back(spheres[i].center.x);
            sphereY.push_back(spheres[i].center.y);
            sphereZ.push_back(spheres[i].center.z);
            sphereRadius.push_back(spheres[i].radius);
            sphereMaterial.push_back(int32_t(scene.primitives()[i].material));
            sphereId.push_back(scene.primitives()[i].id);
        }
        for (const PlanePrimitive& p : scene.planes()) {
            planeNx.push_back(p.shape.normal.x);
            planeNy.push_back(p.shape.normal.y);
            planeNz.push_back(p.shape.normal.z);
            planeMaterial.push_back(int32_t(p.material));
            planeId.push_back(p.id);
        }
        for (const CompiledMaterial& m : scene.materials()) {
            red.push_back(m.color.x), green.push_back(m.color.y), blue.push_back(m.color.z);
            diffuse.push_back(m.diffuse), specular.push_back(m.specular);
            cutoff.push_back(m.specularCutoff), localWeight.push_back(m.localWeight);
        }
        for (auto* v : {&sphereX, &sphereY, &sphereZ, &sphereRadius, &planeNx, &planeNy,
                        &planeNz, &red, &green, &blue, &diffuse, &specular, &cutoff,
                        &localWeight})
            if (v->empty()) v->push_back(0.0f);
        for (auto* v : {&sphereMaterial, &planeMaterial})
            if (v->empty()) v->push_back(0);
        for (auto* v : {&sphereId, &planeId})
            if (v->empty()) v->push_back(kNoObject);
    }
};

namespace {

/// What one ray of a tree gave, to be summed with its children's colours afterwards.
struct PathNode {
    Color local{0.0f};          ///< The shaded local term (zero without one).
    float reflectWeight = 0.0f;
    float refractWeight = 0.0f;
    int32_t reflect = -1;       ///< Index of the reflection child in the next level, or -1.
    int32_t refract = -1;       ///< Index of the refraction child in the next level, or -1.
    float t = 0.0f;             ///< Hit distance.
    uint32_t shadowRays = 0;    ///< Shadow rays traced at this hit.
    bool hit = false;           ///< False: the ray escaped and sees the background.
    bool specular = false;      ///< The tree continues here (trace() did not return early).
    bool specularMaterial = false;  ///< Hit a mirror or glass (PrimaryInfo::touchedSpecular).
};

}  // namespace

#if defined(RS_PACKET_DISPATCH)
namespace avx2 {
namespace {
#pragma GCC push_options
#pragma GCC target("avx2")
#define RS_PACKET_AVX2 1
#include "integrator/packet_kernel.inl"
#undef RS_PACKET_AVX2
#pragma GCC pop_options
}  // namespace
}  // namespace avx2
#endif

namespace baseline {
namespace {
#include "integrator/packet_kernel.inl"
}  // namespace
}  // namespace baseline

namespace {

constexpr int kBatch = 8;

/// One level of a tile's ray trees.
struct Level {
    /// The level's rays (none for the camera level, whose rays are generated).
    std::vector<float> ox, oy, oz, dx, dy, dz;
    std::vector<PathNode> nodes;
    std::vector<Color> colors;
    std::vector<uint32_t> treeRays;     ///< Rays of each node's subtree (tracePixels only).
    std::vector<uint8_t> treeSpecular;  ///< The subtree met a mirror or glass (same).

    /// Room for `count` rays plus one batch read past the end.
    RayArrays arrays(std::size_t count) {
        if (ox.size() < count + kBatch)
            for (auto* v : {&ox, &oy, &oz, &dx, &dy, &dz}) v->resize(count + kBatch, 0.0f);
        return {ox.data(), oy.data(), oz.data(), dx.data(), dy.data(), dz.data()};
    }
};

/// Per-thread storage reused from tile to tile: no allocation once it has grown.
struct Workspace {
    std::vector<Level> levels;
    // The camera level's first hits (tracePixels).
    std::vector<ObjectId> ids;
    std::vector<Vec3> normals;
    std::vector<float> depths;
    std::vector<Vec3> points;
    // Image points of the camera rays, and per-pixel sums of samples.
    std::vector<float> px, py;
    std::vector<Color> sums;
};

/// trace()'s sums for one node, its children's colours already known.
inline Color sumNode(const PathNode& node, const Level* children, const Color& background) {
    if (!node.hit) return background;
    Color result = node.local;
    if (!node.specular) return result;
    Color refracted(0.0f);
    if (node.refract >= 0)
        refracted = node.refractWeight * children->colors[std::size_t(node.refract)];
    if (node.reflectWeight > 0.0f)
        result += node.reflectWeight * children->colors[std::size_t(node.reflect)];
    return result + refracted;
}

/// Traces the levels below the camera level (whose children are `nextCount` rays in level 1)
/// until no ray is left; returns the deepest level.
template <class Kernel>
std::size_t traceSecondaryLevels(const Kernel& kernel, Workspace& ws, std::size_t nextCount,
                                 TraceCounters& counters) {
    std::size_t depth = 0;
    while (nextCount > 0) {
        ++depth;
        if (ws.levels.size() < depth + 2) ws.levels.resize(depth + 2);
        const std::size_t count = nextCount;
        const RayArrays rays = ws.levels[depth].arrays(count);
        const RayArrays next = ws.levels[depth + 1].arrays(2 * count);  // two children at most
        Level& level = ws.levels[depth];
        level.nodes.resize(count);
        nextCount = 0;
        for (std::size_t i = 0; i < count; i += kBatch) {
            const int n = int(std::min<std::size_t>(kBatch, count - i));
            kernel.traceSecondary(rays, i, n, int(depth), &level.nodes[i], next, nextCount,
                                  counters);
        }
    }
    return depth;
}

/// trace()'s sums of levels depth..1, leaves first (the camera level is left to the caller);
/// with `treeInfo`, also each node's subtree ray count and whether it met a mirror or glass.
void sumLevels(Workspace& ws, std::size_t depth, const Color& background, bool treeInfo) {
    for (std::size_t l = depth; l > 0; --l) {
        Level& level = ws.levels[l];
        const Level* children = l < depth ? &ws.levels[l + 1] : nullptr;
        const std::size_t n = level.nodes.size();
        level.colors.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            level.colors[i] = sumNode(level.nodes[i], children, background);
        if (!treeInfo) continue;
        level.treeRays.resize(n);
        level.treeSpecular.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const PathNode& node = level.nodes[i];
            uint32_t rays = 1 + node.shadowRays;
            uint8_t specular = node.specularMaterial;
            for (int32_t child : {node.refract, node.reflect}) {
                if (child < 0) continue;
                rays += children->treeRays[std::size_t(child)];
                specular |= children->treeSpecular[std::size_t(child)];
            }
            level.treeRays[i] = rays;
            level.treeSpecular[i] = specular;
        }
    }
}

/// Appends the secondary segments below `node` (level `level`) in trace()'s order: each
/// child's own segment, then its subtree, the refraction child before the reflection child.
void collectSegments(const Workspace& ws, std::size_t level, const PathNode& node, int capacity,
                     std::vector<TreeSegment>& segments, PacketPixel& out) {
    const Level& below = ws.levels[level + 1];
    for (int32_t child : {node.refract, node.reflect}) {
        if (child < 0) continue;
        const std::size_t c = std::size_t(child);
        const PathNode& n = below.nodes[c];
        const Vec3 o(below.ox[c], below.oy[c], below.oz[c]);
        const Vec3 d(below.dx[c], below.dy[c], below.dz[c]);
        if (out.segmentCount < uint32_t(capacity)) {
            segments.push_back(n.hit ? TreeSegment{o, o + d * n.t, 0u} : TreeSegment{o, d, 1u});
            ++out.segmentCount;
        } else {
            out.segmentOverflow = true;
        }
        collectSegments(ws, level + 1, n, capacity, segments, out);
    }
}

/// Traces a tile level by level with `kernel`: camera rays, then each level's children.
template <class Kernel>
void traceTileWith(const Kernel& kernel, Workspace& ws, const CompiledScene& scene, int x0,
                   int y0, int x1, int y1, const RaySubset& subset, std::size_t stride,
                   Color* colors, ObjectId* ids, Vec3* normals, TraceCounters& counters) {
    const int width = x1 - x0, height = y1 - y0;
    if (width <= 0 || height <= 0) return;
    if (ws.levels.size() < 2) ws.levels.resize(2);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    ws.levels[0].nodes.resize(pixels);
    const RayArrays next = ws.levels[1].arrays(2 * pixels);  // two children per ray at most
    std::size_t nextCount = 0;
    const RaySubset* cameraSubset = subset.valid ? &subset : nullptr;
    float px[kBatch], py[kBatch];
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; x += kBatch) {
            const int count = std::min(kBatch, x1 - x);
            for (int k = 0; k < count; ++k) px[k] = float(x + k) + 0.5f, py[k] = float(y) + 0.5f;
            const std::size_t local =
                std::size_t(y - y0) * std::size_t(width) + std::size_t(x - x0);
            const std::size_t pixel = std::size_t(y) * stride + std::size_t(x);
            kernel.traceCamera(px, py, count, cameraSubset, &ws.levels[0].nodes[local], next,
                               nextCount, ids ? ids + pixel : nullptr,
                               normals ? normals + pixel : nullptr, nullptr, nullptr, counters);
        }
    }
    const std::size_t depth = traceSecondaryLevels(kernel, ws, nextCount, counters);
    const Color& background = scene.settings().background;
    sumLevels(ws, depth, background, false);
    // The camera level's colours go straight to the image.
    const Level* children = depth > 0 ? &ws.levels[1] : nullptr;
    const PathNode* node = ws.levels[0].nodes.data();
    for (int y = y0; y < y1; ++y) {
        Color* row = colors + std::size_t(y) * stride;
        for (int x = x0; x < x1; ++x) row[x] = sumNode(*node++, children, background);
    }
}

/// Image points of the pixels' centres, as renderImage passes them to generateRay.
void centres(Workspace& ws, const int32_t* xs, const int32_t* ys, std::size_t count) {
    ws.px.resize(count + kBatch);
    ws.py.resize(count + kBatch);
    for (std::size_t i = 0; i < count; ++i)
        ws.px[i] = float(xs[i]) + 0.5f, ws.py[i] = float(ys[i]) + 0.5f;
}

/// Traces a list of pixels with `kernel`, with the session's per-pixel outputs.
template <class Kernel>
void tracePixelsWith(const Kernel& kernel, Workspace& ws, const CompiledScene& scene,
                     const int32_t* xs, const int32_t* ys, std::size_t count,
                     const RaySubset& subset, int segmentCapacity, PacketPixel* out,
                     std::vector<TreeSegment>& segments, TraceCounters& counters) {
    if (count == 0) return;
    if (ws.levels.size() < 2) ws.levels.resize(2);
    ws.levels[0].nodes.resize(count);
    ws.ids.resize(count);
    ws.normals.resize(count);
    ws.depths.resize(count);
    ws.points.resize(count);
    centres(ws, xs, ys, count);
    const RayArrays next = ws.levels[1].arrays(2 * count);
    std::size_t nextCount = 0;
    const RaySubset* cameraSubset = subset.valid ? &subset : nullptr;
    for (std::size_t i = 0; i < count; i += kBatch) {
        const int n = int(std::min<std::size_t>(kBatch, count - i));
        kernel.traceCamera(&ws.px[i], &ws.py[i], n, cameraSubset, &ws.levels[0].nodes[i], next,
                           nextCount, &ws.ids[i], &ws.normals[i], &ws.depths[i], &ws.points[i],
                           counters);
    }
    const std::size_t depth = traceSecondaryLevels(kernel, ws, nextCount, counters);
    const Color& background = scene.settings().background;
    sumLevels(ws, depth, background, true);
    const Level* children = depth > 0 ? &ws.levels[1] : nullptr;
    for (std::size_t i = 0; i < count; ++i) {
        const PathNode& node = ws.levels[0].nodes[i];
        PacketPixel& o = out[i];
        o = PacketPixel{};
        o.color = sumNode(node, children, background);
        o.info.id = ws.ids[i];
        o.info.depth = ws.depths[i];
        o.hitPoint = ws.points[i];
        o.info.normal = ws.normals[i];
        o.rays = 1 + node.shadowRays;
        o.info.touchedSpecular = node.specularMaterial;
        for (int32_t child : {node.refract, node.reflect}) {
            if (child < 0) continue;
            o.rays += children->treeRays[std::size_t(child)];
            o.info.touchedSpecular |= children->treeSpecular[std::size_t(child)] != 0;
        }
        o.segmentOffset = uint32_t(segments.size());
        if (depth > 0) collectSegments(ws, 0, node, segmentCapacity, segments, o);
    }
}

/// renderPixel's supersampled colours for a list of pixels: sample k of every pixel is traced
/// as one list, and each pixel adds its samples in order k = 0, 1, ... as renderPixel does.
template <class Kernel>
void traceSamplesWith(const Kernel& kernel, Workspace& ws, const CompiledScene& scene,
                      const int32_t* xs, const int32_t* ys, std::size_t count, int spp,
                      const RaySubset& subset, Color* out, TraceCounters& counters) {
    if (count == 0) return;
    if (ws.levels.size() < 2) ws.levels.resize(2);
    ws.levels[0].nodes.resize(count);
    ws.px.resize(count + kBatch);
    ws.py.resize(count + kBatch);
    ws.sums.assign(count, Color(0.0f));
    const RaySubset* cameraSubset = subset.valid ? &subset : nullptr;
    const Color& background = scene.settings().background;
    for (int k = 0; k < spp; ++k) {
        for (std::size_t i = 0; i < count; ++i) {
            const Vec3 o = pixelSampleOffset(k, spp, pixelSeed(xs[i], ys[i], 0x5eed));
            ws.px[i] = float(xs[i]) + o.x, ws.py[i] = float(ys[i]) + o.y;
        }
        const RayArrays next = ws.levels[1].arrays(2 * count);
        std::size_t nextCount = 0;
        for (std::size_t i = 0; i < count; i += kBatch) {
            const int n = int(std::min<std::size_t>(kBatch, count - i));
            kernel.traceCamera(&ws.px[i], &ws.py[i], n, cameraSubset, &ws.levels[0].nodes[i],
                               next, nextCount, nullptr, nullptr, nullptr, nullptr, counters);
        }
        const std::size_t depth = traceSecondaryLevels(kernel, ws, nextCount, counters);
        sumLevels(ws, depth, background, false);
        const Level* children = depth > 0 ? &ws.levels[1] : nullptr;
        for (std::size_t i = 0; i < count; ++i)
            ws.sums[i] += sumNode(ws.levels[0].nodes[i], children, background);
    }
    for (std::size_t i = 0; i < count; ++i) out[i] = ws.sums[i] / float(spp);
}

}  // namespace

bool PacketTracer::supports(const CompiledScene& scene) {
    if (!scene.testsFlat()) return false;
    if (scene.settings().shadowSamples <= 0) return true;
    for (const CompiledLight& l : scene.lights())
        if (l.radius > 0.0f) return false;
    return true;
}

bool PacketTracer::profitable() {
#if defined(RS_PACKET_DISPATCH)
    return __builtin_cpu_supports("avx2");
#else
    return false;  // not measured elsewhere: the scalar integrator stays
#endif
}

PacketTracer::PacketTracer(const CompiledScene& scene, Kernel kernel)
    : scene_(scene),
      tables_(std::make_unique<PacketTables>(scene)),
      kernel_(kernel),
      maxDepth_(TraceOptions::fromSettings(scene.settings()).maxDepth),
      shadows_(scene.settings().shadowSamples > 0),
      eps_(scene.epsilon()) {}

PacketTracer::~PacketTracer() = default;

void PacketTracer::traceSamples(const int32_t* xs, const int32_t* ys, std::size_t count, int spp,
                                const RaySubset& subset, Color* out,
                                TraceCounters& counters) const {
    thread_local Workspace ws;
#if defined(RS_PACKET_DISPATCH)
    if (kernel_ == Kernel::Fastest && __builtin_cpu_supports("avx2")) {
        const avx2::PacketKernel kernel(scene_, *tables_, maxDepth_, shadows_, eps_);
        traceSamplesWith(kernel, ws, scene_, xs, ys, count, spp, subset, out, counters);
        return;
    }
#endif
    const baseline::PacketKernel kernel(scene_, *tables_, maxDepth_, shadows_, eps_);
    traceSamplesWith(kernel, ws, scene_, xs, ys, count, spp, subset, out, counters);
}

void PacketTracer::firstHits(const int32_t* xs, const int32_t* ys, std::size_t count,
                             const RaySubset& subset, ObjectId* out) const {
    thread_local Workspace ws;
    centres(ws, xs, ys, count);
    const RaySubset* cameraSubset = subset.valid ? &subset : nullptr;
#if defined(RS_PACKET_DISPATCH)
    if (kernel_ == Kernel::Fastest && __builtin_cpu_supports("avx2")) {
        const avx2::PacketKernel kernel(scene_, *tables_, maxDepth_, shadows_, eps_);
        for (std::size_t i = 0; i < count; i += kBatch)
            kernel.firstHits(&ws.px[i], &ws.py[i], int(std::min<std::size_t>(kBatch, count - i)),
                             cameraSubset, out + i);
        return;
    }
#endif
    const baseline::PacketKernel kernel(scene_, *tables_, maxDepth_, shadows_, eps_);
    for (std::size_t i = 0; i < count; i += kBatch)
        kernel.firstHits(&ws.px[i], &ws.py[i], int(std::min<std::size_t>(kBatch, count - i)),
                         cameraSubset, out + i);
}

void PacketTracer::tracePixels(const int32_t* xs, const int32_t* ys, std::size_t count,
                               const RaySubset& subset, int segmentCapacity, PacketPixel* out,
                               std::vector<TreeSegment>& segments,
                               TraceCounters& counters) const {
    thread_local Workspace ws;
#if defined(RS_PACKET_DISPATCH)
    if (kernel_ == Kernel::Fastest && __builtin_cpu_supports("avx2")) {
        const avx2::PacketKernel kernel(scene_, *tables_, maxDepth_, shadows_, eps_);
        tracePixelsWith(kernel, ws, scene_, xs, ys, count, subset, segmentCapacity, out,
                        segments, counters);
        return;
    }
#endif
    const baseline::PacketKernel kernel(scene_, *tables_, maxDepth_, shadows_, eps_);
    tracePixelsWith(kernel, ws, scene_, xs, ys, count, subset, segmentCapacity, out, segments,
                    counters);
}

void PacketTracer::traceTile(int x0, int y0, int x1, int y1, const RaySubset& subset,
                             std::size_t stride, Color* colors, ObjectId* ids, Vec3* normals,
                             TraceCounters& counters) const {
    thread_local Workspace ws;
#if defined(RS_PACKET_DISPATCH)
    // AVX2 holds eight lanes in one register: measured 2.4x the scalar integrator on the
    // room. The baseline build (two SSE registers per vector) is exact but slower than scalar
    // code, which is why renderImage asks profitable() first.
    if (kernel_ == Kernel::Fastest && __builtin_cpu_supports("avx2")) {
        const avx2::PacketKernel kernel(scene_, *tables_, maxDepth_, shadows_, eps_);
        traceTileWith(kernel, ws, scene_, x0, y0, x1, y1, subset, stride, colors, ids, normals,
                      counters);
        return;
    }
#endif
    const baseline::PacketKernel kernel(scene_, *tables_, maxDepth_, shadows_, eps_);
    traceTileWith(kernel, ws, scene_, x0, y0, x1, y1, subset, stride, colors, ids, normals,
                  counters);
}

}  // namespace rs
