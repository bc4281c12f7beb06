// GlFrameView: texture upload of the deep frame and the full-screen draw.
#include "gl_frame_view.h"

#include <QElapsedTimer>
#include <QFile>

static void initRayStudioResources() { Q_INIT_RESOURCE(raystudio); }

namespace rs::ui {

namespace {
QString shaderSource(const char* path) {
    QFile f(QString::fromLatin1(path));
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll());
}
}  // namespace

GlFrameView::GlFrameView(QWidget* parent) : QOpenGLWidget(parent) {
    initRayStudioResources();
    connect(this, &QOpenGLWidget::frameSwapped, this, [this] {
        painted_.composeMs = paintEnd_.nsecsElapsed() / 1e6;
        notifyPresented(painted_);
    });
}

GlFrameView::~GlFrameView() {
    if (!ready_) return;
    makeCurrent();
    glDeleteTextures(1, &colorTex_);
    glDeleteTextures(1, &idTex_);
    vao_.destroy();
    doneCurrent();
}

void GlFrameView::showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                            ObjectId selected) {
    frame_ = std::move(frame);
    mode_ = mode;
    selected_ = selected;
    dirty_ = true;
    update();
}

void GlFrameView::initializeGL() {
    initializeOpenGLFunctions();
    const bool ok =
        program_.addShaderFromSourceCode(QOpenGLShader::Vertex, shaderSource(":/shaders/frame.vert")) &&
        program_.addShaderFromSourceCode(QOpenGLShader::Fragment, shaderSource(":/shaders/frame.frag")) &&
        program_.link();
    if (!ok) {
        qWarning("RayStudio: frame shader failed: %s", qPrintable(program_.log()));
        return;
    }
    vao_.create();
    glGenTextures(1, &colorTex_);
    glGenTextures(1, &idTex_);
    for (GLuint t : {colorTex_, idTex_}) {
        glBindTexture(GL_TEXTURE_2D, t);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    ready_ = true;
    dirty_ = true;
}

void GlFrameView::upload() {
    const DisplayFrame& f = *frame_;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, colorTex_);
    if (mode_ == ViewMode::Color) {
        static_assert(sizeof(Color) == 3 * sizeof(float));
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, f.width, f.height, 0, GL_RGB, GL_FLOAT,
                     f.color.data());
    } else {
        const QImage img = debugImage(f, mode_).convertToFormat(QImage::Format_RGBA8888);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, f.width, f.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     img.constBits());
    }
    glBindTexture(GL_TEXTURE_2D, idTex_);
    static_assert(sizeof(ObjectId) == sizeof(GLuint));
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, f.width, f.height, 0, GL_RED_INTEGER,
                 GL_UNSIGNED_INT, f.id.data());
}

void GlFrameView::paintGL() {
    QElapsedTimer timer;
    timer.start();
    painted_ = {};
    glClearColor(48 / 255.0f, 48 / 255.0f, 48 / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (!ready_ || !frame_ || frame_->empty()) return;
    if (dirty_) {
        upload();
        dirty_ = false;
    }
    const qreal dpr = devicePixelRatioF();
    const QRect r = fitRect(size() * dpr, QSize(frame_->width, frame_->height));
    // GL's origin is bottom-left.
    glViewport(r.x(), int(height() * dpr) - r.y() - r.height(), r.width(), r.height());
    program_.bind();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, colorTex_);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, idTex_);
    program_.setUniformValue("colorTex", 0);
    program_.setUniformValue("idTex", 1);
    program_.setUniformValue("displayReady", mode_ == ViewMode::Color ? 0 : 1);
    program_.setUniformValue("tonemap", int(frame_->tonemap));
    program_.setUniformValue("exposure", frame_->exposure);
    glUniform1ui(program_.uniformLocation("selected"), selected_);
    program_.setUniformValue("outlineColor", QVector3D(kOutlineRgb[0] / 255.0f,
                                                       kOutlineRgb[1] / 255.0f,
                                                       kOutlineRgb[2] / 255.0f));
    vao_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    vao_.release();
    program_.release();
    glActiveTexture(GL_TEXTURE0);
    painted_ = {frame_->serial, frame_->generation, timer.nsecsElapsed() / 1e6, 0.0};
    paintEnd_.start();
}

}  // namespace rs::ui
