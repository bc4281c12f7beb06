// The OpenGL frame view: HDR and id textures on a full-screen quad; tone mapping and the
// selection outline in the fragment shader (thesis 3.3). Textures are kept between frames and
// only the rectangles the frame reports as changed are uploaded. It is a native child window
// that swaps by itself: a QOpenGLWidget would make every repaint compose the whole main
// window through OpenGL, which with software GL cost more than the rest of the frame.
#pragma once

#include <QElapsedTimer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWindow>

#include "display/frame_view.h"

namespace rs::ui {

/// Uploads the frame as textures and lets the shader do the per-pixel display work. Input
/// passes through the window to the widgets under it (the viewport).
class GlFrameView : public QOpenGLWindow, public FrameView, protected QOpenGLExtraFunctions {
    Q_OBJECT
public:
    /// Makes the window and its container, a child of `parent` that owns the window.
    explicit GlFrameView(QWidget* parent);
    ~GlFrameView() override;
    QWidget* widget() override { return container_; }
    void showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                   const std::vector<ObjectId>& selected) override;
    QImage grabImage() override { return grabFramebuffer(); }
    bool usesOpenGL() const override { return true; }
    void setOverlayPainter(std::function<void(QPainter&)> painter) override {
        overlay_ = std::move(painter);
    }
    void repaintOverlay() override { update(); }
    /// The next paint uploads the whole frame again instead of what changed (tests compare
    /// the two pictures).
    void forgetUploads() {
        color_ = ids_ = debug_ = {};
        update();
    }

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    /// What one texture holds: the frame and serial it was last brought up to date with.
    struct Uploaded {
        const DisplayFrame* frame = nullptr;
        uint64_t serial = 0;
        ViewMode mode = ViewMode::Color;
    };
    void upload();
    /// The overlay painter's drawing (light glyphs) over whatever paintGL drew.
    void paintOverlay();
    void allocate(int width, int height);
    /// The rectangles of `frame_` that `texture` lacks (all of it when it cannot tell).
    std::vector<QRect> stale(const Uploaded& texture) const;
    void uploadColor();
    void uploadIds();
    void uploadDebug();

    QWidget* container_ = nullptr;
    std::shared_ptr<const DisplayFrame> frame_;
    ViewMode mode_ = ViewMode::Color;
    std::vector<ObjectId> selected_;
    QOpenGLShaderProgram program_;
    QOpenGLVertexArrayObject vao_;
    /// Linear HDR colour as RGB16F: half precision is far below an 8-bit display step.
    GLuint colorTex_ = 0;
    GLuint idTex_ = 0;     ///< Object ids (R32UI), read only for the selection outline.
    GLuint debugTex_ = 0;  ///< A debug view as 8-bit RGBA, made on the CPU while shown.
    QSize texSize_;
    Uploaded color_, ids_, debug_;
    std::vector<uint16_t> half_;  ///< Staging for colour rectangles (qfloat16 bits).
    bool ready_ = false;
    PresentedFrame painted_;  ///< What the last paintGL drew, reported once it is swapped.
    QElapsedTimer paintEnd_;
    std::function<void(QPainter&)> overlay_;
};

}  // namespace rs::ui
