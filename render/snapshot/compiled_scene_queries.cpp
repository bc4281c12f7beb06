// The snapshot's ray queries: planes and spheres four at a time, the BVH for the rest.
#include "snapshot/compiled_scene.h"

#include <cmath>
#include <limits>

namespace rs {

namespace {

/// Tests one bounded shape against a ray given in the shape's own frame.
bool intersectShape(const BoundedShape& shape, const Ray& ray, float tmin, float tmax,
                    ShapeHit& hit) {
    return std::visit(
        [&](const auto& s) -> bool {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, MeshShape>) {
                return s.accel->intersect(ray, tmin, tmax, hit);
            } else {
                return rs::intersect(s, ray, tmin, tmax, hit);
            }
        },
        shape);
}

}  // namespace

bool CompiledScene::intersectPrimitive(const Primitive& p, const Ray& ray, float tmin, float tmax,
                                       ShapeHit& hit) const {
    if (!p.hasFrame) return intersectShape(p.shape, ray, tmin, tmax, hit);
    // Test in the object's frame: t is unchanged because the direction is mapped linearly too.
    const Frame& f = p.frame;
    const Ray local = Ray::make(Vec3(f.objectFromWorld * glm::vec4(ray.origin, 1.0f)),
                                f.dirToObject * ray.dir);
    if (!intersectShape(p.shape, local, tmin, tmax, hit)) return false;
    hit.n = glm::normalize(f.normalToWorld * hit.n);
    return true;
}

// Ray queries: helpers for the four-wide plane and sphere tests.
namespace {

/// Up to this many world spheres (and nothing else bounded) are tested flat, without the BVH
/// (measured: the room's 8 spheres, two SIMD blocks, cost less than the walk over 7 nodes).
constexpr std::size_t kFlatLimit = 16;


/// Distances to four planes, with the operations of intersect(PlaneShape) in the same order, so
/// t is bit-identical. A ray parallel to a plane gets +-inf or NaN here, which the open-range
/// test rejects like the denom == 0 branch there (tmax is never above infinity).
inline Float4 planeDistances(const PlaneBlock4& b, const Ray& ray) {
    const Float4 denom = ray.dir.x * b.nx + ray.dir.y * b.ny + ray.dir.z * b.nz;
    const Float4 num = (b.px - ray.origin.x) * b.nx + (b.py - ray.origin.y) * b.ny +
                       (b.pz - ray.origin.z) * b.nz;
    return num / denom;
}

/// First half of intersect(SphereShape) for four spheres, same operations in the same order;
/// lanes with disc >= 0 are finished one by one with solveRecentredSphere.
struct SpherePrelude {
    Float4 tProj, fx, fy, fz, bHalf, c, disc;
};

inline SpherePrelude spherePrelude(const SphereBlock4& s, const Ray& ray, float a) {
    SpherePrelude p;
    p.tProj = ((s.cx - ray.origin.x) * ray.dir.x + (s.cy - ray.origin.y) * ray.dir.y +
               (s.cz - ray.origin.z) * ray.dir.z) /
              a;
    p.fx = (ray.origin.x - s.cx) + p.tProj * ray.dir.x;
    p.fy = (ray.origin.y - s.cy) + p.tProj * ray.dir.y;
    p.fz = (ray.origin.z - s.cz) + p.tProj * ray.dir.z;
    p.bHalf = p.fx * ray.dir.x + p.fy * ray.dir.y + p.fz * ray.dir.z;
    p.c = (p.fx * p.fx + p.fy * p.fy + p.fz * p.fz) - s.radius2;
    p.disc = p.bHalf * p.bHalf - a * p.c;
    return p;
}

}  // namespace

void CompiledScene::prepareQueries() {
    planeBlocks_.assign((planes_.size() + 3) / 4, PlaneBlock4{});
    for (std::size_t i = 0; i < planes_.size(); ++i) {
        PlaneBlock4& b = planeBlocks_[i / 4];
        const PlaneShape& s = planes_[i].shape;
        const int k = int(i % 4);
        b.px[k] = s.point.x, b.py[k] = s.point.y, b.pz[k] = s.point.z;
        b.nx[k] = s.normal.x, b.ny[k] = s.normal.y, b.nz[k] = s.normal.z;
    }
    // Flat only when every primitive is a world sphere: measured, testing boxes and meshes on
    // every ray (glass-and-mirrors, mesh scenes) is 12-27% slower than the BVH walk.
    sphereBlocks_.clear();
    flat_ = primitives_.size() <= kFlatLimit;
    for (const Primitive& p : primitives_)
        flat_ = flat_ && !p.hasFrame && std::holds_alternative<SphereShape>(p.shape);
    // Light buffers where they pay (measured): with a few world spheres a shadow ray then
    // tests about one shape. With boxes or meshes the BVH's any-hit walk was 7-13% faster
    // than testing a cell's list (soft-shadows, glass-and-mirrors), so those keep it.
    lightBuffers_.clear();
    flatSpheres_.clear();
    if (flat_) {
        std::vector<BoundingSphere> spheres;
        spheres.reserve(primitives_.size());
        for (const Primitive& p : primitives_) {
            const SphereShape& s = std::get<SphereShape>(p.shape);
            spheres.push_back({s.center, s.radius});
            flatSpheres_.push_back(s);
        }
        std::vector<BufferPlane> planes;
        planes.reserve(planes_.size());
        for (const PlanePrimitive& p : planes_) planes.push_back({p.shape.point, p.shape.normal});
        for (const CompiledLight& l : lights_)
            lightBuffers_.emplace_back(l.position, l.radius + 4.0f * epsilon_, spheres, planes);
    }

    if (!flat_) return;
    for (std::size_t i = 0; i < primitives_.size(); ++i) {
        const SphereShape& s = std::get<SphereShape>(primitives_[i].shape);
        const int k = int(i % 4);
        if (k == 0) {
            SphereBlock4& b = sphereBlocks_.emplace_back();
            b.radius2 = Float4{} + std::numeric_limits<float>::quiet_NaN();
        }
        SphereBlock4& b = sphereBlocks_.back();
        b.cx[k] = s.center.x, b.cy[k] = s.center.y, b.cz[k] = s.center.z;
        b.radius2[k] = s.radius * s.radius;
        b.radius[k] = s.radius;
        b.prim[k] = uint32_t(i);
    }
}

bool CompiledScene::intersect(const Ray& ray, float tmin, float tmax, SurfaceHit& hit) const {
    return intersect(ray, tmin, tmax, hit, nullptr);
}

bool CompiledScene::intersect(const Ray& ray, float tmin, float tmax, SurfaceHit& hit,
                              const RaySubset* subset) const {
    if (subset && !subset->valid) subset = nullptr;
    const PlaneBlock4* planeBlocks = subset ? subset->planes : planeBlocks_.data();
    const std::size_t planeBlockCount = subset ? std::size_t(subset->planeBlocks) : planeBlocks_.size();
    // Planes first: in a closed room almost every ray hits one, and its t culls the rest.
    // Scanning in order with a strict < keeps the first of equally near planes, as before.
    std::size_t nearestLane = ~std::size_t(0);
    for (std::size_t b = 0; b < planeBlockCount; ++b) {
        const Float4 t = planeDistances(planeBlocks[b], ray);
        for (int k = 0; k < 4; ++k) {
            if (t[k] > tmin && t[k] < tmax) {
                tmax = t[k];
                nearestLane = 4 * b + std::size_t(k);
            }
        }
    }
    bool found = false;
    if (nearestLane != ~std::size_t(0)) {
        const PlanePrimitive& p = planes_[subset ? subset->planeIndex[nearestLane] : nearestLane];
        hit = {tmax, p.shape.normal, p.material, p.id};
        found = true;
    }
    if (flat_) {
        return subset ? intersectFlat(ray, tmin, tmax, hit, found, subset->spheres,
                                      std::size_t(subset->sphereBlocks))
                      : intersectFlat(ray, tmin, tmax, hit, found, sphereBlocks_.data(),
                                      sphereBlocks_.size());
    }
    ShapeHit sh;
    found |= bvh_.closestHit(ray, tmin, tmax, [&](uint32_t index, float& tmaxRef) {
        const Primitive& p = primitives_[index];
        if (!intersectPrimitive(p, ray, tmin, tmaxRef, sh)) return false;
        tmaxRef = sh.t;
        hit = {sh.t, sh.n, p.material, p.id};
        return true;
    });
    return found;
}

void CompiledScene::cull(const Vec3& origin, const Vec3& axis, float halfAngle,
                         RaySubset& out) const {
    out = RaySubset{};
    if (planes_.size() > std::size_t(4 * RaySubset::kMaxPlaneBlocks) ||
        (flat_ && primitives_.size() > std::size_t(4 * RaySubset::kMaxSphereBlocks)))
        return;
    // Slack far above the rounding of the exact tests: shapes this close to the cone stay in.
    constexpr float kAngleMargin = 1e-3f;
    const float angle = halfAngle + kAngleMargin;
    const float sinAngle = std::sin(std::min(angle, 0.5f * kPi));
    const float scale = std::max(1.0f, glm::length(sceneBounds_.extent()));
    int lanes = 0;
    for (std::size_t i = 0; i < planes_.size(); ++i) {
        // Hit at t > 0 where d . n has the sign of (point - origin) . n: some d of the cone
        // does that when the axis is less than 90 degrees plus the angle from s n.
        const PlaneShape& s = planes_[i].shape;
        const float num = glm::dot(s.point - origin, s.normal);
        const bool keep = std::abs(num) <= 1e-5f * scale || angle >= 0.5f * kPi ||
                          glm::dot(axis, num > 0.0f ? s.normal : -s.normal) > -sinAngle;
        if (!keep) continue;
        PlaneBlock4& b = out.planes[lanes / 4];
        if (lanes % 4 == 0) b = PlaneBlock4{};
        const int k = lanes % 4;
        b.px[k] = s.point.x, b.py[k] = s.point.y, b.pz[k] = s.point.z;
        b.nx[k] = s.normal.x, b.ny[k] = s.normal.y, b.nz[k] = s.normal.z;
        out.planeIndex[lanes++] = uint32_t(i);
    }
    out.planeBlocks = (lanes + 3) / 4;
    if (flat_) {
        int count = 0;
        const float cosAngle = std::cos(std::min(angle, kPi));
        for (const SphereBlock4& block : sphereBlocks_) {
            for (int k = 0; k < 4; ++k) {
                if (std::isnan(block.radius2[k])) continue;  // padding
                const Vec3 c(block.cx[k], block.cy[k], block.cz[k]);
                const Vec3 d = c - origin;
                const float dist = glm::length(d);
                const float r = block.radius[k] * (1.0f + 1e-4f) + 1e-5f * scale;
                bool keep = !(dist > r) || angle >= 0.5f * kPi;
                if (!keep) {
                    // Overlap of the cone and the sphere's cone, as in the light buffer.
                    const float sinS = r / dist, cosS = std::sqrt(1.0f - sinS * sinS);
                    keep = glm::dot(axis, d / dist) >= cosS * cosAngle - sinS * std::sin(angle);
                }
                if (!keep) continue;
                SphereBlock4& b = out.spheres[count / 4];
                const int lane = count % 4;
                if (lane == 0) {
                    b = SphereBlock4{};
                    b.radius2 = Float4{} + std::numeric_limits<float>::quiet_NaN();
                }
                b.cx[lane] = block.cx[k], b.cy[lane] = block.cy[k], b.cz[lane] = block.cz[k];
                b.radius2[lane] = block.radius2[k];
                b.radius[lane] = block.radius[k];
                b.prim[lane] = block.prim[k];
                ++count;
            }
        }
        out.sphereBlocks = (count + 3) / 4;
    }
    out.valid = true;
}

bool CompiledScene::intersectFlat(const Ray& ray, float tmin, float tmax, SurfaceHit& hit,
                                  bool found, const SphereBlock4* blocks,
                                  std::size_t count) const {
    // The sphere normal is only worked out for the winner, once, after all tests.
    const SphereBlock4* best = nullptr;
    int bestLane = 0;
    float bestOffset = 0.0f;
    const float a = glm::dot(ray.dir, ray.dir);
    for (std::size_t i = 0; i < count; ++i) {
        const SphereBlock4& b = blocks[i];
        const SpherePrelude p = spherePrelude(b, ray, a);
        for (int k = 0; k < 4; ++k) {
            float t, offset;
            if (p.disc[k] >= 0.0f &&
                solveRecentredSphere(a, p.tProj[k], p.bHalf[k], p.c[k], tmin, tmax, t, offset)) {
                tmax = t;
                best = &b;
                bestLane = k;
                bestOffset = offset;
            }
        }
    }
    if (best) {
        // Recomputed with the operations of intersect(SphereShape), so n is bit-identical.
        const Primitive& p = primitives_[best->prim[bestLane]];
        const SphereShape& s = std::get<SphereShape>(p.shape);
        const float tProj = glm::dot(s.center - ray.origin, ray.dir) / a;
        const Vec3 f = (ray.origin - s.center) + tProj * ray.dir;
        hit = {tmax, divide(f + bestOffset * ray.dir, s.radius), p.material, p.id};
        found = true;
    }
    return found;
}

bool CompiledScene::occluded(const Ray& ray, float tmin, float tmax) const {
    // Bounded objects first: a shadow ray toward a light inside a room never reaches a wall.
    if (flat_) {
        if (occludedFlat(ray, tmin, tmax)) return true;
    } else {
        ShapeHit sh;
        if (bvh_.anyHit(ray, tmin, tmax, [&](uint32_t index) {
                return intersectPrimitive(primitives_[index], ray, tmin, tmax, sh);
            }))
            return true;
    }
    return occludedByPlanes(ray, tmin, tmax);
}

bool CompiledScene::occludedToLight(std::size_t light, const Vec3& origin, const Vec3& dir,
                                    float tmin, float tmax) const {
    // Buffers exist only for flat scenes: the candidates are world spheres and planes, tested
    // with the operations of intersect(SphereShape) and intersect(PlaneShape) up to the
    // answer, so it is the same bit for bit (and no Ray with reciprocals is needed).
    if (light >= lightBuffers_.size()) return occluded(Ray::make(origin, dir), tmin, tmax);
    const float a = glm::dot(dir, dir);
    const int hit = lightBuffers_[light].anyHit(origin, [&](uint32_t item) {
        if (item & LightBuffer::kPlaneBit) {
            const PlaneShape& s = planes_[item & ~LightBuffer::kPlaneBit].shape;
            const float denom = glm::dot(dir, s.normal);
            const float num = glm::dot(s.point - origin, s.normal);
            // Opposite signs make t negative (or NaN): a miss for tmin >= 0, without dividing.
            if (std::signbit(num) != std::signbit(denom) || denom == 0.0f) return false;
            const float t = num / denom;
            return t > tmin && t < tmax;
        }
        const SphereShape& s = flatSpheres_[item];
        const float tProj = glm::dot(s.center - origin, dir) / a;
        const Vec3 f = (origin - s.center) + tProj * dir;
        const float bHalf = glm::dot(f, dir);
        const float c = glm::dot(f, f) - s.radius * s.radius;
        float t, offset;
        return solveRecentredSphere(a, tProj, bHalf, c, tmin, tmax, t, offset);
    });
    return hit < 0 ? occluded(Ray::make(origin, dir), tmin, tmax) : hit == 1;
}

bool CompiledScene::occludedByPlanes(const Ray& ray, float tmin, float tmax) const {
    for (const PlaneBlock4& b : planeBlocks_) {
        const Float4 t = planeDistances(b, ray);
        for (int k = 0; k < 4; ++k)
            if (t[k] > tmin && t[k] < tmax) return true;
    }
    return false;
}

bool CompiledScene::occludedFlat(const Ray& ray, float tmin, float tmax) const {
    const float a = glm::dot(ray.dir, ray.dir);
    for (const SphereBlock4& b : sphereBlocks_) {
        const SpherePrelude p = spherePrelude(b, ray, a);
        for (int k = 0; k < 4; ++k) {
            float t, offset;
            if (p.disc[k] >= 0.0f &&
                solveRecentredSphere(a, p.tProj[k], p.bHalf[k], p.c[k], tmin, tmax, t, offset))
                return true;
        }
    }
    return false;
}

}  // namespace rs
