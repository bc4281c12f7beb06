// The viewport: shows the session's frame and turns mouse and keys into selection, object
// drags and camera moves on the document.
#pragma once

#include "display_frame.h"
#include "frame_view.h"
#include "scene/document.h"

#include <QPoint>
#include <QWidget>

#include <memory>
#include <optional>

namespace rs::ui {

class SceneEditor;
class SessionController;

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
    /// Widget point at the centre of frame pixel (x, y).
    QPoint widgetPointOf(int x, int y) const;
    /// Copies the session's frame and redraws.
    void refresh();
    /// Aims the camera at the selection.
    void frameSelection();

protected:
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;

private:
    enum class Drag { None, PendingObject, Object, Orbit, Pan };
    void startObjectDrag();
    void updateObjectDrag(const QPoint& pos);
    void finishDrag(bool cancel);
    Vec3 dragPoint(const QPoint& pos) const;
    void redraw();

    SceneEditor* editor_;
    SessionController* session_;
    FrameView* view_;
    std::shared_ptr<const DisplayFrame> frame_;
    ViewMode mode_ = ViewMode::Color;

    Drag drag_ = Drag::None;
    QPoint pressPos_, lastPos_;
    ObjectId dragId_ = kNoObject;
    SceneDocument dragStartDoc_;
    Vec3 anchor_{0.0f};       ///< Centre of the dragged object at press.
    Vec3 grabOffset_{0.0f};   ///< Press point on the drag plane minus the anchor.
    int axisLock_ = -1;       ///< -1 free, else 0/1/2 for X/Y/Z.
};

}  // namespace rs::ui
