// Building a snapshot from a document, refitting it after moves, and the scene ray queries.
#include "snapshot/compiled_scene.h"

#include <cmath>

namespace rs {

namespace {

CompiledMaterial compileMaterial(const Material& m) {
    float cutoff = 0.0f;
    if (m.specular > 0.0f && m.shininess > 0.0f)
        cutoff = std::min(1.0f, std::pow(1e-7f / m.specular, 1.0f / m.shininess));
    return {m.color,        m.diffuse, m.specular, m.shininess, m.reflectivity,
            m.transparency, m.ior,     1.0f - m.reflectivity - m.transparency, cutoff};
}

/// True when the linear part is a rotation times a uniform scale (spheres stay spheres).
bool isSimilarity(const Transform& t) {
    const Vec3 s = glm::abs(t.scale);
    return s.x == s.y && s.y == s.z;
}

Frame makeFrame(const Mat4& worldFromObject) {
    Frame f;
    f.objectFromWorld = glm::inverse(worldFromObject);
    f.dirToObject = Mat3(f.objectFromWorld);
    f.normalToWorld = glm::transpose(Mat3(f.objectFromWorld));
    return f;
}

uint32_t materialIndex(const SceneDocument& doc, const std::string& name) {
    for (std::size_t i = 0; i < doc.materials.size(); ++i)
        if (doc.materials[i].name == name) return uint32_t(i + 1);
    return 0;  // The built-in grey diffuse.
}

/// Mesh BVH of `previous` for the same mesh data, so edits never rebuild a mesh's BVH.
std::shared_ptr<const MeshAccel> findMeshAccel(const CompiledScene* previous,
                                               const MeshGeometry& mesh) {
    if (!previous) return nullptr;
    for (const Primitive& p : previous->primitives())
        if (const auto* m = std::get_if<MeshShape>(&p.shape))
            if (m->accel->data() == mesh.data && m->accel->smooth() == mesh.smoothNormals)
                return m->accel;
    return nullptr;
}

/// Render form of one bounded object; false for planes and meshes without triangles.
bool compileBounded(const Object& o, uint32_t material, std::shared_ptr<const MeshAccel> accel,
                    Primitive& prim) {
    const Mat4 m = o.transform.matrix();
    const Mat3 m3(m);
    prim = Primitive{};
    prim.material = material;
    prim.id = o.id;
    if (const auto* s = std::get_if<SphereGeometry>(&o.geometry)) {
        if (isSimilarity(o.transform)) {
            const SphereShape world{Vec3(m * glm::vec4(s->center, 1.0f)),
                                    s->radius * std::abs(o.transform.scale.x)};
            prim.shape = world;
            prim.worldBounds = bounds(world);
        } else {
            const SphereShape local{s->center, s->radius};
            prim.shape = local;
            prim.hasFrame = true;
            prim.frame = makeFrame(m);
            prim.worldBounds = bounds(local).transformed(m);
        }
    } else if (const auto* r = std::get_if<RectangleGeometry>(&o.geometry)) {
        // An affine map keeps a parallelogram a parallelogram: store it in world space.
        const RectangleShape world = RectangleShape::make(Vec3(m * glm::vec4(r->center, 1.0f)),
                                                          m3 * r->u, m3 * r->v);
        prim.shape = world;
        prim.worldBounds = bounds(world);
    } else if (const auto* b = std::get_if<BoxGeometry>(&o.geometry)) {
        const BoxShape local{Aabb{b->min, b->max}};
        if (o.transform.rotate == Vec3(0.0f)) {
            // Scale and translation keep the box axis-aligned: store it in world space.
            const BoxShape world{local.box.transformed(m)};
            prim.shape = world;
            prim.worldBounds = world.box;
        } else {
            prim.shape = local;
            prim.hasFrame = true;
            prim.frame = makeFrame(m);
            prim.worldBounds = local.box.transformed(m);
        }
    } else if (const auto* mesh = std::get_if<MeshGeometry>(&o.geometry)) {
        if (!mesh->data || mesh->data->triangleCount() == 0) return false;
        if (!accel) accel = std::make_shared<const MeshAccel>(mesh->data, mesh->smoothNormals);
        prim.worldBounds = accel->bounds().transformed(m);
        prim.shape = MeshShape{std::move(accel)};
        prim.hasFrame = true;
        prim.frame = makeFrame(m);
    } else {
        return false;
    }
    return true;
}

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

CompiledScene::CompiledScene(const SceneDocument& doc, const CompiledScene* previous)
    : camera_(doc.camera, doc.render.width, doc.render.height), settings_(doc.render) {
    materials_.push_back(compileMaterial(Material{}));
    for (const Material& m : doc.materials) materials_.push_back(compileMaterial(m));
    for (const Light& l : doc.lights) {
        const float radius = l.type == LightType::Sphere ? l.radius : 0.0f;
        lights_.push_back({l.position, radius, l.color * l.intensity, l.id});
    }
    for (const Object& o : doc.objects) {
        if (!o.visible) continue;
        const uint32_t mat = materialIndex(doc, o.material);
        if (const auto* plane = std::get_if<PlaneGeometry>(&o.geometry)) {
            planes_.push_back({{plane->point, glm::normalize(plane->normal)}, mat, o.id});
            continue;
        }
        std::shared_ptr<const MeshAccel> accel;
        if (const auto* mesh = std::get_if<MeshGeometry>(&o.geometry))
            accel = findMeshAccel(previous, *mesh);
        Primitive prim;
        if (compileBounded(o, mat, std::move(accel), prim)) primitives_.push_back(std::move(prim));
    }
    std::vector<Aabb> boxes;
    boxes.reserve(primitives_.size());
    for (const Primitive& p : primitives_) boxes.push_back(p.worldBounds);
    bvh_.build(boxes, 2);
    computeEpsilon();
    prepareQueries();
}

void CompiledScene::computeEpsilon() {
    sceneBounds_ = Aabb{};
    for (const Primitive& p : primitives_) sceneBounds_.expand(p.worldBounds);
    for (const CompiledLight& l : lights_) {
        sceneBounds_.expand(l.position - Vec3(l.radius));
        sceneBounds_.expand(l.position + Vec3(l.radius));
    }
    for (const PlanePrimitive& p : planes_) sceneBounds_.expand(p.shape.point);
    sceneBounds_.expand(camera_.origin());
    // Offsets grow with the scene so large scenes do not self-intersect in float precision.
    const float extent = sceneBounds_.empty() ? 1.0f : glm::length(sceneBounds_.extent());
    epsilon_ = std::exp2(std::ceil(std::log2(1e-4f * std::max(1.0f, extent))));
}

CompiledScene CompiledScene::refitted(const SceneDocument& doc,
                                      const std::vector<ObjectId>& moved) const {
    CompiledScene out = *this;
    // Material definitions may have changed (same names, same order): recompile the table.
    out.materials_.resize(1);
    for (const Material& m : doc.materials) out.materials_.push_back(compileMaterial(m));
    // Planes are few and cheap: recompile them for material changes.
    out.planes_.clear();
    for (const Object& o : doc.objects)
        if (const auto* plane = std::get_if<PlaneGeometry>(&o.geometry); plane && o.visible)
            out.planes_.push_back({{plane->point, glm::normalize(plane->normal)},
                                   materialIndex(doc, o.material), o.id});
    for (ObjectId id : moved) {
        const int index = primitiveIndex(id);
        const Object* o = doc.findObject(id);
        if (index < 0 || !o) continue;
        Primitive& prim = out.primitives_[std::size_t(index)];
        std::shared_ptr<const MeshAccel> accel;
        if (const auto* m = std::get_if<MeshShape>(&prim.shape)) accel = m->accel;
        compileBounded(*o, materialIndex(doc, o->material), std::move(accel), prim);
        out.bvh_.refitPrimitive(uint32_t(index), prim.worldBounds);
    }
    out.computeEpsilon();
    out.prepareQueries();
    return out;
}

CompiledScene CompiledScene::withBoxProxy(ObjectId id) const {
    CompiledScene out = *this;
    const int index = primitiveIndex(id);
    if (index >= 0) {
        Primitive& prim = out.primitives_[std::size_t(index)];
        prim.shape = BoxShape{prim.worldBounds};
        prim.hasFrame = false;
    }
    out.prepareQueries();
    return out;
}

int CompiledScene::primitiveIndex(ObjectId id) const {
    for (std::size_t i = 0; i < primitives_.size(); ++i)
        if (primitives_[i].id == id) return int(i);
    return -1;
}

Aabb CompiledScene::objectBounds(ObjectId id) const {
    const int index = primitiveIndex(id);
    return index < 0 ? Aabb{} : primitives_[std::size_t(index)].worldBounds;
}

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
    // Planes first: in a closed room almost every ray hits one, and its t culls the rest.
    // Scanning in order with a strict < keeps the first of equally near planes, as before.
    std::size_t nearestPlane = planes_.size();
    for (std::size_t b = 0; b < planeBlocks_.size(); ++b) {
        const Float4 t = planeDistances(planeBlocks_[b], ray);
        for (int k = 0; k < 4; ++k) {
            if (t[k] > tmin && t[k] < tmax) {
                tmax = t[k];
                nearestPlane = 4 * b + std::size_t(k);
            }
        }
    }
    bool found = false;
    if (nearestPlane < planes_.size()) {
        const PlanePrimitive& p = planes_[nearestPlane];
        hit = {tmax, p.shape.normal, p.material, p.id};
        found = true;
    }
    if (flat_) return intersectFlat(ray, tmin, tmax, hit, found);
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

bool CompiledScene::intersectFlat(const Ray& ray, float tmin, float tmax, SurfaceHit& hit,
                                  bool found) const {
    // The sphere normal is only worked out for the winner, once, after all tests.
    const SphereBlock4* best = nullptr;
    int bestLane = 0;
    float bestOffset = 0.0f;
    const float a = glm::dot(ray.dir, ray.dir);
    for (const SphereBlock4& b : sphereBlocks_) {
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
        hit = {tmax, (f + bestOffset * ray.dir) / s.radius, p.material, p.id};
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
