// Which frame view draws the viewport: OpenGL on a real GPU, QPainter on software GL or none.
#pragma once

#include <QString>

class QWidget;

namespace rs::ui {

class FrameView;

/// Preferences → Display.
enum class DisplayKind { Automatic, OpenGL, Software };

/// Storage names ("automatic", "opengl", "software") and back; false for anything else.
const char* displayKindName(DisplayKind kind);
bool parseDisplayKind(const QString& name, DisplayKind& kind);

/// True when `glRenderer` (GL_RENDERER) names a software rasteriser: Mesa's llvmpipe,
/// softpipe or swrast ("Software Rasterizer"), where every swap is a CPU copy of the whole
/// window and the fragment shader runs on the cores the ray tracer needs.
bool softwareRenderer(const QString& glRenderer);

/// The rule behind Automatic: OpenGL when a context can be made (`glRenderer` not empty) on a
/// GPU; the QPainter view on a software renderer or without OpenGL. OpenGL is honoured
/// whenever a context can be made, Software always.
bool useOpenGL(DisplayKind preference, const QString& glRenderer);

/// GL_RENDERER of a context made on this platform, empty when none can be made (offscreen
/// platform, RAYSTUDIO_NO_OPENGL set). Asked once per process; the override below wins.
QString openGLRenderer();
/// Tests pretend to have another renderer ("NVIDIA GeForce ..."); empty restores the real one.
void setOpenGLRendererOverride(const QString& renderer);

/// Makes the view `preference` resolves to, as a child of `parent`.
FrameView* createFrameView(QWidget* parent, DisplayKind preference);

}  // namespace rs::ui
