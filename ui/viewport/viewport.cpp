// Viewport input: id-buffer and light-glyph picking, image-plane drags with axis locks, and
// the routing of mouse and keys to view navigation, the gizmo and G/R/S gestures.
#include "viewport/viewport.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "adapter/session_controller.h"
#include "document/scene_editor.h"
#include "document/scene_edits.h"
#include "document/transform_edits.h"
#include "viewport/camera_navigation.h"
#include "viewport/passepartout.h"
#include "viewport/viewport_overlay.h"

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

Viewport::Viewport(SceneEditor* editor, SessionController* session, QWidget* parent,
                   DisplayKind display)
    : QWidget(parent),
      editor_(editor),
      session_(session),
      overlay_(new ViewportOverlay(
          [this](QPainter& p) {
              // Any paint, a tile's too, draws the overlay as it is at that moment.
              overlayShown_ += overlayRegion();
              paintOverlay(p);
          },
          this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    installFrameView(createFrameView(this, display));
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setMinimumSize(320, 180);
    resizeSettle_.setSingleShot(true);
    resizeSettle_.setInterval(kResizeSettleMs);
    connect(&resizeSettle_, &QTimer::timeout, this, &Viewport::postView);
    connect(session_, &SessionController::frameUpdated, this, &Viewport::showNewPixels);
    // A still frame's tiles wait for the pace; the end of a pass is shown at once.
    paceClock_.start();
    paceTimer_.setSingleShot(true);
    connect(&paceTimer_, &QTimer::timeout, this, &Viewport::showNewPixels);
    connect(session_, &SessionController::passFinished, this, [this](const PassInfo& info) {
        if (info.cancelled) return;
        pacing_.passCompleted();
        showNewPixels();
    });
    connect(editor_, &SceneEditor::selectionChanged, this, &Viewport::redraw);
    connect(editor_, &SceneEditor::documentReset, this, &Viewport::onDocumentReset);
    connect(editor_, &SceneEditor::documentChanged, this, &Viewport::onDocumentChanged);
    connect(editor_->undoStack(), &QUndoStack::indexChanged, this, &Viewport::onUndoIndexChanged);
}

void Viewport::installFrameView(FrameView* view) {
    view_ = view;
    layout()->addWidget(view_->widget());
    view_->widget()->setAttribute(Qt::WA_TransparentForMouseEvents);
    overlay_->raise();
    // A native GL window covers sibling widgets: the GL view paints the overlay itself.
    overlay_->setVisible(!view_->usesOpenGL());
    if (view_->usesOpenGL()) view_->setOverlayPainter([this](QPainter& p) { paintOverlay(p); });
}

void Viewport::setDisplay(DisplayKind display) {
    if (useOpenGL(display, openGLRenderer()) == view_->usesOpenGL()) return;
    delete view_->widget();  // Owns the view (the GL window is its container's).
    installFrameView(createFrameView(this, display));
    redraw();
}

void Viewport::setViewMode(ViewMode mode) {
    mode_ = mode;
    // Normals and ray costs are handed over only while a view shows them: fetched now.
    session_->setDebugBuffers(showsDebugBuffers(mode));
    if (showsDebugBuffers(mode)) frame_ = session_->displayFrame();
    redraw();
}

void Viewport::refresh() {
    const QSize before = frame_ ? QSize(frame_->width, frame_->height) : QSize();
    frame_ = session_->displayFrame();
    pacing_.handedOver(paceClock_.elapsed());
    showHandedOver(before);
}

void Viewport::setRepaintPacing(const RepaintPacing& pacing) {
    pacing_ = pacing;
    pacing_.handedOver(paceClock_.elapsed());
    paceTimer_.stop();
}

bool Viewport::interacting() const {
    return gesture_.has_value() || drag_ == Drag::Object || drag_ == Drag::Orbit ||
           drag_ == Drag::Pan;
}

void Viewport::showNewPixels() {
    pacing_.setInteracting(interacting());
    if (const int64_t wait = pacing_.delay(paceClock_.elapsed()); wait > 0) {
        // Tiles that come meanwhile are all in the one hand-over the timer brings.
        if (!paceTimer_.isActive()) paceTimer_.start(int(std::min<int64_t>(wait, 1 << 30)));
        return;
    }
    paceTimer_.stop();
    const QSize before = frame_ ? QSize(frame_->width, frame_->height) : QSize();
    const uint64_t serial = frame_ ? frame_->serial : 0;
    const int busy = session_->handoverStats().busy;
    frame_ = session_->displayFrame(SessionController::FrameWait::TryOnly);
    // A busy lock brings frameUpdated again shortly (the pass's end still pending then).
    if (session_->handoverStats().busy == busy) pacing_.handedOver(paceClock_.elapsed());
    if (frame_->serial != serial)
        showHandedOver(before);  // Else the lock was busy, or nothing new.
}

void Viewport::showHandedOver(const QSize& before) {
    // New pixels alone leave the overlay as it is; a new frame size moves it.
    if (QSize(frame_->width, frame_->height) != before) {
        redraw();
        return;
    }
    view_->showFrame(frame_, mode_, editor_->selectedIds());
}

void Viewport::redraw() {
    view_->showFrame(frame_, mode_, editor_->selectedIds());
    glyphs_ = ui::lightGlyphs(editor_->document(), projection());
    repaintOverlay();
}

void Viewport::repaintOverlay() {
    if (view_->usesOpenGL()) {
        view_->repaintOverlay();
        return;
    }
    // Only where the overlay was or is now drawn: the frame under the rest stays on screen.
    const QRegion now = overlayRegion();
    const QRectF output = throughScene_ ? projection().outputRect() : QRectF();
    if (output != outputShown_)
        overlay_->update();
    else
        overlay_->update(now | overlayShown_);
    overlayShown_ = now;
    outputShown_ = output;
}

QRegion Viewport::overlayRegion() const {
    // Pens, antialiasing and the highlight ring reach a few pixels past the shapes.
    constexpr int kMargin = 4;
    QRegion r;
    for (const LightGlyph& g : glyphs_) r += glyphRegion(g, kMargin);
    if (const auto g = gizmo()) r += g->bounds().toAlignedRect();
    if (drag_ == Drag::Box)
        r += QRect(pressPos_, lastPos_).normalized().adjusted(-kMargin, -kMargin, kMargin, kMargin);
    return r;
}

std::optional<TransformGizmo> Viewport::gizmo() const {
    const std::vector<ObjectId>& ids = editor_->selectedIds();
    if (ids.empty() || !gizmoVisible_) return std::nullopt;
    const SceneDocument& doc = editor_->document();
    TransformGizmo g(projection(), pivotOf(doc, ids), gizmoAxes(doc, ids.back(), localAxes_));
    if (!g.valid()) return std::nullopt;
    return g;
}

void Viewport::setGizmoVisible(bool visible) {
    gizmoVisible_ = visible;
    repaintOverlay();
}

void Viewport::setLocalOrientation(bool local) {
    localAxes_ = local;
    repaintOverlay();
}

void Viewport::beginBoxSelect() {
    if (gesture_ || drag_ != Drag::None) return;
    boxArmed_ = true;
    syncModal();
    Q_EMIT statusMessage(
        tr("Box select: drag a rectangle (Shift or Ctrl adds to the selection, "
           "Esc cancels)"));
}

void Viewport::paintOverlay(QPainter& p) const {
    // Through the scene camera, what lies outside the output frame is dimmed (passepartout).
    if (throughScene_) paintPassepartout(p, rect(), projection().outputRect());
    paintLightGlyphs(p, glyphs_, editor_->selectedIds());
    if (const auto g = gizmo()) g->paint(p, gizmoHandle_);
    if (drag_ == Drag::Box) {
        p.setRenderHint(QPainter::Antialiasing, false);
        p.setPen(QPen(QColor(240, 240, 240), 1.0, Qt::DashLine));
        p.setBrush(QColor(255, 255, 255, 30));
        p.drawRect(QRect(pressPos_, lastPos_).normalized());
    }
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
    // views' shortcuts, and G/R/S switch the gesture instead of starting another. During a
    // mouse drag, Ctrl+Z / Ctrl+Y cancel the drag instead of undoing under it.
    if (e->type() == QEvent::ShortcutOverride) {
        const auto* k = static_cast<QKeyEvent*>(e);
        const bool undoKey = k->matches(QKeySequence::Undo) || k->matches(QKeySequence::Redo);
        if (gesture_ || (drag_ != Drag::None && undoKey) ||
            (boxArmed_ && k->key() == Qt::Key_Escape)) {
            e->accept();
            return true;
        }
    }
    const bool handled = QWidget::event(e);
    syncModal();  // Presses, releases and keys start and end drags and gestures.
    return handled;
}

void Viewport::syncModal() {
    setProperty(kTakesAllKeys, gesture_.has_value() || drag_ != Drag::None || boxArmed_);
}

void Viewport::mousePressEvent(QMouseEvent* e) {
    setFocus();
    if (gesture_) {
        finishGesture(e->button() != Qt::LeftButton);
        return;
    }
    editor_->closeMerge();
    pressPos_ = lastPos_ = e->position().toPoint();
    if (boxArmed_ && e->button() != Qt::LeftButton) {
        boxArmed_ = false;  // Any other button cancels B.
        Q_EMIT statusMessage({});
        return;
    }
    if (e->button() == Qt::RightButton ||
        (e->button() == Qt::LeftButton && (e->modifiers() & Qt::AltModifier))) {
        drag_ = Drag::Orbit;
        orbitPivot_ = orbitPivot(pressPos_);
    } else if (e->button() == Qt::MiddleButton) {
        drag_ = Drag::Pan;
    } else if (e->button() == Qt::LeftButton) {
        pressLeft(e);
        return;
    }
    if (drag_ == Drag::Orbit || drag_ == Drag::Pan) session_->beginInteraction(kNoObject);
}

void Viewport::pressLeft(QMouseEvent* e) {
    const bool extend = e->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier);
    if (boxArmed_) {
        boxArmed_ = false;
        drag_ = Drag::Box;
        return;
    }
    // The gizmo is drawn over everything: its handles win.
    if (!extend)
        if (const auto g = gizmo())
            if (const auto handle = g->handleAt(e->position())) {
                startGesture(handle->kind, e->position(), handle);
                return;
            }
    // A light's glyph is drawn in front of every surface, so it is picked next.
    ObjectId id = pickLight(glyphs_, e->position());
    if (id == kNoObject) {
        const auto px = pixelAt(pressPos_);
        id = px ? frame_->idAt(px->x(), px->y()) : kNoObject;
    }
    if (id == kNoObject) {
        // Empty space: a drag draws a box, a click clears the selection.
        drag_ = Drag::PendingBox;
        return;
    }
    if (extend) {
        editor_->toggleSelected(id);
        return;
    }
    // Pressing one of several selected keeps the group, so a drag moves them all; a click
    // without a drag selects it alone (on release).
    if (!editor_->isSelected(id)) editor_->setSelection(id);
    drag_ = Drag::PendingObject;
    dragId_ = id;
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
    const bool moved = (pos - pressPos_).manhattanLength() >= kDragThresholdPx;
    if (drag_ == Drag::PendingObject && moved) startObjectDrag();
    if (drag_ == Drag::PendingBox && moved) drag_ = Drag::Box;
    if (drag_ == Drag::Box) {
        repaintOverlay();
    } else if (drag_ == Drag::Object) {
        updateObjectDrag(pos);
    } else if (drag_ == Drag::Orbit || drag_ == Drag::Pan) {
        if (drag_ == Drag::Orbit) {
            orbitView(delta);
        } else {
            Camera c = viewCamera_;
            pan(c, float(delta.x()) / std::max(1, height()),
                float(delta.y()) / std::max(1, height()));
            setView(c);
        }
    }
}

void Viewport::mouseReleaseEvent(QMouseEvent* e) {
    if (gesture_) {
        // A gizmo drag ends with its button; a key-started gesture ends with a click.
        if (gizmoHandle_) finishGesture(false);
        return;
    }
    const bool extend = e->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier);
    if (drag_ == Drag::Box) {
        drag_ = Drag::None;
        finishBox(QRect(pressPos_, e->position().toPoint()).normalized(), extend);
        return;
    }
    if (drag_ == Drag::PendingBox) {
        drag_ = Drag::None;
        if (!extend) editor_->setSelection(kNoObject);
        return;
    }
    if (drag_ == Drag::PendingObject) editor_->setSelection(dragId_);  // A click: it alone.
    finishDrag(false);
}

void Viewport::finishBox(const QRect& box, bool add) {
    Q_EMIT statusMessage({});
    const ViewProjection view = projection();
    const SceneDocument& doc = editor_->document();
    std::vector<ObjectId> ids = add ? editor_->selectedIds() : std::vector<ObjectId>{};
    const auto inside = [&](const Vec3& p) {
        const auto at = view.project(p);
        return at && box.contains(at->toPoint());
    };
    for (const Light& l : doc.lights)
        if (inside(l.position)) ids.push_back(l.id);
    // Planes are unbounded (the room's walls): a box around a ball must not take them.
    for (const Object& o : doc.objects)
        if (!std::holds_alternative<PlaneGeometry>(o.geometry) && o.visible)
            if (const auto c = entityCentre(doc, o.id); c && inside(*c)) ids.push_back(o.id);
    editor_->setSelection(ids);
    repaintOverlay();
}

void Viewport::wheelEvent(QWheelEvent* e) {
    pacing_.input(paceClock_.elapsed());  // More steps may follow: show them as they come.
    const float clicks = e->angleDelta().y() / 120.0f;
    if (clicks == 0.0f) return;
    setView(dollied(clicks, e->position()));
}

void Viewport::keyPressEvent(QKeyEvent* e) {
    const bool undoKey = e->matches(QKeySequence::Undo) || e->matches(QKeySequence::Redo);
    if (gesture_ && undoKey) {
        finishGesture(true);  // Undo mid-gesture cancels it, back to where it began.
        return;
    }
    if (drag_ != Drag::None && undoKey) {
        finishDrag(true);
        return;
    }
    if (boxArmed_ && e->key() == Qt::Key_Escape) {
        boxArmed_ = false;
        Q_EMIT statusMessage({});
        return;
    }
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
        const int axis = e->key() == Qt::Key_X   ? 0
                         : e->key() == Qt::Key_Y ? 1
                         : e->key() == Qt::Key_Z ? 2
                                                 : -1;
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
    dragIds_ = editor_->isSelected(dragId_) ? editor_->selectedIds() : std::vector{dragId_};
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
    for (ObjectId id : dragIds_) {
        restoreEntity(doc, dragStartDoc_, id);
        moveBy(doc, id, delta);
    }
    if (const auto px = pixelAt(pos)) session_->session().setFocus(px->x() + 0.5f, px->y() + 0.5f);
    dragEdit(tr("Move object"), std::move(doc), QString::number(dragId_));
}

void Viewport::dragEdit(const QString& text, SceneDocument doc, const QString& mergeKey) {
    ownEdit_ = true;
    editor_->edit(text, std::move(doc), MergeKind::Drag, mergeKey);
    ownEdit_ = false;
}

void Viewport::onUndoIndexChanged() {
    // Undo from the menu (a mouse click) while a gesture or drag runs: the undo has already
    // put the document back, so the gesture ends without restoring (or editing) anything.
    if (ownEdit_ || (!gesture_ && drag_ != Drag::Object)) return;
    abandonDrag();
}

void Viewport::finishDrag(bool cancel) {
    const Drag was = drag_;
    drag_ = Drag::None;
    if (was == Drag::Object && cancel) {
        SceneDocument doc = editor_->document();
        for (ObjectId id : dragIds_) restoreEntity(doc, dragStartDoc_, id);
        dragEdit(tr("Move object"), std::move(doc), QString::number(dragId_));
    }
    if (was == Drag::Object || was == Drag::Orbit || was == Drag::Pan) session_->endInteraction();
    if (was == Drag::Box) repaintOverlay();
    editor_->closeMerge();
}

}  // namespace rs::ui
