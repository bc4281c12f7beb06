// Placement of new objects by a ray cast through the view camera; see placement.h.
#include "document/placement.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "document/scene_edits.h"
#include "document/transform_edits.h"
#include "scene/parameters.h"
#include "snapshot/compiled_scene.h"

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

namespace {

/// The first surface from `from` along unit `dir`, or nullopt.
std::optional<float> surfaceAlong(const CompiledScene* scene, const Vec3& from, const Vec3& dir) {
    SurfaceHit hit;
    if (!scene || !scene->intersect(Ray::make(from, dir), kInfinity, hit) || !std::isfinite(hit.t))
        return std::nullopt;
    return hit.t;
}

bool overlapsAny(const SceneDocument& doc, ObjectId id, const Aabb& b) {
    for (const Object& o : doc.objects) {
        if (o.id == id || !o.visible) continue;
        const Aabb other = worldBounds(o);
        if (!other.empty() && other.overlaps(b)) return true;
    }
    return false;
}

/// Whether every corner of `b` lies inside the view's frustum (perspective; an orthographic
/// view sees whatever is in front).
bool inSight(const Aabb& b, const Camera& view, float aspect) {
    const Vec3 forward = glm::normalize(view.target - view.position);
    const Vec3 right = glm::normalize(glm::cross(forward, view.up));
    const Vec3 up = glm::cross(right, forward);
    const float tanY = std::tan(glm::radians(view.fovY) * 0.5f), tanX = tanY * aspect;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 c((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                     (corner & 4) ? b.max.z : b.min.z);
        const Vec3 d = c - view.position;
        const float z = glm::dot(d, forward);
        if (!(z > 0.0f)) return false;
        if (view.projection == Projection::Orthographic) continue;
        if (std::abs(glm::dot(d, right)) > z * tanX || std::abs(glm::dot(d, up)) > z * tanY)
            return false;
    }
    return true;
}

/// Whether something of `scene` lies between `eye` and the centre of `b` (short of b).
bool hidden(const CompiledScene* scene, const Vec3& eye, const Aabb& b) {
    const Vec3 to = b.center() - eye;
    const float distance = glm::length(to);
    if (!(distance > 0.0f)) return false;
    const auto blocked = surfaceAlong(scene, eye, to / distance);
    return blocked && *blocked < distance - 0.5f * glm::length(b.extent());
}

}  // namespace

Vec3 placeInView(SceneDocument& doc, ObjectId id, const CompiledScene* scene, const Camera& view,
                 const Vec3& up, float aspect) {
    const Vec3 toTarget = view.target - view.position;
    const Vec3 dir = glm::length(toTarget) > 1e-6f ? glm::normalize(toTarget) : Vec3(0, 0, -1);
    float distance = fallbackDistance(view);
    if (const auto ahead = surfaceAlong(scene, view.position, dir))
        distance = std::min(distance, 0.5f * *ahead);
    const Vec3 front = view.position + dir * distance;
    const auto below = surfaceAlong(scene, front, -up);
    const Vec3 ground = below ? front - up * *below : front;

    if (Light* l = doc.findLight(id)) {
        const auto above = surfaceAlong(scene, ground + up * 1e-3f, up);
        const float lift = above ? *above / 3.0f : distance / 3.0f;
        l->position = ground + up * lift;
        return ground;
    }
    Object* o = doc.findObject(id);
    if (!o) return ground;
    if (auto* plane = std::get_if<PlaneGeometry>(&o->geometry)) {
        float lowest = kInfinity;
        for (const Object& other : doc.objects) {
            const Aabb b = other.id == id ? Aabb{} : worldBounds(other);
            if (b.empty()) continue;
            for (int corner = 0; corner < 8; ++corner) {
                const Vec3 c((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                             (corner & 4) ? b.max.z : b.min.z);
                lowest = std::min(lowest, glm::dot(c, up));
            }
        }
        plane->normal = up;
        plane->point =
            std::isfinite(lowest) ? ground + up * (lowest - glm::dot(ground, up)) : ground;
        return plane->point;
    }
    const Aabb start = worldBounds(doc, id);
    if (start.empty()) return ground;
    // Across the view (right, left, twice as far right, ...) by a bit more than its width;
    // then the same a step further out (a big import on the floor near the view shows only
    // its top), never past most of the way to the surface ahead.
    const Vec3 across = glm::length(glm::cross(dir, up)) > 1e-6f
                            ? glm::normalize(glm::cross(dir, up))
                            : Vec3(1.0f, 0.0f, 0.0f);
    const float stride = 1.25f * 2.0f * halfDepth(start, across);
    const auto ahead = surfaceAlong(scene, view.position, dir);
    const float farthest = ahead ? 0.8f * *ahead - halfDepth(start, dir) : kInfinity;
    // Touching counts: resting on top of another object is not clear of it.
    const Vec3 margin = 0.01f * start.extent();
    std::optional<Vec3> firstSeen;
    Vec3 firstRest(0.0f);
    for (const float depth : {1.0f, 1.4f, 2.0f, 2.8f}) {
        const float d = depth == 1.0f ? distance : std::min(distance * depth, farthest);
        if (depth > 1.0f && !(d > distance)) break;
        for (int k = 0; k < kPlacementTries; ++k) {
            const float side = float((k + 1) / 2) * (k % 2 ? 1.0f : -1.0f);
            const Vec3 at = view.position + dir * d + across * (side * stride);
            Vec3 rest = at;
            if (const auto floor = surfaceAlong(scene, at, -up))
                rest = at - up * (*floor - halfDepth(start, up));
            if (depth == 1.0f && k == 0) firstRest = rest;
            moveBy(doc, id, rest - worldBounds(doc, id).center());
            Aabb now = worldBounds(doc, id);
            // Only where it can be seen: in the frame, its centre not behind anything.
            if (!inSight(now, view, aspect) || hidden(scene, view.position, now)) continue;
            if (!firstSeen) firstSeen = rest;
            now.min -= margin;
            now.max += margin;
            if (!overlapsAny(doc, id, now)) return rest - up * halfDepth(start, up);
        }
    }
    // Crowded all round: in sight if it can be, else straight ahead.
    const Vec3 rest = firstSeen.value_or(firstRest);
    moveBy(doc, id, rest - worldBounds(doc, id).center());
    return rest - up * halfDepth(start, up);
}

void anchorSunGlyphs(SceneDocument& doc) {
    const auto unanchored = [](const Light& l) {
        return l.type == LightType::Directional && l.position == Vec3(0.0f);
    };
    // The scene's bounds only when a sun needs them: 11 ms of a 100,000-object open.
    if (std::none_of(doc.lights.begin(), doc.lights.end(), unanchored)) return;
    Aabb bounds;
    for (const Object& o : doc.objects) bounds.expand(worldBounds(o));
    const Vec3 centre = bounds.empty() ? Vec3(0.0f) : bounds.center();
    const float radius = bounds.empty() ? 0.0f : 0.5f * glm::length(bounds.extent());
    for (Light& l : doc.lights) {
        if (!unanchored(l)) continue;
        const float length = glm::length(l.direction);
        const Vec3 toward = length > 0.0f ? l.direction / length : Vec3(0.0f, -1.0f, 0.0f);
        l.position = centre - toward * (radius + 1.0f);
    }
}

}  // namespace rs::ui
