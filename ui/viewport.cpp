// Viewport input: id-buffer picking, image-plane drags with axis locks, camera navigation.
#include "viewport.h"

#include "camera_navigation.h"
#include "scene_edits.h"
#include "scene_editor.h"
#include "session_controller.h"
#include "snapshot/camera_model.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QVBoxLayout>
#include <QWheelEvent>

namespace rs::ui {

namespace {
constexpr int kDragThresholdPx = 3;

/// The point of line (a + s * axis) closest to the ray (o + t * d).
Vec3 closestOnAxis(const Vec3& a, const Vec3& axis, const Vec3& o, const Vec3& d) {
    const Vec3 w = a - o;
    const float b = glm::dot(axis, d), dd = glm::dot(d, d), aa = glm::dot(axis, axis);
    const float denom = aa * dd - b * b;
    if (std::abs(denom) < 1e-8f) return a;
    const float s = (b * glm::dot(d, w) - dd * glm::dot(axis, w)) / denom;
    return a + axis * s;
}
}  // namespace

Viewport::Viewport(SceneEditor* editor, SessionController* session, QWidget* parent)
    : QWidget(parent), editor_(editor), session_(session), view_(createFrameView(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(view_->widget());
    view_->widget()->setAttribute(Qt::WA_TransparentForMouseEvents);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setMinimumSize(320, 180);
    connect(session_, &SessionController::frameUpdated, this, &Viewport::refresh);
    connect(editor_, &SceneEditor::selectionChanged, this, &Viewport::redraw);
}

void Viewport::setViewMode(ViewMode mode) {
    mode_ = mode;
    redraw();
}

void Viewport::refresh() {
    frame_ = session_->displayFrame();
    redraw();
}

void Viewport::redraw() {
    const ObjectId sel = editor_->selection() == SceneEditor::kCameraSelection
                             ? kNoObject
                             : editor_->selection();
    view_->showFrame(frame_, mode_, sel);
}

std::optional<QPoint> Viewport::pixelAt(const QPoint& p) const {
    if (!frame_ || frame_->empty()) return std::nullopt;
    const QRect r = fitRect(size(), QSize(frame_->width, frame_->height));
    if (!r.contains(p)) return std::nullopt;
    const int x = int((p.x() - r.x() + 0.5) * frame_->width / r.width());
    const int y = int((p.y() - r.y() + 0.5) * frame_->height / r.height());
    return QPoint(std::clamp(x, 0, frame_->width - 1), std::clamp(y, 0, frame_->height - 1));
}

QPoint Viewport::widgetPointOf(int x, int y) const {
    if (!frame_ || frame_->empty()) return {};
    const QRect r = fitRect(size(), QSize(frame_->width, frame_->height));
    return QPoint(r.x() + int((x + 0.5) * r.width() / frame_->width),
                  r.y() + int((y + 0.5) * r.height() / frame_->height));
}

void Viewport::mousePressEvent(QMouseEvent* e) {
    setFocus();
    editor_->closeMerge();
    pressPos_ = lastPos_ = e->position().toPoint();
    if (e->button() == Qt::RightButton ||
        (e->button() == Qt::LeftButton && (e->modifiers() & Qt::AltModifier))) {
        drag_ = Drag::Orbit;
    } else if (e->button() == Qt::MiddleButton) {
        drag_ = Drag::Pan;
    } else if (e->button() == Qt::LeftButton) {
        const auto px = pixelAt(pressPos_);
        const ObjectId id = px ? frame_->idAt(px->x(), px->y()) : kNoObject;
        editor_->setSelection(id);
        if (id != kNoObject) {
            drag_ = Drag::PendingObject;
            dragId_ = id;
        }
        return;
    }
    if (drag_ == Drag::Orbit || drag_ == Drag::Pan) session_->beginInteraction(kNoObject);
}

void Viewport::mouseMoveEvent(QMouseEvent* e) {
    const QPoint pos = e->position().toPoint();
    const QPoint delta = pos - lastPos_;
    lastPos_ = pos;
    if (drag_ == Drag::PendingObject &&
        (pos - pressPos_).manhattanLength() >= kDragThresholdPx)
        startObjectDrag();
    if (drag_ == Drag::Object) {
        updateObjectDrag(pos);
    } else if (drag_ == Drag::Orbit || drag_ == Drag::Pan) {
        SceneDocument doc = editor_->document();
        if (drag_ == Drag::Orbit)
            orbit(doc.camera, delta.x() * 0.4f, delta.y() * 0.4f);
        else
            pan(doc.camera, float(delta.x()) / std::max(1, height()),
                float(delta.y()) / std::max(1, height()));
        editor_->edit(tr("Move camera"), std::move(doc), MergeKind::Camera, QStringLiteral("camera"));
    }
}

void Viewport::mouseReleaseEvent(QMouseEvent*) {
    finishDrag(false);
}

void Viewport::wheelEvent(QWheelEvent* e) {
    SceneDocument doc = editor_->document();
    dolly(doc.camera, e->angleDelta().y() / 120.0f * 0.1f);
    editor_->edit(tr("Dolly camera"), std::move(doc), MergeKind::Camera, QStringLiteral("camera"));
}

void Viewport::keyPressEvent(QKeyEvent* e) {
    if (drag_ == Drag::Object) {
        const int axis = e->key() == Qt::Key_X ? 0 : e->key() == Qt::Key_Y ? 1 : e->key() == Qt::Key_Z ? 2 : -1;
        if (axis >= 0) {
            axisLock_ = axisLock_ == axis ? -1 : axis;
            updateObjectDrag(lastPos_);
            return;
        }
        if (e->key() == Qt::Key_Escape) {
            finishDrag(true);
            return;
        }
    }
    QWidget::keyPressEvent(e);
}

void Viewport::startObjectDrag() {
    drag_ = Drag::Object;
    axisLock_ = -1;
    dragStartDoc_ = editor_->document();
    const auto snapshot = session_->session().snapshot();
    const Aabb bounds = snapshot ? snapshot->objectBounds(dragId_) : Aabb{};
    const auto px = pixelAt(pressPos_);
    const std::size_t i = std::size_t(px->y()) * frame_->width + px->x();
    const CameraModel cam(dragStartDoc_.camera, frame_->width, frame_->height);
    const Ray ray = cam.generateRay(px->x() + 0.5f, px->y() + 0.5f);
    const Vec3 hit = ray.at(std::isfinite(frame_->depth.empty() ? 0.0f : frame_->depth[i])
                                ? frame_->depth[i]
                                : 1.0f);
    // Planes are unbounded: drag them through the point that was clicked.
    anchor_ = bounds.empty() ? hit : bounds.center();
    grabOffset_ = Vec3(0.0f);
    grabOffset_ = dragPoint(pressPos_) - anchor_;
    session_->beginInteraction(dragId_);
}

Vec3 Viewport::dragPoint(const QPoint& pos) const {
    const QRect r = fitRect(size(), QSize(frame_->width, frame_->height));
    const float px = float(pos.x() - r.x()) * frame_->width / std::max(1, r.width());
    const float py = float(pos.y() - r.y()) * frame_->height / std::max(1, r.height());
    const CameraModel cam(dragStartDoc_.camera, frame_->width, frame_->height);
    const Ray ray = cam.generateRay(px, py);
    if (axisLock_ >= 0) {
        Vec3 axis(0.0f);
        axis[axisLock_] = 1.0f;
        return closestOnAxis(anchor_, axis, ray.origin, ray.dir) + grabOffset_;
    }
    // Plane parallel to the image through the anchor.
    const Vec3 n = cam.forward();
    const float denom = glm::dot(ray.dir, n);
    if (std::abs(denom) < 1e-6f) return anchor_ + grabOffset_;
    const float t = glm::dot(anchor_ + grabOffset_ - ray.origin, n) / denom;
    return ray.at(t);
}

void Viewport::updateObjectDrag(const QPoint& pos) {
    Vec3 delta = dragPoint(pos) - grabOffset_ - anchor_;
    if (axisLock_ >= 0) {
        const float d = delta[axisLock_];
        delta = Vec3(0.0f);
        delta[axisLock_] = d;
    }
    SceneDocument doc = dragStartDoc_;
    moveBy(doc, dragId_, delta);
    if (const auto px = pixelAt(pos)) session_->session().setFocus(px->x() + 0.5f, px->y() + 0.5f);
    editor_->edit(tr("Move object"), std::move(doc), MergeKind::Drag, QString::number(dragId_));
}

void Viewport::finishDrag(bool cancel) {
    const Drag was = drag_;
    drag_ = Drag::None;
    if (was == Drag::Object && cancel)
        editor_->edit(tr("Move object"), dragStartDoc_, MergeKind::Drag, QString::number(dragId_));
    if (was == Drag::Object || was == Drag::Orbit || was == Drag::Pan) session_->endInteraction();
    editor_->closeMerge();
}

void Viewport::frameSelection() {
    const ObjectId id = editor_->selection();
    SceneDocument doc = editor_->document();
    Vec3 center;
    float radius = 1.0f;
    if (const Light* l = doc.findLight(id)) {
        center = l->position;
    } else {
        const auto snapshot = session_->session().snapshot();
        const Aabb b = snapshot ? snapshot->objectBounds(id) : Aabb{};
        if (b.empty()) return;
        center = b.center();
        radius = 0.5f * glm::length(b.extent());
    }
    ui::frame(doc.camera, center, radius);
    editor_->edit(tr("Frame selection"), std::move(doc));
}

}  // namespace rs::ui
