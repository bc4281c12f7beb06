// Viewport view camera: navigation moves it and never the document; the session renders the
// document through it (a camera edit to the session, no undo step, no modified flag).
#include <algorithm>

#include "adapter/session_controller.h"
#include "document/scene_editor.h"
#include "document/transform_edits.h"
#include "snapshot/compiled_scene.h"
#include "viewport/camera_navigation.h"
#include "viewport/viewport.h"

namespace rs::ui {

namespace {
/// How far short of the first surface behind the view F stops, as a share of its distance.
constexpr float kWallClearance = 0.9f;
/// Share of the distance a wheel click dollies the view.
constexpr float kDollyShare = 0.1f;
/// The least a dolly keeps from a surface, as a share of the scene camera's distance to its
/// target.
constexpr float kDollyGap = 0.02f;
/// Surfaces of the selection itself a framing ray passes through before it finds a wall.
constexpr int kMaxSelfHits = 8;
/// A plane nearer than this to a cast's start is the one it starts on.
constexpr float kOnPlane = 1e-3f;
}  // namespace

SceneDocument Viewport::viewDocument() const {
    SceneDocument doc = editor_->document();
    // The output size stays the document's (Render Image, Export, the CLI); the viewport
    // traces its own.
    const QSize traced = posting_.traced();
    doc.camera =
        fitOutputFrame(camera_.camera(), traced, QSize(doc.render.width, doc.render.height));
    doc.render.width = traced.width();
    doc.render.height = traced.height();
    return doc;
}

void Viewport::onDocumentReset() {
    camera_.reset(editor_->document().camera);
}

void Viewport::onDocumentChanged() {
    // Looking through the scene camera, its edits (property panel, undo) move the view too.
    camera_.sceneEdited(editor_->document().camera);
    postView();
}

void Viewport::setView(const Camera& camera) {
    camera_.look(camera);
    postView();
}

void Viewport::postView() {
    posting_.post();
}  // Redraws when posted.

void Viewport::viewThroughSceneCamera() {
    camera_.lookThroughScene(editor_->document().camera);
    postView();
}

void Viewport::sceneCameraFromView() {
    SceneDocument doc = editor_->document();
    const Camera& view = camera_.camera();
    if (doc.camera == view) {
        camera_.adoptedByScene();
        redraw();
        return;
    }
    // Only the pose: lens and extras stay the scene camera's.
    doc.camera.position = view.position;
    doc.camera.target = view.target;
    doc.camera.up = view.up;
    camera_.adoptedByScene();
    editor_->closeMerge();
    editor_->edit(tr("Scene camera from view"), std::move(doc));
    editor_->closeMerge();
}

void Viewport::setAxisView(AxisView v) {
    static const Vec3 kDirs[] = {{0, 0, -1}, {0, 0, 1},  {-1, 0, 0},
                                 {1, 0, 0},  {0, -1, 0}, {0, 1, 0}};
    static const Vec3 kUps[] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    Camera c = camera_.camera();
    alignView(c, kDirs[int(v)], kUps[int(v)]);
    setView(c);
}

Orbit Viewport::startOrbit(const QPoint& pos) const {
    // The selection's centre; else the surface under the cursor; else the view's target.
    const ObjectId sel = editor_->selection();
    const SceneDocument& doc = editor_->document();
    const Object* o = doc.findObject(sel);
    const bool unbounded = o && std::holds_alternative<PlaneGeometry>(o->geometry);
    const Camera& view = camera_.camera();
    if (!unbounded)
        if (const auto c = entityCentre(doc, sel)) return Orbit(view, *c, sel);
    ObjectId ignore = kNoObject;
    if (const auto px = pixelAt(pos)) {
        ignore = frame_->idAt(px->x(), px->y());
        const std::size_t i = std::size_t(px->y()) * frame_->width + px->x();
        const float depth = i < frame_->depth.size() ? frame_->depth[i] : kInfinity;
        if (std::isfinite(depth))
            return Orbit(view, projection().pixelRay(px->x(), px->y()).at(depth), ignore);
    }
    return Orbit(view, view.target, ignore);
}

void Viewport::frameSelection() {
    const ObjectId id = editor_->selection();
    const SceneDocument& doc = editor_->document();
    // The session's snapshot must hold the latest edits: its bounds and walls are used.
    const auto snapshot = session_->appliedSnapshot();
    Vec3 center;
    float radius = 1.0f;
    if (const Light* l = doc.findLight(id)) {
        center = l->position;
        if (l->type == LightType::Sphere) radius = std::max(radius, l->radius);
    } else {
        const Aabb b = snapshot ? snapshot->objectBounds(id) : Aabb{};
        if (b.empty()) return;
        center = b.center();
        radius = 0.5f * glm::length(b.extent());
    }
    // Cast from the centre towards where the view will stand: the first surface that is not
    // the selection itself (a wall of the room) limits the distance.
    const Vec3 back = camera_.camera().position - camera_.camera().target;
    const float maxDistance = glm::length(back) > 1e-6f
                                  ? freeDistance(center, glm::normalize(back), id) * kWallClearance
                                  : kInfinity;
    Camera c = camera_.camera();
    ui::frame(c, center, radius, maxDistance);
    setView(c);
}

float Viewport::freeDistance(const Vec3& from, const Vec3& dir, ObjectId ignore) const {
    const auto snapshot = session_->session().snapshot();
    if (!snapshot) return kInfinity;
    float free = kInfinity;
    Vec3 origin = from;
    float travelled = 0.0f;
    for (int i = 0; i < kMaxSelfHits; ++i) {
        SurfaceHit hit;
        if (!snapshot->intersect(Ray::make(origin, dir), kInfinity, hit)) break;
        if (hit.id != ignore) {
            free = travelled + hit.t;
            break;
        }
        const float step = hit.t + snapshot->epsilon();
        origin += dir * step;
        travelled += step;
    }
    // Walls and floors also limit it when `from` touches one: stepping out of `ignore` there
    // can land behind the plane, where the cast above sees nothing. A plane `from` lies on
    // (an orbit about a point of a wall) is left behind, not in the way.
    for (const PlanePrimitive& p : snapshot->planes()) {
        const float denom = glm::dot(dir, p.shape.normal);
        if (denom == 0.0f) continue;
        const float t = glm::dot(p.shape.point - from, p.shape.normal) / denom;
        if (t > kOnPlane) free = std::min(free, t);
    }
    return free;
}

float Viewport::dollyRoom(float free) const {
    // Short of the surface by a share of the way and by a gap of the scene's scale (the
    // scene camera's distance to its target): without the gap, click after click would
    // creep up to a wall until it counted as the plane the view stands on, and pass it.
    const Camera& scene = editor_->document().camera;
    const float gap = kDollyGap * glm::length(scene.target - scene.position);
    return std::max(0.0f, std::min(free * kWallClearance, free - gap));
}

Camera Viewport::dollied(float clicks, const QPointF& cursor) const {
    Camera c = camera_.camera();
    if (c.projection == Projection::Orthographic) {
        dolly(c, clicks * kDollyShare);
        return c;
    }
    const Vec3 forward = c.target - c.position;
    const float toTarget = glm::length(forward);
    if (!(toTarget > 1e-6f)) return c;
    const Vec3 dir = forward / toTarget;
    if (clicks > 0.0f) {
        // In: a share of the distance to what is under the cursor (the target's without a
        // surface there), stopping short of the first surface ahead.
        float under = toTarget;
        if (const auto snapshot = session_->session().snapshot()) {
            const Ray ray = projection().rayThrough(cursor);
            SurfaceHit hit;
            if (snapshot->intersect(ray, kInfinity, hit)) under = hit.t;
        }
        const float ahead = dollyRoom(freeDistance(c.position, dir, kNoObject));
        const float step = std::min(std::min(clicks * kDollyShare, 0.9f) * under, ahead);
        if (!(step > 0.0f)) return c;
        c.position += dir * step;
        // Never onto or past the target: it moves on ahead of the view.
        if (toTarget - step < kDollyShare * under)
            c.target = c.position + dir * (kDollyShare * under);
        return c;
    }
    // Out: a share of the distance to the target, stopping short of the surface behind.
    const float behind = dollyRoom(freeDistance(c.position, -dir, kNoObject));
    const float step = std::min(-clicks * kDollyShare * toTarget, behind);
    if (step > 0.0f) c.position -= dir * step;
    return c;
}

void Viewport::orbitView(Orbit& orbit, const QPoint& delta) {
    // Stops short of the first surface between the pivot and the camera, as F does.
    setView(orbit.turn(delta, camera_.worldUp(),
                       [this](const Vec3& from, const Vec3& dir, ObjectId ignore) {
                           return freeDistance(from, dir, ignore) * kWallClearance;
                       }));
}

}  // namespace rs::ui
