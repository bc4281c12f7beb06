// The OpenGL frame view: HDR and id textures on a full-screen quad; tone mapping and the
// selection outline in the fragment shader (thesis 3.3).
#pragma once

#include "frame_view.h"

#include <QElapsedTimer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>

namespace rs::ui {

/// Uploads the frame as textures and lets the shader do the per-pixel display work.
class GlFrameView : public QOpenGLWidget, public FrameView, protected QOpenGLExtraFunctions {
    Q_OBJECT
public:
    explicit GlFrameView(QWidget* parent = nullptr);
    ~GlFrameView() override;
    QWidget* widget() override { return this; }
    void showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                   ObjectId selected) override;
    QImage grabImage() override { return grabFramebuffer(); }
    bool usesOpenGL() const override { return true; }

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    void upload();

    std::shared_ptr<const DisplayFrame> frame_;
    ViewMode mode_ = ViewMode::Color;
    ObjectId selected_ = kNoObject;
    bool dirty_ = false;
    QOpenGLShaderProgram program_;
    QOpenGLVertexArrayObject vao_;
    GLuint colorTex_ = 0;
    GLuint idTex_ = 0;
    bool ready_ = false;
    PresentedFrame painted_;  ///< What the last paintGL drew, reported once it is swapped.
    QElapsedTimer paintEnd_;
};

}  // namespace rs::ui
