// Building a snapshot from a document and refitting it after moves.
#include "snapshot/compiled_scene.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/id_search.h"
#include "scene/mesh_parts.h"
#include "scene/shading_rules.h"
#include "texture/texture_store.h"

namespace rs {

namespace {

CompiledMaterial compileMaterial(const Material& m) {
    return {m.color,
            m.diffuse,
            m.specular,
            m.shininess,
            m.reflectivity,
            m.transparency,
            m.ior,
            1.0f - m.reflectivity - m.transparency,
            highlightCutoff(m.specular, m.shininess),
            MaterialPattern{}};
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

/// The mesh BVHs of a previous snapshot by their mesh data, so edits never rebuild one. The
/// map is made on the first lookup: a document without meshes never walks the snapshot.
class PreviousMeshes {
public:
    explicit PreviousMeshes(const CompiledScene* previous) : previous_(previous) {}
    std::shared_ptr<const MeshAccel> find(const std::shared_ptr<const MeshData>& data,
                                          bool smooth) {
        if (previous_) {
            for (const Primitive& p : previous_->primitives())
                if (const auto* m = std::get_if<MeshShape>(&p.shape))
                    accels_.emplace(std::pair(m->accel->data().get(), m->accel->smooth()),
                                    m->accel);
            previous_ = nullptr;
        }
        const auto it = accels_.find(std::pair(data.get(), smooth));
        return it == accels_.end() || it->second->data() != data ? nullptr : it->second;
    }

private:
    const CompiledScene* previous_;
    std::map<std::pair<const MeshData*, bool>, std::shared_ptr<const MeshAccel>> accels_;
};

/// What one object is traced as: one surface, or for a mesh with part materials one per part
/// (its triangles and the material name), each a primitive of its own.
struct ObjectSurface {
    std::shared_ptr<const MeshData> mesh;  ///< A part's triangles; null: the object's shape.
    const std::string* material;
};

std::vector<ObjectSurface> surfacesOf(const Object& o) {
    const auto* mesh = std::get_if<MeshGeometry>(&o.geometry);
    if (!mesh || mesh->partMaterials.empty() || !mesh->data || mesh->data->parts.empty())
        return {{nullptr, &o.material}};
    const std::vector<MeshPart>& parts = mesh->data->parts;
    if (parts.size() == 1) return {{nullptr, &partMaterial(o, parts[0].material)}};
    std::vector<ObjectSurface> surfaces;
    const auto meshes = meshPartsOf(mesh->data);
    for (std::size_t i = 0; i < parts.size(); ++i)
        surfaces.push_back({meshes[i], &partMaterial(o, parts[i].material)});
    return surfaces;
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
    PreviousMeshes meshes(previous);
    for (const Object& o : doc.objects) {
        if (!o.visible || std::holds_alternative<PlaneGeometry>(o.geometry)) continue;
        const auto* mesh = std::get_if<MeshGeometry>(&o.geometry);
        for (const ObjectSurface& surface : surfacesOf(o)) {
            std::shared_ptr<const MeshAccel> accel;
            if (mesh) {
                const auto& data = surface.mesh ? surface.mesh : mesh->data;
                accel = meshes.find(data, mesh->smoothNormals);
                if (!accel && surface.mesh)
                    accel = std::make_shared<const MeshAccel>(data, mesh->smoothNormals);
            }
            Primitive prim;
            if (compileBounded(o, materialIndex(doc, *surface.material), std::move(accel), prim))
                prims->push_back(std::move(prim));
        }
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
        const auto [first, end] = primitiveRange(id);
        const Object* o = doc.findObject(id);
        if (first == end || !o) continue;
        // The same surfaces as when compiled (same mesh and part materials, or a rebuild).
        const std::vector<ObjectSurface> surfaces = surfacesOf(*o);
        for (std::size_t index = first; index < end; ++index) {
            Primitive& prim = (*prims)[index];
            std::shared_ptr<const MeshAccel> accel;
            if (const auto* m = std::get_if<MeshShape>(&prim.shape)) accel = m->accel;
            const std::string& material =
                *surfaces[std::min(index - first, surfaces.size() - 1)].material;
            compileBounded(*o, materialIndex(doc, material), std::move(accel), prim);
            indices.push_back(uint32_t(index));
        }
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
        const auto* mesh = std::get_if<MeshShape>(&p.shape);
        if (const Object* o = doc.findObject(p.id))
            patterns->setPrimitive(
                i, SurfacePatterns::surfaceOf(*o, mesh ? mesh->accel->data() : nullptr));
    }
    for (std::size_t i = 0; i < planes_->size(); ++i) {
        const PlanePrimitive& p = (*planes_)[i];
        if (!patterned(p.material)) continue;
        if (const Object* o = doc.findObject(p.id))
            patterns->setPlane(i, SurfacePatterns::surfaceOf(*o, nullptr));
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

void CompiledScene::environmentColors(std::size_t count, const Directions& dirs, float spread,
                                      EnvironmentSpot* spots, Color* out) const {
    if (!environment_.present || !environment_.texture) {
        for (std::size_t i = 0; i < count; ++i)
            out[i] = environmentColor(Vec3(dirs.x[i], dirs.y[i], dirs.z[i]), spread);
        return;
    }
    environmentSpots(count, dirs, environment_.rotation, spread, spots);
    TextureStore::shared().environmentAt(environment_.texture, count, spots, out);
    for (std::size_t i = 0; i < count; ++i) out[i] = environment_.intensity * out[i];
}

CompiledScene CompiledScene::withBoxProxy(ObjectId id) const {
    CompiledScene out = *this;
    const auto [first, end] = primitiveRange(id);
    if (first != end) {
        auto prims = std::make_shared<std::vector<Primitive>>(*primitives_);
        std::vector<uint32_t> changed;
        for (std::size_t index = first; index < end; ++index) {
            Primitive& prim = (*prims)[index];
            prim.shape = BoxShape{prim.worldBounds};
            prim.hasFrame = false;
            changed.push_back(uint32_t(index));
        }
        out.primitives_ = std::move(prims);
        out.engine_ = engine_->updated(out.geometry(), changed);
    }
    return out;
}

int CompiledScene::primitiveIndex(ObjectId id) const {
    // Primitives follow the document's object order, which is by id.
    return int(indexById(*primitives_, id, [](const Primitive& p) { return p.id; }));
}

std::pair<std::size_t, std::size_t> CompiledScene::primitiveRange(ObjectId id) const {
    const int first = primitiveIndex(id);
    if (first < 0) return {0, 0};
    std::size_t end = std::size_t(first) + 1;
    while (end < primitives_->size() && (*primitives_)[end].id == id) ++end;
    return {std::size_t(first), end};
}

Aabb CompiledScene::objectBounds(ObjectId id) const {
    const auto [first, end] = primitiveRange(id);
    Aabb box;
    for (std::size_t index = first; index < end; ++index)
        box.expand((*primitives_)[index].worldBounds);
    return box;
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
