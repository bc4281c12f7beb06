// Helpers shared by the GUI tests: isolated settings, waiting for a final frame, finding ids.
#pragma once

#include <QColor>
#include <QCoreApplication>
#include <QFileInfo>
#include <QImage>
#include <QSettings>
#include <QStandardPaths>
#include <QString>
#include <QTest>
#include <chrono>
#include <filesystem>
#include <memory>

#include "adapter/session_controller.h"
#include "display/display_frame.h"
#include "document/scene_editor.h"
#include "panels/image_preview.h"
#include "session/render_session.h"
#include "shell/main_window.h"
#include "viewport/view_projection.h"
#include "viewport/viewport.h"

namespace rs::ui {

/// The controller hands the rest of the designer a SessionHandle; the tests look behind it.
struct SessionControllerTestAccess {
    static RenderSession& session(SessionController& c) { return *c.session_; }
};

}  // namespace rs::ui

namespace rs::ui::test {

/// The window's whole render session (its frame, its waits), which only the adapter holds.
inline RenderSession& renderSession(MainWindow& w) {
    return SessionControllerTestAccess::session(*w.session());
}

/// Keeps tests away from the user's settings.
inline void isolateSettings() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("RayStudioTests"));
    // One settings file per test program, emptied when it starts: the programs ran with what
    // others left (a saved window geometry, the OpenGL display) and, under ctest -j, beside
    // them. Settings still carry over between the cases of one program, as in the designer.
    const QString program = QFileInfo(QCoreApplication::applicationFilePath()).baseName();
    QCoreApplication::setApplicationName(QStringLiteral("RayStudioGuiTests-") + program);
    QSettings().clear();
}

inline QString scenePath(const char* name) {
    return QStringLiteral(RAYSTUDIO_SCENES_DIR "/") + QString::fromLatin1(name);
}

/// A 4 x 4 PNG of one colour, dated `age` seconds from now (each version its own stamp, as a
/// paint program saving the file again gives it).
inline bool writeFlat(const QString& path, const QColor& c, int age) {
    QImage image(4, 4, QImage::Format_RGB888);
    image.fill(c);
    if (!image.save(path, "PNG")) return false;
    namespace fs = std::filesystem;
    const fs::path file = path.toStdString();
    fs::last_write_time(file, fs::file_time_type::clock::now() + std::chrono::seconds(age));
    return true;
}

/// Waits (test-only) until no image preview under `root` is still reading its file: previews
/// are made on a thread of their own and arrive through the event loop.
inline bool previewsRead(QWidget& root) {
    return QTest::qWaitFor(
        [&] {
            for (const ImagePreview* p : root.findChildren<ImagePreview*>())
                if (p->reading()) return false;
            return true;
        },
        20000);
}

/// Sends pending document updates and waits (test-only) until the frame is final, then
/// lets the viewport copy it.
inline bool settle(MainWindow& w) {
    w.session()->flushUpdate();
    const bool ok = renderSession(w).waitUntilComplete(std::chrono::seconds(60));
    w.viewport()->refresh();
    return ok;
}

/// Waits until the viewport has been laid out at `widget` and the session traces
/// tracedFrameSize(widget, its preview divider) (a resize is posted once it rests), then settles.
inline bool settleAtViewportSize(MainWindow& w, const QSize& widget) {
    Viewport* v = w.viewport();
    const bool laidOut = QTest::qWaitFor(
        [&] {
            return v->size() == widget &&
                   v->tracedSize() ==
                       tracedFrameSize(widget * v->devicePixelRatioF(), v->previewDivider());
        },
        5000);
    return laidOut && settle(w);
}

/// Sizes the viewport at `widget` pixels and preview scale 1 / `divider`, as a user resizing
/// the window and choosing the scale in Preferences would (fixed, so the main window's
/// layout keeps it), and waits until the frame of that size is final.
inline bool traceViewport(MainWindow& w, const QSize& widget, int divider) {
    w.viewport()->setFixedSize(widget);
    w.viewport()->setPreviewDivider(divider);
    return settleAtViewportSize(w, widget);
}

/// A shown, active main window on the reference room with a 160x90 frame (a 320x180 viewport
/// at preview scale 1/2, the output also 160x90), refined to final: the starting point of
/// most designer tests.
inline bool openRoomWindow(std::unique_ptr<MainWindow>& window) {
    window = std::make_unique<MainWindow>();
    window->resize(1000, 700);
    // Before the first post: the session never traces the big default viewport.
    window->viewport()->setFixedSize(320, 180);
    window->viewport()->setPreviewDivider(2);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get())) return false;
    window->activateWindow();
    if (!QTest::qWaitForWindowActive(window.get())) return false;
    if (!window->openFile(scenePath("reference-room.scene.json"))) return false;
    window->setRenderSize(160, 90);
    return settleAtViewportSize(*window, QSize(320, 180));
}

/// The id of the object named `name` (kNoObject when absent).

inline ObjectId idOf(const MainWindow& w, const std::string& name) {
    for (const Object& o : w.editor()->document().objects)
        if (o.name == name) return o.id;
    return kNoObject;
}

/// A vector as "(x, y, z)", for test messages.
inline QString str(const Vec3& v) {
    return QStringLiteral("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z);
}

/// Centre of the pixels showing `id` in the viewport's frame (x, y), or (-1, -1).
inline std::pair<int, int> pixelOf(const DisplayFrame& f, ObjectId id) {
    long sx = 0, sy = 0, n = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            if (f.idAt(x, y) == id) sx += x, sy += y, ++n;
    if (n == 0) return {-1, -1};
    return {int(sx / n), int(sy / n)};
}

}  // namespace rs::ui::test
