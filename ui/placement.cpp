// Placement of new objects by a ray cast through the view camera; see placement.h.
#include "placement.h"

#include <algorithm>
#include <cmath>

#include "scene/parameters.h"
#include "scene_edits.h"
#include "snapshot/compiled_scene.h"
#include "transform_edits.h"

namespace rs::ui {

namespace {

/// Share of the distance to the surface a new light stays short of it.
constexpr float kLightClearance = 0.2f;

/// Half the depth of `b` along unit `n`: how far its centre must stand off a surface.
float halfDepth(const Aabb& b, const Vec3& n) {
    const Vec3 e = b.extent();
    return 0.5f * (std::abs(e.x * n.x) + std::abs(e.y * n.y) + std::abs(e.z * n.z));
}

float twoSignificantDigits(float x) {
    const float magnitude = std::pow(10.0f, std::floor(std::log10(x)) - 1.0f);
    return std::round(x / magnitude) * magnitude;
}

}  // namespace

Placement placeAlong(const CompiledScene* scene, const Ray& ray, float fallback) {
    Placement p;
    const float len = glm::length(ray.dir);
    p.viewDir = len > 1e-12f ? ray.dir / len : Vec3(0.0f, 0.0f, -1.0f);
    p.normal = -p.viewDir;
    p.distance = fallback;
    SurfaceHit hit;
    const Ray unit = Ray::make(ray.origin, p.viewDir);
    if (scene && scene->intersect(unit, kInfinity, hit) && std::isfinite(hit.t)) {
        p.distance = hit.t;
        p.onSurface = true;
        p.normal = glm::dot(hit.n, p.viewDir) > 0.0f ? -hit.n : hit.n;
    }
    p.point = ray.origin + p.viewDir * p.distance;
    return p;
}

float fallbackDistance(const Camera& view) {
    const float d = glm::length(view.target - view.position);
    return d > 1e-6f ? std::min(d, kMaxFallbackDistance) : kMaxFallbackDistance;
}

void restOn(SceneDocument& doc, ObjectId id, const Placement& at) {
    if (Light* l = doc.findLight(id)) {
        l->position = at.point - at.viewDir * (at.distance * kLightClearance);
        return;
    }
    Object* o = doc.findObject(id);
    if (!o) return;
    if (auto* plane = std::get_if<PlaneGeometry>(&o->geometry)) {
        plane->point = at.point;
        return;
    }
    const Aabb b = worldBounds(doc, id);
    if (b.empty()) return;
    moveBy(doc, id, at.point + at.normal * halfDepth(b, at.normal) - b.center());
}

bool snapToFloor(SceneDocument& doc, ObjectId id, const CompiledScene* scene, const Vec3& up) {
    const Aabb b = worldBounds(doc, id);
    if (!scene || b.empty()) return false;
    SurfaceHit hit;
    if (!scene->intersect(Ray::make(b.center(), -up), kInfinity, hit) || !std::isfinite(hit.t))
        return false;
    moveBy(doc, id, -up * (hit.t - halfDepth(b, up)));
    return true;
}

float fitScale(const Aabb& bounds, const Camera& view, float distance) {
    if (bounds.empty()) return 1.0f;
    const float size = glm::length(bounds.extent());
    const float visible = view.projection == Projection::Orthographic
                              ? view.orthoHeight
                              : 2.0f * distance * std::tan(glm::radians(view.fovY) * 0.5f);
    if (!(size > 0.0f) || !(visible > 0.0f) || !std::isfinite(size / visible)) return 1.0f;
    const float share = size / visible;
    if (share >= kMinViewShare && share <= kMaxViewShare) return 1.0f;
    // Within what the Transform's Scale field accepts, so the factor stays editable there.
    const ParamDescriptor* range = findParameter(ParamKind::Transform, "scale");
    const float factor = twoSignificantDigits(kFitViewShare / share);
    return range ? std::clamp(factor, float(range->softMin), float(range->softMax)) : factor;
}

void anchorSunGlyphs(SceneDocument& doc) {
    Aabb bounds;
    for (const Object& o : doc.objects) bounds.expand(worldBounds(doc, o.id));
    const Vec3 centre = bounds.empty() ? Vec3(0.0f) : bounds.center();
    const float radius = bounds.empty() ? 0.0f : 0.5f * glm::length(bounds.extent());
    for (Light& l : doc.lights) {
        if (l.type != LightType::Directional || l.position != Vec3(0.0f)) continue;
        const float length = glm::length(l.direction);
        const Vec3 toward = length > 0.0f ? l.direction / length : Vec3(0.0f, -1.0f, 0.0f);
        l.position = centre - toward * (radius + 1.0f);
    }
}

}  // namespace rs::ui
