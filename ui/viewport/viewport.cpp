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

Viewport::Viewport(SceneEditor* editor, SessionController* session, QWidget* parent,
                   DisplayKind display)
    : QWidget(parent),
      editor_(editor),
      session_(session),
      overlay_(new ViewportOverlay([this](QPainter& p) { paintOverlay(p); },
                                   [this] { return overlayRegion(); }, this)),
      pace_([this] { showNewPixels(); }),
      posting_(this, session, [this] { return viewDocument(); }) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    installFrameView(createFrameView(this, display));
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setMinimumSize(320, 180);
    connect(&posting_, &ViewPosting::posted, this, &Viewport::redraw);
    connect(session_, &SessionController::frameUpdated, this, &Viewport::showNewPixels);
    // A still frame's tiles wait for the pace; the end of a pass is shown at once.
    connect(session_, &SessionController::passFinished, this, [this](const PassInfo& info) {
        if (info.cancelled) return;
        pace_.passCompleted();
        showNewPixels();
    });
    connect(editor_, &SceneEditor::selectionChanged, this, &Viewport::redraw);
    connect(editor_, &SceneEditor::documentReset, this, &Viewport::onDocumentReset);
    connect(editor_, &SceneEditor::documentChanged, this, &Viewport::onDocumentChanged);
    // The same document again: the session re-traces what shows an image saved again since.
    connect(editor_, &SceneEditor::imagesReloaded, this, &Viewport::postView);
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
    pace_.handedOver();
    showHandedOver(before);
}

void Viewport::setRepaintPacing(const RepaintPacing& pacing) {
    pace_.setPacing(pacing);
}

bool Viewport::interacting() const {
    return gesture_.has_value() || drag_.interacting();
}

void Viewport::showNewPixels() {
    if (pace_.waits(interacting())) return;
    const QSize before = frame_ ? QSize(frame_->width, frame_->height) : QSize();
    const uint64_t serial = frame_ ? frame_->serial : 0;
    const int busy = session_->handoverStats().busy;
    frame_ = session_->displayFrame(SessionController::FrameWait::TryOnly);
    // A busy lock brings frameUpdated again shortly (the pass's end still pending then).
    if (session_->handoverStats().busy == busy) pace_.handedOver();
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
    overlay_->repaintChanged(camera_.throughScene() ? projection().outputRect() : QRectF());
}

QRegion Viewport::overlayRegion() const {
    // Pens, antialiasing and the highlight ring reach a few pixels past the shapes.
    constexpr int kMargin = 4;
    QRegion r;
    for (const LightGlyph& g : glyphs_) r += glyphRegion(g, kMargin);
    if (const auto g = gizmo()) r += g->bounds().toAlignedRect();
    if (drag_.kind() == MouseDrag::Kind::Box)
        r += drag_.box().adjusted(-kMargin, -kMargin, kMargin, kMargin);
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
    if (gesture_ || drag_.active()) return;
    drag_.armBox();
    syncModal();
    Q_EMIT statusMessage(
        tr("Box select: drag a rectangle (Shift or Ctrl adds to the selection, "
           "Esc cancels)"));
}

void Viewport::paintOverlay(QPainter& p) const {
    // Through the scene camera, what lies outside the output frame is dimmed (passepartout).
    if (camera_.throughScene()) paintPassepartout(p, rect(), projection().outputRect());
    paintLightGlyphs(p, glyphs_, editor_->selectedIds());
    if (const auto g = gizmo()) g->paint(p, gesture_ ? gesture_->handle() : std::nullopt);
    if (drag_.kind() == MouseDrag::Kind::Box) {
        p.setRenderHint(QPainter::Antialiasing, false);
        p.setPen(QPen(QColor(240, 240, 240), 1.0, Qt::DashLine));
        p.setBrush(QColor(255, 255, 255, 30));
        p.drawRect(drag_.box());
    }
}

void Viewport::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    overlay_->setGeometry(rect());
    posting_.resized();
    redraw();
}

void Viewport::setPreviewDivider(int divider) {
    if (posting_.setDivider(divider)) postView();
}

ViewProjection Viewport::projection() const {
    // The frame shown, or before the first one arrives, the size posted for it.
    const QSize frameSize =
        frame_ && !frame_->empty() ? QSize(frame_->width, frame_->height) : posting_.traced();
    const RenderSettings& output = editor_->document().render;
    return ViewProjection(camera_.camera(), QSize(output.width, output.height), frameSize, size());
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
        if (gesture_ || (drag_.active() && undoKey) ||
            (drag_.boxArmed() && k->key() == Qt::Key_Escape)) {
            e->accept();
            return true;
        }
    }
    const bool handled = QWidget::event(e);
    syncModal();  // Presses, releases and keys start and end drags and gestures.
    return handled;
}

void Viewport::syncModal() {
    setProperty(kTakesAllKeys, gesture_.has_value() || drag_.active() || drag_.boxArmed());
}

void Viewport::mousePressEvent(QMouseEvent* e) {
    setFocus();
    if (gesture_) {
        finishGesture(e->button() != Qt::LeftButton);
        return;
    }
    editor_->closeMerge();
    drag_.press(e->position().toPoint());
    if (drag_.boxArmed() && e->button() != Qt::LeftButton) {
        drag_.disarmBox();  // Any other button cancels B.
        Q_EMIT statusMessage({});
        return;
    }
    if (e->button() == Qt::RightButton ||
        (e->button() == Qt::LeftButton && (e->modifiers() & Qt::AltModifier))) {
        drag_.startOrbit(startOrbit(drag_.pressPos()));
    } else if (e->button() == Qt::MiddleButton) {
        drag_.startPan();
    } else if (e->button() == Qt::LeftButton) {
        pressLeft(e);
        return;
    }
    if (drag_.kind() == MouseDrag::Kind::Orbit || drag_.kind() == MouseDrag::Kind::Pan)
        session_->beginInteraction(kNoObject);
}

void Viewport::pressLeft(QMouseEvent* e) {
    const bool extend = e->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier);
    if (drag_.boxArmed()) {
        drag_.disarmBox();
        drag_.startBox();
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
        const auto px = pixelAt(drag_.pressPos());
        id = px ? frame_->idAt(px->x(), px->y()) : kNoObject;
    }
    if (id == kNoObject) {
        // Empty space: a drag draws a box, a click clears the selection.
        drag_.pressEmpty();
        return;
    }
    if (extend) {
        editor_->toggleSelected(id);
        return;
    }
    // Pressing one of several selected keeps the group, so a drag moves them all; a click
    // without a drag selects it alone (on release).
    if (!editor_->isSelected(id)) editor_->setSelection(id);
    drag_.pressEntity(id);
}

void Viewport::mouseMoveEvent(QMouseEvent* e) {
    const QPoint pos = e->position().toPoint();
    const QPoint delta = drag_.moveTo(pos);
    if (gesture_) {
        gesture_->transform().setCursor(e->position(), e->modifiers() & Qt::ControlModifier);
        updateGesture();
        return;
    }
    using Kind = MouseDrag::Kind;
    const bool moved = drag_.pastThreshold();
    if (drag_.kind() == Kind::PendingObject && moved) startObjectDrag();
    if (drag_.kind() == Kind::PendingBox && moved) drag_.startBox();
    if (drag_.kind() == Kind::Box) {
        repaintOverlay();
    } else if (drag_.kind() == Kind::Object) {
        updateObjectDrag(pos);
    } else if (Orbit* orbit = drag_.orbit()) {
        orbitView(*orbit, delta);
    } else if (drag_.kind() == Kind::Pan) {
        Camera c = camera_.camera();
        pan(c, float(delta.x()) / std::max(1, height()), float(delta.y()) / std::max(1, height()));
        setView(c);
    }
}

void Viewport::mouseReleaseEvent(QMouseEvent* e) {
    if (gesture_) {
        // A gizmo drag ends with its button; a key-started gesture ends with a click.
        if (gesture_->handle()) finishGesture(false);
        return;
    }
    const bool extend = e->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier);
    if (drag_.kind() == MouseDrag::Kind::Box) {
        const QPoint press = drag_.pressPos();
        drag_.finish();
        finishBox(QRect(press, e->position().toPoint()).normalized(), extend);
        return;
    }
    if (drag_.kind() == MouseDrag::Kind::PendingBox) {
        drag_.finish();
        if (!extend) editor_->setSelection(kNoObject);
        return;
    }
    if (drag_.kind() == MouseDrag::Kind::PendingObject)
        editor_->setSelection(drag_.pressedEntity());  // A click: it alone.
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
    pace_.input();  // More steps may follow: show them as they come.
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
    if (drag_.active() && undoKey) {
        finishDrag(true);
        return;
    }
    if (drag_.boxArmed() && e->key() == Qt::Key_Escape) {
        drag_.disarmBox();
        Q_EMIT statusMessage({});
        return;
    }
    if (gesture_) {
        switch (gesture_->transform().keyPress(e->key(), e->text())) {
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
                    gesture_->transform().setSnap(true);
                    updateGesture();
                }
                return;  // Nothing else happens mid-gesture.
        }
    }
    if (ObjectDrag* objects = drag_.objects()) {
        const int axis = e->key() == Qt::Key_X   ? 0
                         : e->key() == Qt::Key_Y ? 1
                         : e->key() == Qt::Key_Z ? 2
                                                 : -1;
        if (axis >= 0) {
            objects->toggleAxis(axis);
            updateObjectDrag(drag_.lastPos());
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
        gesture_->transform().setSnap(false);
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
    const auto px = pixelAt(drag_.pressPos());
    if (!px) {
        drag_.finish();
        return;
    }
    const ObjectId id = drag_.pressedEntity();
    SceneDocument start = editor_->document();
    std::vector<ObjectId> ids = editor_->isSelected(id) ? editor_->selectedIds() : std::vector{id};
    const Vec3 anchor = anchorAt(*px);
    drag_.startObjects(
        ObjectDrag(id, std::move(ids), std::move(start), anchor, projection(), drag_.pressPos()));
    session_->beginInteraction(id);
}

Vec3 Viewport::anchorAt(const QPoint& px) const {
    const ObjectId id = drag_.pressedEntity();
    if (const Light* l = editor_->document().findLight(id)) return l->position;
    const auto snapshot = session_->session().snapshot();
    const Aabb bounds = snapshot ? snapshot->objectBounds(id) : Aabb{};
    const std::size_t i = std::size_t(px.y()) * frame_->width + px.x();
    const Ray ray = projection().pixelRay(px.x(), px.y());
    const float depth = i < frame_->depth.size() ? frame_->depth[i] : kInfinity;
    const Vec3 hit = ray.at(std::isfinite(depth) ? depth : 1.0f);
    // Planes are unbounded: drag them through the point that was clicked.
    return bounds.empty() ? hit : bounds.center();
}

void Viewport::updateObjectDrag(const QPoint& pos) {
    const ObjectDrag* objects = drag_.objects();
    SceneDocument doc = objects->moved(editor_->document(), projection(), pos);
    if (const auto px = pixelAt(pos)) session_->session().setFocus(px->x() + 0.5f, px->y() + 0.5f);
    dragEdit(tr("Move object"), std::move(doc), QString::number(objects->pressed()));
}

void Viewport::dragEdit(const QString& text, SceneDocument doc, const QString& mergeKey) {
    ownEdit_ = true;
    editor_->edit(text, std::move(doc), MergeKind::Drag, mergeKey);
    ownEdit_ = false;
}

void Viewport::onUndoIndexChanged() {
    // Undo from the menu (a mouse click) while a gesture or drag runs: the undo has already
    // put the document back, so the gesture ends without restoring (or editing) anything.
    if (ownEdit_ || (!gesture_ && drag_.kind() != MouseDrag::Kind::Object)) return;
    abandonDrag();
}

void Viewport::finishDrag(bool cancel) {
    const bool interacted = drag_.interacting(), box = drag_.kind() == MouseDrag::Kind::Box;
    const std::optional<ObjectDrag> objects = drag_.finish();
    if (objects && cancel)
        dragEdit(tr("Move object"), objects->restored(editor_->document()),
                 QString::number(objects->pressed()));
    if (interacted) session_->endInteraction();
    if (box) repaintOverlay();
    editor_->closeMerge();
}

}  // namespace rs::ui
