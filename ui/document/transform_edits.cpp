// Transform edits about a pivot: the object's translate absorbs the pivot, so a ball whose
// centre sits in its geometry turns and grows in place.
#include "document/transform_edits.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "document/scene_edits.h"

namespace rs::ui {

namespace {

/// The shape's own bounds, before its transform (empty for planes).
Aabb localBounds(const Geometry& g) {
    Aabb b;
    if (const auto* s = std::get_if<SphereGeometry>(&g)) {
        b.expand(s->center - Vec3(s->radius));
        b.expand(s->center + Vec3(s->radius));
    } else if (const auto* r = std::get_if<RectangleGeometry>(&g)) {
        for (float su : {-1.0f, 1.0f})
            for (float sv : {-1.0f, 1.0f}) b.expand(r->center + su * r->u + sv * r->v);
    } else if (const auto* box = std::get_if<BoxGeometry>(&g)) {
        b.expand(box->min);
        b.expand(box->max);
    } else if (const auto* m = std::get_if<MeshGeometry>(&g)) {
        if (m->data) b = m->data->bounds();
    }
    return b;
}

/// The shape's own centre, before its transform.
Vec3 localCentre(const Geometry& g) {
    const Aabb b = localBounds(g);
    return b.empty() ? Vec3(0.0f) : b.center();
}

Mat4 rotationOf(const Vec3& degrees) {
    const Mat4 i(1.0f);
    return glm::rotate(i, glm::radians(degrees.z), Vec3(0, 0, 1)) *
           glm::rotate(i, glm::radians(degrees.y), Vec3(0, 1, 0)) *
           glm::rotate(i, glm::radians(degrees.x), Vec3(1, 0, 0));
}

Vec3 apply(const Mat4& m, const Vec3& v) {
    return Vec3(m * glm::vec4(v, 0.0f));
}

}  // namespace

std::optional<Vec3> entityCentre(const SceneDocument& doc, ObjectId id) {
    if (const Light* l = doc.findLight(id)) return l->position;
    const Object* o = doc.findObject(id);
    if (!o) return std::nullopt;
    if (const auto* p = std::get_if<PlaneGeometry>(&o->geometry)) return p->point;
    return Vec3(o->transform.matrix() * glm::vec4(localCentre(o->geometry), 1.0f));
}

Aabb worldBounds(const SceneDocument& doc, ObjectId id) {
    const Object* o = doc.findObject(id);
    return o ? worldBounds(*o) : Aabb{};
}

Aabb worldBounds(const Object& o) {
    const Aabb local = localBounds(o.geometry);
    return local.empty() ? local : local.transformed(o.transform.matrix());
}

Vec3 pivotOf(const SceneDocument& doc, const std::vector<ObjectId>& ids) {
    Vec3 sum(0.0f);
    int n = 0;
    for (ObjectId id : ids)
        if (const auto c = entityCentre(doc, id)) sum += *c, ++n;
    return n ? sum / float(n) : Vec3(0.0f);
}

void translateAll(SceneDocument& doc, const std::vector<ObjectId>& ids, const Vec3& delta) {
    for (ObjectId id : ids) moveBy(doc, id, delta);
}

Vec3 eulerDegreesOf(const Mat4& r) {
    // r = Rz(c) Ry(b) Rx(a); glm is column-major, so r[col][row].
    const float sb = std::clamp(-r[0][2], -1.0f, 1.0f);
    float a, b = std::asin(sb), c;
    if (std::abs(sb) < 0.99999f) {
        a = std::atan2(r[1][2], r[2][2]);
        c = std::atan2(r[0][1], r[0][0]);
    } else {
        // Gimbal lock: only a - c (or a + c) is defined; put it all in a.
        c = 0.0f;
        a = std::atan2(sb * r[1][0], r[1][1]);
    }
    return glm::degrees(Vec3(a, b, c));
}

void rotateAll(SceneDocument& doc, const std::vector<ObjectId>& ids, const Vec3& pivot,
               const Vec3& axis, float degrees) {
    const Mat4 turn = glm::rotate(Mat4(1.0f), glm::radians(degrees), glm::normalize(axis));
    const bool aboutZ = std::abs(axis.x) < 1e-6f && std::abs(axis.y) < 1e-6f;
    for (ObjectId id : ids) {
        if (Light* l = doc.findLight(id)) {
            // A spot turns rigidly (its target about its own position when it is the pivot);
            // a sun's direction turns, its glyph's anchor goes round the pivot.
            l->position = pivot + apply(turn, l->position - pivot);
            if (l->type == LightType::Spot) l->target = pivot + apply(turn, l->target - pivot);
            if (l->type == LightType::Directional)
                l->direction = glm::normalize(apply(turn, l->direction));
            continue;
        }
        Object* o = doc.findObject(id);
        if (!o) continue;
        if (auto* p = std::get_if<PlaneGeometry>(&o->geometry)) {
            p->point = pivot + apply(turn, p->point - pivot);
            p->normal = glm::normalize(apply(turn, p->normal));
            continue;
        }
        Transform& t = o->transform;
        t.translate = pivot + apply(turn, t.translate - pivot);
        if (aboutZ) {
            // Z is the outermost Euler rotation: adding to it is exact, so a typed 45 stays 45.
            t.rotate.z += axis.z > 0.0f ? degrees : -degrees;
        } else {
            t.rotate = eulerDegreesOf(turn * rotationOf(t.rotate));
        }
    }
}

void scaleAll(SceneDocument& doc, const std::vector<ObjectId>& ids, const Vec3& pivot,
              const Vec3& factors, const Mat3& axes) {
    // The scale as a world matrix: `factors` along the columns of the orthonormal `axes`.
    const Mat3 scale = axes * Mat3(glm::scale(Mat4(1.0f), factors)) * glm::transpose(axes);
    for (ObjectId id : ids) {
        if (Light* l = doc.findLight(id)) {
            const Vec3 was = l->position;
            l->position = pivot + scale * (l->position - pivot);
            if (l->type == LightType::Spot) l->target += l->position - was;  // Keeps its aim.
            if (l->type == LightType::Sphere)
                l->radius *=
                    std::max({std::abs(factors.x), std::abs(factors.y), std::abs(factors.z)});
            continue;
        }
        Object* o = doc.findObject(id);
        if (!o) continue;
        if (auto* p = std::get_if<PlaneGeometry>(&o->geometry)) {
            p->point = pivot + scale * (p->point - pivot);
            continue;
        }
        o->transform.translate = pivot + scale * (o->transform.translate - pivot);
        // Each of the object's own axes stretches by how much the scale lengthens it; its
        // rotation stays. Exact when the scale's axes are the object's (local gizmo) or the
        // scale is uniform or the object turned by right angles; otherwise the shear a
        // transform cannot hold is dropped, as Blender does for objects.
        const Mat3 rotation(rotationOf(o->transform.rotate));
        for (int i = 0; i < 3; ++i) o->transform.scale[i] *= glm::length(scale * rotation[i]);
    }
}

}  // namespace rs::ui
