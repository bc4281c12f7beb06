// The viewport: shows the session's frame through a view camera of its own and turns mouse
// and keys into selection, object drags, G/R/S gestures and view navigation.
#pragma once

#include "display_frame.h"
#include "frame_view.h"
#include "light_overlay.h"
#include "modal_transform.h"
#include "scene/document.h"
#include "view_projection.h"

#include <QPoint>
#include <QTimer>
#include <QWidget>

#include <memory>
#include <optional>

namespace rs::ui {

class SceneEditor;
class SessionController;

/// Blender's numpad views (1, 3, 7; with Ctrl the opposite side).
enum class AxisView { Front, Back, Right, Left, Top, Bottom };

/// Central widget of the main window.
class Viewport : public QWidget {
    Q_OBJECT
public:
    Viewport(SceneEditor* editor, SessionController* session, QWidget* parent = nullptr);

    /// The frame drawer (OpenGL or raster).
    FrameView* frameView() { return view_; }
    /// The last frame copied from the session.
    std::shared_ptr<const DisplayFrame> frame() const { return frame_; }
    void setViewMode(ViewMode mode);
    ViewMode viewMode() const { return mode_; }
    /// Frame pixel under widget point `p`, or nullopt outside the image.
    std::optional<QPoint> pixelAt(const QPoint& p) const;
    /// Preview scale 1 / `divider` (1, 2 or 4; anything else means 1): the session traces the
    /// widget's device pixels divided by it (Blender's pixel size).
    void setPreviewDivider(int divider);
    int previewDivider() const { return divider_; }
    /// The frame size posted to the session last: tracedFrameSize() of the widget when it
    /// was posted (a resize is posted once the window edge rests, kResizeSettleMs).
    QSize tracedSize() const { return tracedSize_; }
    /// How long a resize must rest before the session traces the new size.
    static constexpr int kResizeSettleMs = 120;
    /// Widget point at the centre of frame pixel (x, y).
    QPoint widgetPointOf(int x, int y) const;
    /// Copies the session's frame and redraws.
    void refresh();

    // View camera: navigation moves it, never the document (Blender's model).
    /// The camera the viewport looks through.
    const Camera& viewCamera() const { return viewCamera_; }
    /// True while the view is the scene camera and follows its edits (the default on open).
    bool throughSceneCamera() const { return throughScene_; }
    /// The document as the session renders it: the open document seen through the view camera
    /// (fitted to the traced frame), at the viewport's traced size instead of the output size.
    SceneDocument viewDocument() const;
    /// View -> Through Scene Camera.
    void viewThroughSceneCamera();
    /// View -> Scene Camera from View: one undoable edit of the document's camera.
    void sceneCameraFromView();
    /// Looks at the view's target along a world axis.
    void setAxisView(AxisView view);
    /// Aims the view at the selection from the current side, no further than the first
    /// surface behind the view (so it stays inside a room).
    void frameSelection();

    /// Starts a G / R / S gesture on the selection; false when nothing movable is selected.
    bool beginTransform(TransformKind kind);
    bool transforming() const { return gesture_.has_value(); }
    /// The light glyphs as drawn now.
    const std::vector<LightGlyph>& lightGlyphs() const { return overlay_->glyphs(); }
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
    enum class Drag { None, PendingObject, Object, Orbit, Pan };
    void startObjectDrag();
    void updateObjectDrag(const QPoint& pos);
    void finishDrag(bool cancel);
    Vec3 dragPoint(const QPoint& pos) const;
    void redraw();

    // viewport_navigation.cpp
    void onDocumentReset();
    void onDocumentChanged();
    void setView(const Camera& camera);
    void postView();
    /// tracedFrameSize() of the widget as it is now.
    QSize sizeToTrace() const;
    Vec3 orbitPivot(const QPoint& pos) const;

    // viewport_gesture.cpp
    void updateGesture();
    void finishGesture(bool cancel);
    std::vector<ObjectId> selectedIds() const;

    SceneEditor* editor_;
    SessionController* session_;
    FrameView* view_;
    LightOverlay* overlay_;
    std::shared_ptr<const DisplayFrame> frame_;
    ViewMode mode_ = ViewMode::Color;

    Camera viewCamera_;
    bool throughScene_ = true;
    Vec3 worldUp_{0.0f, 1.0f, 0.0f};
    Vec3 orbitPivot_{0.0f};

    Drag drag_ = Drag::None;
    QPoint pressPos_, lastPos_;
    ObjectId dragId_ = kNoObject;
    SceneDocument dragStartDoc_;
    Vec3 anchor_{0.0f};       ///< Centre of the dragged object at press.
    Vec3 grabOffset_{0.0f};   ///< Press point on the drag plane minus the anchor.
    int axisLock_ = -1;       ///< -1 free, else 0/1/2 for X/Y/Z.

    int divider_ = 1;
    QSize tracedSize_;     ///< Empty until the first post.
    QTimer resizeSettle_;  ///< Restarted by each resize; posts the new size when it fires.

    std::optional<ModalTransform> gesture_;
};

}  // namespace rs::ui
