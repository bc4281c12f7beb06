// Viewport input: id-buffer and light-glyph picking, image-plane drags with axis locks, and
// the routing of mouse and keys to view navigation and G/R/S gestures.
#include "viewport.h"

#include "camera_navigation.h"
#include "passepartout.h"
#include "scene_edits.h"
#include "scene_editor.h"
#include "session_controller.h"

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
    : QWidget(parent), editor_(editor), session_(session), view_(createFrameView(this)),
      overlay_(new LightOverlay(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(view_->widget());
    view_->widget()->setAttribute(Qt::WA_TransparentForMouseEvents);
    overlay_->raise();
    if (view_->usesOpenGL()) {
        // A native GL window covers sibling widgets: the GL view paints the glyphs itself
        // (the overlay widget keeps them for picking).
        overlay_->hide();
        view_->setOverlayPainter([this](QPainter& p) {
            paintPassepartout(p, rect(), overlay_->passepartout());
            paintLightGlyphs(p, overlay_->glyphs(), overlay_->selected());
        });
    }
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setMinimumSize(320, 180);
    resizeSettle_.setSingleShot(true);
    resizeSettle_.setInterval(kResizeSettleMs);
    connect(&resizeSettle_, &QTimer::timeout, this, &Viewport::postView);
    connect(session_, &SessionController::frameUpdated, this, &Viewport::refresh);
    connect(editor_, &SceneEditor::selectionChanged, this, &Viewport::redraw);
    connect(editor_, &SceneEditor::documentReset, this, &Viewport::onDocumentReset);
    connect(editor_, &SceneEditor::documentChanged, this, &Viewport::onDocumentChanged);
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
    const ViewProjection view = projection();
    overlay_->setGlyphs(ui::lightGlyphs(editor_->document(), view), sel);
    overlay_->setPassepartout(throughScene_ ? view.outputRect() : QRectF());
}

void Viewport::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    overlay_->setGeometry(rect());
    // While the window edge moves, the old frame stays (letterboxed); the session restarts
    // at the new size once it rests.
    if (tracedSize_.isEmpty())
        postView();
    else
        resizeSettle_.start();
    redraw();
}

void Viewport::setPreviewDivider(int divider) {
    divider = validPreviewDivider(divider) ? divider : 1;
    if (divider == divider_) return;
    divider_ = divider;
    postView();
}

ViewProjection Viewport::projection() const {
    // The frame shown, or before the first one arrives, the size posted for it.
    const QSize frameSize = frame_ && !frame_->empty() ? QSize(frame_->width, frame_->height)
                            : !tracedSize_.isEmpty()   ? tracedSize_
                                                       : sizeToTrace();
    const RenderSettings& output = editor_->document().render;
    return ViewProjection(viewCamera_, QSize(output.width, output.height), frameSize, size());
}

std::optional<QPoint> Viewport::pixelAt(const QPoint& p) const {
    if (!frame_ || frame_->empty()) return std::nullopt;
    return projection().pixelAt(p);
}

QPoint Viewport::widgetPointOf(int x, int y) const {
    if (!frame_ || frame_->empty()) return {};
    return projection().widgetPointOf(x, y);
}

bool Viewport::event(QEvent* e) {
    // During a gesture every key is the gesture's: digits are typed values, not the numpad
    // views' shortcuts, and G/R/S switch the gesture instead of starting another.
    if (e->type() == QEvent::ShortcutOverride && gesture_) {
        e->accept();
        return true;
    }
    return QWidget::event(e);
}

void Viewport::mousePressEvent(QMouseEvent* e) {
    setFocus();
    if (gesture_) {
        finishGesture(e->button() != Qt::LeftButton);
        return;
    }
    editor_->closeMerge();
    pressPos_ = lastPos_ = e->position().toPoint();
    if (e->button() == Qt::RightButton ||
        (e->button() == Qt::LeftButton && (e->modifiers() & Qt::AltModifier))) {
        drag_ = Drag::Orbit;
        orbitPivot_ = orbitPivot(pressPos_);
    } else if (e->button() == Qt::MiddleButton) {
        drag_ = Drag::Pan;
    } else if (e->button() == Qt::LeftButton) {
        // A light's glyph is drawn in front of everything, so it is picked first.
        ObjectId id = pickLight(overlay_->glyphs(), e->position());
        if (id == kNoObject) {
            const auto px = pixelAt(pressPos_);
            id = px ? frame_->idAt(px->x(), px->y()) : kNoObject;
        }
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
    if (gesture_) {
        gesture_->setCursor(e->position(), e->modifiers() & Qt::ControlModifier);
        updateGesture();
        return;
    }
    if (drag_ == Drag::PendingObject &&
        (pos - pressPos_).manhattanLength() >= kDragThresholdPx)
        startObjectDrag();
    if (drag_ == Drag::Object) {
        updateObjectDrag(pos);
    } else if (drag_ == Drag::Orbit || drag_ == Drag::Pan) {
        Camera c = viewCamera_;
        if (drag_ == Drag::Orbit)
            orbitAround(c, orbitPivot_, worldUp_, delta.x() * 0.4f, delta.y() * 0.4f);
        else
            pan(c, float(delta.x()) / std::max(1, height()), float(delta.y()) / std::max(1, height()));
        setView(c);
    }
}

void Viewport::mouseReleaseEvent(QMouseEvent*) {
    if (!gesture_) finishDrag(false);
}

void Viewport::wheelEvent(QWheelEvent* e) {
    Camera c = viewCamera_;
    dolly(c, e->angleDelta().y() / 120.0f * 0.1f);
    setView(c);
}

void Viewport::keyPressEvent(QKeyEvent* e) {
    if (gesture_) {
        switch (gesture_->keyPress(e->key(), e->text())) {
            case ModalTransform::KeyResult::Confirm:
                finishGesture(false);
                return;
            case ModalTransform::KeyResult::Cancel:
                finishGesture(true);
                return;
            case ModalTransform::KeyResult::Updated:
                updateGesture();
                return;
            case ModalTransform::KeyResult::Unhandled:
                if (e->key() == Qt::Key_Control) {
                    gesture_->setSnap(true);
                    updateGesture();
                }
                return;  // Nothing else happens mid-gesture.
        }
    }
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

void Viewport::keyReleaseEvent(QKeyEvent* e) {
    if (gesture_ && e->key() == Qt::Key_Control) {
        gesture_->setSnap(false);
        updateGesture();
        return;
    }
    QWidget::keyReleaseEvent(e);
}

void Viewport::focusOutEvent(QFocusEvent* e) {
    // A gesture the viewport no longer hears the keys of would never end (a menu opening
    // over it is no such loss).
    if (gesture_ && e->reason() != Qt::PopupFocusReason) finishGesture(true);
    QWidget::focusOutEvent(e);
}

void Viewport::startObjectDrag() {
    // The frame may have changed size since the press (a resize, a new render size): when the
    // press point no longer lies on the image there is nothing to grab, and the press stays
    // a click.
    const auto px = pixelAt(pressPos_);
    if (!px) {
        drag_ = Drag::None;
        return;
    }
    drag_ = Drag::Object;
    axisLock_ = -1;
    dragStartDoc_ = editor_->document();
    if (const Light* l = dragStartDoc_.findLight(dragId_)) {
        anchor_ = l->position;
    } else {
        const auto snapshot = session_->session().snapshot();
        const Aabb bounds = snapshot ? snapshot->objectBounds(dragId_) : Aabb{};
        const std::size_t i = std::size_t(px->y()) * frame_->width + px->x();
        const Ray ray = projection().pixelRay(px->x(), px->y());
        const float depth = i < frame_->depth.size() ? frame_->depth[i] : kInfinity;
        const Vec3 hit = ray.at(std::isfinite(depth) ? depth : 1.0f);
        // Planes are unbounded: drag them through the point that was clicked.
        anchor_ = bounds.empty() ? hit : bounds.center();
    }
    grabOffset_ = Vec3(0.0f);
    grabOffset_ = dragPoint(pressPos_) - anchor_;
    session_->beginInteraction(dragId_);
}

Vec3 Viewport::dragPoint(const QPoint& pos) const {
    // The current view, not the one at press: the user may dolly during the drag.
    const ViewProjection view = projection();
    const Ray ray = view.rayThrough(QPointF(pos));
    if (axisLock_ >= 0) {
        Vec3 axis(0.0f);
        axis[axisLock_] = 1.0f;
        return closestOnAxis(anchor_, axis, ray.origin, ray.dir) + grabOffset_;
    }
    // Plane parallel to the image through the anchor.
    const Vec3 n = view.camera().forward();
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
    // Everything but the dragged object comes from the current document, so any other edit
    // made during the drag survives the next step.
    SceneDocument doc = editor_->document();
    restoreEntity(doc, dragStartDoc_, dragId_);
    moveBy(doc, dragId_, delta);
    if (const auto px = pixelAt(pos)) session_->session().setFocus(px->x() + 0.5f, px->y() + 0.5f);
    editor_->edit(tr("Move object"), std::move(doc), MergeKind::Drag, QString::number(dragId_));
}

void Viewport::finishDrag(bool cancel) {
    const Drag was = drag_;
    drag_ = Drag::None;
    if (was == Drag::Object && cancel) {
        SceneDocument doc = editor_->document();
        restoreEntity(doc, dragStartDoc_, dragId_);
        editor_->edit(tr("Move object"), std::move(doc), MergeKind::Drag, QString::number(dragId_));
    }
    if (was == Drag::Object || was == Drag::Orbit || was == Drag::Pan) session_->endInteraction();
    editor_->closeMerge();
}

}  // namespace rs::ui
