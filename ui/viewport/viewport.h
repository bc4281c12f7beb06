// The viewport: shows the session's frame through a view camera of its own and turns mouse
// and keys into selection (click, Ctrl/Shift-click, box), object drags, the transform gizmo,
// G/R/S gestures and view navigation.
#pragma once

#include <QPoint>
#include <QRegion>
#include <QWidget>
#include <memory>
#include <optional>

#include "display/display_choice.h"
#include "display/display_frame.h"
#include "display/frame_view.h"
#include "scene/document.h"
#include "viewport/gesture.h"
#include "viewport/light_overlay.h"
#include "viewport/modal_transform.h"
#include "viewport/mouse_drag.h"
#include "viewport/transform_gizmo.h"
#include "viewport/view_camera.h"
#include "viewport/view_posting.h"
#include "viewport/view_projection.h"
#include "viewport/viewport_pacing.h"

namespace rs::ui {

class SceneEditor;
class SessionController;
class ViewportOverlay;

/// The widget property the viewport sets while it takes every key (a drag, gesture or armed
/// box select): the window's command shortcuts (shell/command_shortcut_filter.h) leave those
/// keys alone.
inline constexpr char kTakesAllKeys[] = "raystudioTakesAllKeys";

/// Blender's numpad views (1, 3, 7; with Ctrl the opposite side).
enum class AxisView { Front, Back, Right, Left, Top, Bottom };

/// Central widget of the main window.
class Viewport : public QWidget {
    Q_OBJECT
public:
    Viewport(SceneEditor* editor, SessionController* session, QWidget* parent = nullptr,
             DisplayKind display = DisplayKind::Automatic);

    /// The frame drawer (OpenGL or raster).
    FrameView* frameView() { return view_; }
    /// Preferences → Display: replaces the frame drawer when `display` resolves to the other one.
    void setDisplay(DisplayKind display);
    /// The last frame copied from the session.
    std::shared_ptr<const DisplayFrame> frame() const { return frame_; }
    void setViewMode(ViewMode mode);
    ViewMode viewMode() const { return mode_; }
    /// Frame pixel under widget point `p`, or nullopt outside the image.
    std::optional<QPoint> pixelAt(const QPoint& p) const;
    /// Preview scale 1 / `divider` (1, 2 or 4; anything else means 1): the session traces the
    /// widget's device pixels divided by it (Blender's pixel size).
    void setPreviewDivider(int divider);
    int previewDivider() const { return posting_.divider(); }
    /// The frame size posted to the session last: tracedFrameSize() of the widget when it
    /// was posted (a resize is posted once the window edge rests, kResizeSettleMs).
    QSize tracedSize() const { return posting_.postedSize(); }
    /// How long a resize must rest before the session traces the new size.
    static constexpr int kResizeSettleMs = ViewPosting::kResizeSettleMs;
    /// Widget point at the centre of frame pixel (x, y).
    QPoint widgetPointOf(int x, int y) const;
    /// Copies the session's frame (waiting for its lock) and redraws.
    void refresh();
    /// Replaces the hand-over pace (tests slow a still frame's to an hour), counting the
    /// frame shown now as just handed over.
    void setRepaintPacing(const RepaintPacing& pacing);

    // View camera: navigation moves it, never the document (Blender's model).
    /// The camera the viewport looks through.
    const Camera& viewCamera() const { return camera_.camera(); }
    /// True while the view is the scene camera and follows its edits (the default on open).
    bool throughSceneCamera() const { return camera_.throughScene(); }
    /// The document as the session renders it: the open document seen through the view camera
    /// (fitted to the traced frame), at the viewport's traced size instead of the output size.
    SceneDocument viewDocument() const;
    /// View -> Through Scene Camera.
    void viewThroughSceneCamera();
    /// View -> Scene Camera from View: one undoable edit of the document's camera.
    void sceneCameraFromView();
    /// Looks through `camera` (a view bookmark's) as navigation would: the document and its
    /// scene camera stay as they are.
    void setView(const Camera& camera);
    /// Looks at the view's target along a world axis.
    void setAxisView(AxisView view);
    /// Aims the view at the selection from the current side, no further than the first
    /// surface behind the view (so it stays inside a room).
    void frameSelection();

    /// Starts a G / R / S gesture on the selection; false when nothing movable is selected.
    bool beginTransform(TransformKind kind);
    bool transforming() const { return gesture_.has_value(); }
    /// The light glyphs as drawn now.
    const std::vector<LightGlyph>& lightGlyphs() const { return glyphs_; }
    /// The transform gizmo about the selection as drawn now; nullopt when nothing is
    /// selected or the gizmo is hidden.
    std::optional<TransformGizmo> gizmo() const;
    /// View -> Show Gizmo.
    void setGizmoVisible(bool visible);
    bool gizmoVisible() const { return gizmoVisible_; }
    /// World (false) or local (true) axes for the gizmo and for G/R/S axis locks.
    void setLocalOrientation(bool local);
    bool localOrientation() const { return localAxes_; }
    /// B: the next left-button drag draws a selection box, even over an object.
    void beginBoxSelect();
    /// Cancels a running drag or gesture (the window closes while one runs: its edits must
    /// reach the session before the session goes).
    void cancelInteraction();
    /// The mapping from widget points to view rays for the frame shown now.
    ViewProjection projection() const;

Q_SIGNALS:
    /// A line for the status bar (the gesture's state), empty to clear it.
    void statusMessage(const QString& text);

protected:
    bool event(QEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void keyReleaseEvent(QKeyEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;
    void focusOutEvent(QFocusEvent* e) override;

private:
    void pressLeft(QMouseEvent* e);
    void startObjectDrag();
    /// Where the pressed entity is held at `px` (its centre, or a plane's point there).
    Vec3 anchorAt(const QPoint& px) const;
    void updateObjectDrag(const QPoint& pos);
    void finishDrag(bool cancel);
    void redraw();
    /// frameUpdated: copies what the session committed if its frame lock is free, and draws;
    /// while the frame is still, at pace_'s pace (its timer brings the rest).
    void showNewPixels();
    /// A drag, orbit, pan or gesture is running: every hand-over is taken.
    bool interacting() const;
    /// Shows frame_ after a hand-over that may have changed its size.
    void showHandedOver(const QSize& before);
    /// Puts `view` in the layout, with the overlay drawn by it or over it.
    void installFrameView(FrameView* view);
    /// Light glyphs, the gizmo and the selection box, in widget coordinates.
    void paintOverlay(QPainter& p) const;
    void repaintOverlay();
    /// Where paintOverlay draws glyphs, the gizmo and the selection box (not the passepartout,
    /// which changes only with the projection): the raster view repaints just that.
    QRegion overlayRegion() const;
    /// The box select's result: entities whose centre is drawn inside `box`.
    void finishBox(const QRect& box, bool add);
    /// An undo or redo that this viewport did not make, while a drag or gesture runs.
    void onUndoIndexChanged();
    /// Makes an edit of a drag or gesture (the undo guard knows it for its own).
    void dragEdit(const QString& text, SceneDocument doc, const QString& mergeKey);

    // viewport_navigation.cpp
    void onDocumentReset();
    void onDocumentChanged();
    /// Posts viewDocument() to the session at the size it traces now, and redraws.
    void postView();
    /// The orbit for a press at `pos`: about the selection's centre, else the surface under
    /// the cursor, else the view's target.
    Orbit startOrbit(const QPoint& pos) const;
    void orbitView(Orbit& orbit, const QPoint& delta);
    /// How far from `from` along unit `dir` the first surface not of `ignore` lies.
    float freeDistance(const Vec3& from, const Vec3& dir, ObjectId ignore) const;
    /// The view camera after `clicks` wheel clicks (positive: in) at widget point `cursor`:
    /// in by a tenth a click of the distance to the surface under the cursor, out by a tenth
    /// of the distance to the target, never through a surface (stopping short, as orbit).
    Camera dollied(float clicks, const QPointF& cursor) const;
    /// How far a dolly may go toward a surface `free` away.
    float dollyRoom(float free) const;

    // viewport_gesture.cpp
    bool startGesture(TransformKind kind, const QPointF& cursor,
                      const std::optional<GizmoHandle>& handle);
    void updateGesture();
    void finishGesture(bool cancel);
    /// Drops the gesture or drag without restoring anything (an undo already did).
    void abandonDrag();
    /// Tells the window's command shortcuts to leave our keys alone while a drag, gesture or
    /// armed box select runs (CommandShortcutFilter).
    void syncModal();

    SceneEditor* editor_;
    SessionController* session_;
    FrameView* view_;                 ///< The frame drawer (OpenGL or raster).
    ViewportOverlay* overlay_;        ///< The raster view's overlay widget (hidden over OpenGL).
    std::vector<LightGlyph> glyphs_;  ///< The light glyphs as drawn now.
    std::shared_ptr<const DisplayFrame> frame_;  ///< The frame handed over last.
    ViewMode mode_ = ViewMode::Color;
    HandoverPace pace_;  ///< When the session's new pixels are taken.
    ViewCamera camera_;
    ViewPosting posting_;             ///< The view's document to the session, and its size.
    MouseDrag drag_;                  ///< The held button's drag, and B's armed box.
    std::optional<Gesture> gesture_;  ///< The running G / R / S gesture.
    bool localAxes_ = false;  ///< Local axes (else the world's) for the gizmo and G/R/S locks.
    bool gizmoVisible_ = true;
    /// The viewport's own drag or gesture edit is being made (the undo guard lets it be).
    bool ownEdit_ = false;
};

}  // namespace rs::ui
