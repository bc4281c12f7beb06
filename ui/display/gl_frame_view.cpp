// GlFrameView: texture upload of the deep frame and the full-screen draw.
#include "display/gl_frame_view.h"

#include <QtCore/qfloat16.h>

#include <QElapsedTimer>
#include <QFile>
#include <QOpenGLPaintDevice>
#include <QPainter>
#include <QWidget>
#include <algorithm>

#include "scene/parameters.h"

static void initRayStudioResources() {
    Q_INIT_RESOURCE(raystudio);
}

namespace rs::ui {

namespace {
QString shaderSource(const char* path) {
    QFile f(QString::fromLatin1(path));
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll());
}

/// "#define TONEMAP_CLAMP 0" ... for every operator the schema names, so the shader's codes
/// are the ToneMap values the frame carries, written in one place (scene/parameters.cpp).
QString toneMapDefines() {
    QString out;
    const auto& names = findParameter(ParamKind::Render, "tonemap")->enumNames;
    for (std::size_t i = 0; i < names.size(); ++i)
        out += QStringLiteral("#define TONEMAP_%1 %2\n")
                   .arg(QString::fromStdString(names[i]).toUpper())
                   .arg(i);
    return out;
}

/// The fragment shader with the defines inserted after its #version line.
QString fragmentSource() {
    QString text = shaderSource(":/shaders/frame.frag");
    const qsizetype eol = text.indexOf(QLatin1Char('\n'));
    if (eol < 0) return text;
    return text.insert(eol + 1, toneMapDefines());
}
}  // namespace

GlFrameView::GlFrameView(QWidget* parent) : QOpenGLWindow(QOpenGLWindow::NoPartialUpdate) {
    initRayStudioResources();
    setFlag(Qt::WindowTransparentForInput);
    container_ = QWidget::createWindowContainer(this, parent);
    connect(this, &QOpenGLWindow::frameSwapped, this, [this] {
        painted_.composeMs = paintEnd_.nsecsElapsed() / 1e6;
        notifyPresented(painted_);
    });
}

GlFrameView::~GlFrameView() {
    if (!ready_) return;
    makeCurrent();
    glDeleteTextures(1, &colorTex_);
    glDeleteTextures(1, &idTex_);
    glDeleteTextures(1, &debugTex_);
    vao_.destroy();
    doneCurrent();
}

void GlFrameView::showFrame(std::shared_ptr<const DisplayFrame> frame, ViewMode mode,
                            const std::vector<ObjectId>& selected) {
    frame_ = std::move(frame);
    mode_ = mode;
    selected_ = selected;
    update();
}

void GlFrameView::initializeGL() {
    initializeOpenGLFunctions();
    const bool ok = program_.addShaderFromSourceCode(QOpenGLShader::Vertex,
                                                     shaderSource(":/shaders/frame.vert")) &&
                    program_.addShaderFromSourceCode(QOpenGLShader::Fragment, fragmentSource()) &&
                    program_.link();
    if (!ok) {
        qWarning("RayStudio: frame shader failed: %s", qPrintable(program_.log()));
        return;
    }
    vao_.create();
    glGenTextures(1, &colorTex_);
    glGenTextures(1, &idTex_);
    glGenTextures(1, &debugTex_);
    for (GLuint t : {colorTex_, idTex_, debugTex_}) {
        glBindTexture(GL_TEXTURE_2D, t);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    ready_ = true;
    texSize_ = {};
}

void GlFrameView::allocate(int width, int height) {
    glBindTexture(GL_TEXTURE_2D, colorTex_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16F, width, height, 0, GL_RGB, GL_HALF_FLOAT, nullptr);
    glBindTexture(GL_TEXTURE_2D, idTex_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, width, height, 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                 nullptr);
    glBindTexture(GL_TEXTURE_2D, debugTex_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    texSize_ = QSize(width, height);
    color_ = ids_ = debug_ = {};
}

std::vector<QRect> GlFrameView::stale(const Uploaded& texture) const {
    std::vector<QRect> rects;
    if (texture.frame != frame_.get() || !frame_->changedSince(texture.serial, rects))
        rects.assign(1, QRect(0, 0, frame_->width, frame_->height));
    return rects;
}

void GlFrameView::uploadColor() {
    static_assert(sizeof(Color) == 3 * sizeof(float) && sizeof(qfloat16) == sizeof(uint16_t));
    const DisplayFrame& f = *frame_;
    glBindTexture(GL_TEXTURE_2D, colorTex_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    for (const QRect& r : stale(color_)) {
        const std::size_t row = 3 * std::size_t(r.width());
        half_.resize(row * std::size_t(r.height()));
        for (int y = r.top(); y <= r.bottom(); ++y)
            qFloatToFloat16(
                reinterpret_cast<qfloat16*>(half_.data()) + row * std::size_t(y - r.top()),
                &f.color[std::size_t(y) * f.width + r.left()][0], qsizetype(row));
        glTexSubImage2D(GL_TEXTURE_2D, 0, r.x(), r.y(), r.width(), r.height(), GL_RGB,
                        GL_HALF_FLOAT, half_.data());
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    color_ = {frame_.get(), f.serial, ViewMode::Color};
}

void GlFrameView::uploadIds() {
    static_assert(sizeof(ObjectId) == sizeof(GLuint));
    const DisplayFrame& f = *frame_;
    glBindTexture(GL_TEXTURE_2D, idTex_);
    // Straight from the frame's rows: no staging copy.
    glPixelStorei(GL_UNPACK_ROW_LENGTH, f.width);
    for (const QRect& r : stale(ids_)) {
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, r.x());
        glPixelStorei(GL_UNPACK_SKIP_ROWS, r.y());
        glTexSubImage2D(GL_TEXTURE_2D, 0, r.x(), r.y(), r.width(), r.height(), GL_RED_INTEGER,
                        GL_UNSIGNED_INT, f.id.data());
    }
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    ids_ = {frame_.get(), f.serial, ViewMode::Color};
}

void GlFrameView::uploadDebug() {
    // Debug views normalise over the whole frame (depth, cost): made whole, and only while shown.
    const DisplayFrame& f = *frame_;
    if (debug_.frame == frame_.get() && debug_.serial == f.serial && debug_.mode == mode_) return;
    const QImage img = debugImage(f, mode_).convertToFormat(QImage::Format_RGBA8888);
    glBindTexture(GL_TEXTURE_2D, debugTex_);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, f.width, f.height, GL_RGBA, GL_UNSIGNED_BYTE,
                    img.constBits());
    debug_ = {frame_.get(), f.serial, mode_};
}

void GlFrameView::upload() {
    const DisplayFrame& f = *frame_;
    if (texSize_ != QSize(f.width, f.height)) allocate(f.width, f.height);
    if (mode_ == ViewMode::Color)
        uploadColor();
    else
        uploadDebug();
    if (!selected_.empty()) uploadIds();
}

void GlFrameView::paintOverlay() {
    if (!overlay_) return;
    // QPainter's GL engine over the quad; it leaves its own state, which the next paintGL
    // does not rely on (viewport, program, textures and VAO are set each time).
    const qreal dpr = devicePixelRatioF();
    glViewport(0, 0, int(width() * dpr), int(height() * dpr));
    QOpenGLPaintDevice device(size() * dpr);
    device.setDevicePixelRatio(dpr);
    QPainter painter(&device);
    overlay_(painter);
}

void GlFrameView::paintGL() {
    QElapsedTimer timer;
    timer.start();
    painted_ = {};
    glClearColor(48 / 255.0f, 48 / 255.0f, 48 / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (!ready_ || !frame_ || frame_->empty()) {
        paintOverlay();
        return;
    }
    upload();
    const qreal dpr = devicePixelRatioF();
    const QRect r = fitRect(size() * dpr, QSize(frame_->width, frame_->height));
    // GL's origin is bottom-left.
    glViewport(r.x(), int(height() * dpr) - r.y() - r.height(), r.width(), r.height());
    program_.bind();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, mode_ == ViewMode::Color ? colorTex_ : debugTex_);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, idTex_);
    program_.setUniformValue("colorTex", 0);
    program_.setUniformValue("idTex", 1);
    program_.setUniformValue("displayReady", mode_ == ViewMode::Color ? 0 : 1);
    program_.setUniformValue("tonemap", int(frame_->tonemap));
    program_.setUniformValue("exposure", frame_->exposure);
    GLuint outlined[kMaxOutlined] = {};
    const std::size_t count = std::min(selected_.size(), kMaxOutlined);
    std::copy_n(selected_.begin(), count, outlined);
    glUniform1uiv(program_.uniformLocation("selected"), GLsizei(kMaxOutlined), outlined);
    program_.setUniformValue("selectedCount", int(count));
    program_.setUniformValue(
        "outlineColor",
        QVector3D(kOutlineRgb[0] / 255.0f, kOutlineRgb[1] / 255.0f, kOutlineRgb[2] / 255.0f));
    vao_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    vao_.release();
    program_.release();
    glActiveTexture(GL_TEXTURE0);
    paintOverlay();
    painted_ = {frame_->serial, frame_->generation, timer.nsecsElapsed() / 1e6, 0.0};
    paintEnd_.start();
}

}  // namespace rs::ui
