// Building a snapshot from a document and refitting it after moves.
#include "snapshot/compiled_scene.h"

#include <algorithm>
#include <cmath>

#include "core/id_search.h"
#include "texture/texture_store.h"

namespace rs {

namespace {

CompiledMaterial compileMaterial(const Material& m) {
    float cutoff = 0.0f;
    if (m.specular > 0.0f && m.shininess > 0.0f)
        cutoff = std::min(1.0f, std::pow(1e-7f / m.specular, 1.0f / m.shininess));
    return {m.color,        m.diffuse,        m.specular, m.shininess,
            m.reflectivity, m.transparency,   m.ior,      1.0f - m.reflectivity - m.transparency,
            cutoff,         MaterialPattern{}};
}

/// True when the linear part is a rotation times a uniform scale (spheres stay spheres).
bool isSimilarity(const Transform& t) {
    const Vec3 s = glm::abs(t.scale);
    return s.x == s.y && s.y == s.z;
}

Frame makeFrame(const Mat4& worldFromObject) {
    Frame f;
    f.worldFromObject = worldFromObject;
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
        const RectangleShape world =
            RectangleShape::make(Vec3(m * glm::vec4(r->center, 1.0f)), m3 * r->u, m3 * r->v);
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
        if (accel->bounds().empty()) return false;  // no valid triangle
        prim.worldBounds = accel->bounds().transformed(m);
        prim.shape = MeshShape{std::move(accel)};
        prim.hasFrame = true;
        prim.frame = makeFrame(m);
    } else {
        return false;
    }
    return true;
}

/// The planes of `doc` that are shown.
std::shared_ptr<const std::vector<PlanePrimitive>> compilePlanes(const SceneDocument& doc) {
    auto planes = std::make_shared<std::vector<PlanePrimitive>>();
    for (const Object& o : doc.objects)
        if (const auto* plane = std::get_if<PlaneGeometry>(&o.geometry); plane && o.visible)
            planes->push_back({{plane->point, glm::normalize(plane->normal)},
                               materialIndex(doc, o.material),
                               o.id});
    return planes;
}

}  // namespace

CompiledLight compileLight(const Light& l) {
    CompiledLight c{l.position, l.type == LightType::Sphere ? l.radius : 0.0f,
                    l.color * l.intensity, l.id};
    if (l.type == LightType::Directional) {
        c.position = -glm::normalize(l.direction) * kSunDistance;
        c.sun = true;
    } else if (l.type == LightType::Spot) {
        c.spot = true;
        const Vec3 axis = l.target - l.position;
        c.axis = glm::length(axis) > 0.0f ? glm::normalize(axis) : Vec3(0.0f, -1.0f, 0.0f);
        const float radians = float(M_PI) / 180.0f;
        c.cosRadius = std::cos(std::clamp(l.coneRadius, 0.0f, 90.0f) * radians);
        c.cosFalloff =
            std::cos(std::clamp(std::max(l.coneFalloff, l.coneRadius), 0.0f, 90.0f) * radians);
    }
    return c;
}

CompiledScene::CompiledScene(const SceneDocument& doc, const CompiledScene* previous,
                             EngineKind engine)
    : camera_(doc.camera, doc.render.width, doc.render.height), settings_(doc.render) {
    compileLooks(doc);
    for (const Light& l : doc.lights) lights_.push_back(compileLight(l));
    planes_ = compilePlanes(doc);
    auto prims = std::make_shared<std::vector<Primitive>>();
    for (const Object& o : doc.objects) {
        if (!o.visible || std::holds_alternative<PlaneGeometry>(o.geometry)) continue;
        std::shared_ptr<const MeshAccel> accel;
        if (const auto* mesh = std::get_if<MeshGeometry>(&o.geometry))
            accel = findMeshAccel(previous, *mesh);
        Primitive prim;
        if (compileBounded(o, materialIndex(doc, o.material), std::move(accel), prim))
            prims->push_back(std::move(prim));
    }
    primitives_ = std::move(prims);
    computeEpsilon();
    engine_ = buildEngine(engine, geometry(), previous ? previous->engine_.get() : nullptr);
    compilePatterns(doc);
}

SceneGeometry CompiledScene::geometry() const {
    SceneGeometry g;
    g.primitives = primitives_;
    g.planes = planes_;
    for (const CompiledLight& l : lights_) g.lights.push_back({l.position, l.radius});
    g.epsilon = epsilon_;
    return g;
}

void CompiledScene::computeEpsilon() {
    sceneBounds_ = Aabb{};
    for (const Primitive& p : *primitives_) sceneBounds_.expand(p.worldBounds);
    for (const CompiledLight& l : lights_) {
        if (l.sun) continue;  // Far away by construction; the scene's size is what matters.
        sceneBounds_.expand(l.position - Vec3(l.radius));
        sceneBounds_.expand(l.position + Vec3(l.radius));
    }
    for (const PlanePrimitive& p : *planes_) sceneBounds_.expand(p.shape.point);
    sceneBounds_.expand(camera_.origin());
    // Offsets grow with the scene so large scenes do not self-intersect in float precision.
    const float extent = sceneBounds_.empty() ? 1.0f : glm::length(sceneBounds_.extent());
    epsilon_ = std::exp2(std::ceil(std::log2(1e-4f * std::max(1.0f, extent))));
}

CompiledScene CompiledScene::refitted(const SceneDocument& doc,
                                      const std::vector<ObjectId>& moved) const {
    CompiledScene out = *this;
    // Material definitions may have changed (same names, same order): recompile the table.
    out.compileLooks(doc);
    // Planes are few and cheap: recompile them for material changes.
    out.planes_ = compilePlanes(doc);
    auto prims = std::make_shared<std::vector<Primitive>>(*primitives_);
    std::vector<uint32_t> indices;
    for (ObjectId id : moved) {
        const int index = primitiveIndex(id);
        const Object* o = doc.findObject(id);
        if (index < 0 || !o) continue;
        Primitive& prim = (*prims)[std::size_t(index)];
        std::shared_ptr<const MeshAccel> accel;
        if (const auto* m = std::get_if<MeshShape>(&prim.shape)) accel = m->accel;
        compileBounded(*o, materialIndex(doc, o->material), std::move(accel), prim);
        indices.push_back(uint32_t(index));
    }
    out.primitives_ = std::move(prims);
    out.computeEpsilon();
    out.engine_ = engine_->updated(out.geometry(), indices);
    out.compilePatterns(doc);
    return out;
}

void CompiledScene::compileLooks(const SceneDocument& doc) {
    problems_.clear();
    materials_.clear();
    materials_.push_back(compileMaterial(Material{}));
    for (std::size_t i = 0; i < doc.materials.size(); ++i) {
        const Material& m = doc.materials[i];
        CompiledMaterial c = compileMaterial(m);
        MaterialPattern& p = c.pattern;
        if (const auto* checker = std::get_if<CheckerPattern>(&m.pattern)) {
            p.kind = MaterialPattern::Kind::Checker;
            p.even = checker->even, p.odd = checker->odd, p.checkerScale = checker->scale;
        } else if (const auto* image = std::get_if<ImageTexture>(&m.pattern)) {
            p.kind = MaterialPattern::Kind::Image;
            p.scaleU = image->scaleU, p.scaleV = image->scaleV;
            p.offsetU = image->offsetU, p.offsetV = image->offsetV;
            std::string error;
            p.texture = TextureStore::shared().open(image->image.source(), error);
            if (!p.texture)
                problems_.push_back("/materials/" + std::to_string(i) + "/color/texture: " + error);
        }
        materials_.push_back(c);
    }
    environment_ = CompiledEnvironment{};
    if (doc.environment.present()) {
        environment_.present = true;
        environment_.intensity = doc.environment.intensity;
        environment_.rotation = doc.environment.rotation;
        std::string error;
        environment_.texture = TextureStore::shared().open(doc.environment.image.source(), error);
        if (!environment_.texture) problems_.push_back("/environment/file: " + error);
    }
}

void CompiledScene::compilePatterns(const SceneDocument& doc) {
    bool any = false;
    for (const CompiledMaterial& m : materials_)
        any |= m.pattern.kind != MaterialPattern::Kind::None;
    if (!any) {
        if (!patterns_->empty()) patterns_ = std::make_shared<SurfacePatterns>();
        return;
    }
    auto patterns = std::make_shared<SurfacePatterns>();
    patterns->resize(primitives_->size(), planes_->size());
    auto patterned = [&](uint32_t material) {
        return materials_[material].pattern.kind != MaterialPattern::Kind::None;
    };
    for (std::size_t i = 0; i < primitives_->size(); ++i) {
        const Primitive& p = (*primitives_)[i];
        if (!patterned(p.material)) continue;
        if (const Object* o = doc.findObject(p.id))
            patterns->setPrimitive(i, SurfacePatterns::surfaceOf(*o));
    }
    for (std::size_t i = 0; i < planes_->size(); ++i) {
        const PlanePrimitive& p = (*planes_)[i];
        if (!patterned(p.material)) continue;
        if (const Object* o = doc.findObject(p.id))
            patterns->setPlane(i, SurfacePatterns::surfaceOf(*o));
    }
    patterns_ = std::move(patterns);
}

Color CompiledScene::environmentColor(const Vec3& dir, float spread) const {
    if (!environment_.present) return settings_.background;
    if (!environment_.texture) {
        // The loud "missing" pattern over the sky, in the environment's own coordinates.
        const float u = 0.5f + std::atan2(dir.z, dir.x) / (2.0f * float(M_PI));
        const float v = 0.5f + std::asin(std::clamp(dir.y, -1.0f, 1.0f)) / float(M_PI);
        return missingTexture(8.0f * u, 4.0f * (1.0f - v));
    }
    return environment_.intensity * TextureStore::shared().environment(
                                        environment_.texture, dir, environment_.rotation, spread);
}

CompiledScene CompiledScene::withBoxProxy(ObjectId id) const {
    CompiledScene out = *this;
    const int index = primitiveIndex(id);
    if (index >= 0) {
        auto prims = std::make_shared<std::vector<Primitive>>(*primitives_);
        Primitive& prim = (*prims)[std::size_t(index)];
        prim.shape = BoxShape{prim.worldBounds};
        prim.hasFrame = false;
        out.primitives_ = std::move(prims);
        const uint32_t changed[] = {uint32_t(index)};
        out.engine_ = engine_->updated(out.geometry(), changed);
    }
    return out;
}

int CompiledScene::primitiveIndex(ObjectId id) const {
    // Primitives follow the document's object order, which is by id.
    return int(indexById(*primitives_, id, [](const Primitive& p) { return p.id; }));
}

Aabb CompiledScene::objectBounds(ObjectId id) const {
    const int index = primitiveIndex(id);
    return index < 0 ? Aabb{} : (*primitives_)[std::size_t(index)].worldBounds;
}

bool CompiledScene::intersect(const Ray& ray, float tmax, SurfaceHit& hit) const {
    EngineHit h;
    if (!engine_->closestHit(ray, tmax, h)) return false;
    hit.t = h.t;
    hit.n = h.n;
    describe(h.slot, hit.material, hit.id);
    return true;
}

bool CompiledScene::occluded(const Ray& ray, float tmax) const {
    return engine_->anyHit(ray, tmax);
}

}  // namespace rs
