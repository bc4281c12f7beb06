// The Display preference's rule: software GL gets the QPainter view (measured in
// tests/bench/measure-designer.sh: with llvmpipe the OpenGL view's shader and whole-window
// swaps took more CPU than the ray tracer).
#include "display/display_choice.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <optional>

#include "display/gl_frame_view.h"
#include "display/raster_frame_view.h"

namespace rs::ui {

namespace {
std::optional<QString>& rendererOverride() {
    static std::optional<QString> value;
    return value;
}

QString queryRenderer() {
    const QString platform = QGuiApplication::platformName();
    if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal") ||
        qEnvironmentVariableIsSet("RAYSTUDIO_NO_OPENGL"))
        return {};
    QOpenGLContext context;
    if (!context.create()) return {};
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    if (!context.makeCurrent(&surface)) return {};
    const auto* name = reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
    // A context that cannot even name its renderer still draws: call it a GPU of no name.
    QString renderer = name && *name ? QString::fromUtf8(name) : QStringLiteral("unknown");
    context.doneCurrent();
    return renderer;
}
}  // namespace

const char* displayKindName(DisplayKind kind) {
    switch (kind) {
        case DisplayKind::OpenGL:
            return "opengl";
        case DisplayKind::Software:
            return "software";
        case DisplayKind::Automatic:
            break;
    }
    return "automatic";
}

bool parseDisplayKind(const QString& name, DisplayKind& kind) {
    for (DisplayKind k : {DisplayKind::Automatic, DisplayKind::OpenGL, DisplayKind::Software})
        if (name == QLatin1String(displayKindName(k))) {
            kind = k;
            return true;
        }
    return false;
}

bool softwareRenderer(const QString& glRenderer) {
    for (const char* s : {"llvmpipe", "softpipe", "swrast", "software rasterizer"})
        if (glRenderer.contains(QLatin1String(s), Qt::CaseInsensitive)) return true;
    return false;
}

bool useOpenGL(DisplayKind preference, const QString& glRenderer) {
    if (glRenderer.isEmpty() || preference == DisplayKind::Software) return false;
    return preference == DisplayKind::OpenGL || !softwareRenderer(glRenderer);
}

QString openGLRenderer() {
    if (rendererOverride()) return *rendererOverride();
    static const QString renderer = queryRenderer();
    return renderer;
}

void setOpenGLRendererOverride(const QString& renderer) {
    if (renderer.isEmpty())
        rendererOverride().reset();
    else
        rendererOverride() = renderer;
}

FrameView* createFrameView(QWidget* parent, DisplayKind preference) {
    if (useOpenGL(preference, openGLRenderer())) return new GlFrameView(parent);
    return new RasterFrameView(parent);
}

}  // namespace rs::ui
