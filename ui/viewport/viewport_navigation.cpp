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
    const QSize traced = tracedSize_.isEmpty() ? sizeToTrace() : tracedSize_;
    doc.camera = fitOutputFrame(viewCamera_, traced, QSize(doc.render.width, doc.render.height));
    doc.render.width = traced.width();
    doc.render.height = traced.height();
    return doc;
}

void Viewport::onDocumentReset() {
    viewCamera_ = editor_->document().camera;
    throughScene_ = true;
    const float len = glm::length(viewCamera_.up);
    worldUp_ = len > 1e-6f ? viewCamera_.up / len : Vec3(0.0f, 1.0f, 0.0f);
}

void Viewport::onDocumentChanged() {
    // Looking through the scene camera, its edits (property panel, undo) move the view too.
    if (throughScene_) viewCamera_ = editor_->document().camera;
    postView();
}

void Viewport::setView(const Camera& camera) {
    viewCamera_ = camera;
    throughScene_ = false;
    postView();
}

QSize Viewport::sizeToTrace() const {
    return tracedFrameSize(size() * devicePixelRatioF(), divider_);
}

void Viewport::postView() {
    resizeSettle_.stop();
    tracedSize_ = sizeToTrace();
    session_->requestUpdate(viewDocument());
    redraw();
}

void Viewport::viewThroughSceneCamera() {
    viewCamera_ = editor_->document().camera;
    throughScene_ = true;
    postView();
}

void Viewport::sceneCameraFromView() {
    SceneDocument doc = editor_->document();
    if (doc.camera == viewCamera_) {
        throughScene_ = true;
        redraw();
        return;
    }
    // Only the pose: lens and extras stay the scene camera's.
    doc.camera.position = viewCamera_.position;
    doc.camera.target = viewCamera_.target;
    doc.camera.up = viewCamera_.up;
    throughScene_ = true;
    editor_->closeMerge();
    editor_->edit(tr("Scene camera from view"), std::move(doc));
    editor_->closeMerge();
}

void Viewport::setAxisView(AxisView v) {
    static const Vec3 kDirs[] = {{0, 0, -1}, {0, 0, 1},  {-1, 0, 0},
                                 {1, 0, 0},  {0, -1, 0}, {0, 1, 0}};
    static const Vec3 kUps[] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    Camera c = viewCamera_;
    alignView(c, kDirs[int(v)], kUps[int(v)]);
    setView(c);
}

Vec3 Viewport::orbitPivot(const QPoint& pos) {
    // The selection's centre; else the surface under the cursor; else the view's target.
    const ObjectId sel = editor_->selection();
    const SceneDocument& doc = editor_->document();
    const Object* o = doc.findObject(sel);
    const bool unbounded = o && std::holds_alternative<PlaneGeometry>(o->geometry);
    orbitFree_ = viewCamera_;
    orbitIgnore_ = sel;
    if (!unbounded)
        if (const auto c = entityCentre(doc, sel)) return *c;
    orbitIgnore_ = kNoObject;
    if (const auto px = pixelAt(pos)) {
        orbitIgnore_ = frame_->idAt(px->x(), px->y());
        const std::size_t i = std::size_t(px->y()) * frame_->width + px->x();
        const float depth = i < frame_->depth.size() ? frame_->depth[i] : kInfinity;
        if (std::isfinite(depth)) return projection().pixelRay(px->x(), px->y()).at(depth);
    }
    return viewCamera_.target;
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
    const Vec3 back = viewCamera_.position - viewCamera_.target;
    const float maxDistance = glm::length(back) > 1e-6f
                                  ? freeDistance(center, glm::normalize(back), id) * kWallClearance
                                  : kInfinity;
    Camera c = viewCamera_;
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
    Camera c = viewCamera_;
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

void Viewport::orbitView(const QPoint& delta) {
    // The orbit turns a camera of its own, unclipped, so the view comes back out to its
    // distance once the way is clear; what is shown stops short of the first surface between
    // the pivot and the camera (orbiting about a far wall would swing out through the side
    // walls of the room).
    orbitAround(orbitFree_, orbitPivot_, worldUp_, delta.x() * 0.4f, delta.y() * 0.4f);
    Camera c = orbitFree_;
    const Vec3 out = c.position - orbitPivot_;
    const float dist = glm::length(out);
    if (dist > 1e-6f) {
        const float free = freeDistance(orbitPivot_, out / dist, orbitIgnore_) * kWallClearance;
        if (free < dist) {
            const Vec3 in = out * (free / dist - 1.0f);
            c.position += in;
            c.target += in;
        }
    }
    setView(c);
}

}  // namespace rs::ui
