// Long jobs off the GUI thread, reporting back on the GUI thread: mesh import behind a
// progress dialog, and the final-quality render (RenderQueue shows its progress).
#pragma once

#include <QImage>
#include <QRect>
#include <QString>
#include <atomic>
#include <functional>
#include <memory>

#include "accel/ray_engine.h"
#include "io/mesh_io.h"
#include "scene/document.h"

class QObject;
class QThread;
class QWidget;

namespace rs::ui {

/// Loads `path` in a worker thread with a busy progress dialog; `done` runs on the GUI thread
/// (not at all when the user cancelled).
void importMeshAsync(QWidget* parent, const QString& path, bool smoothNormals,
                     std::function<void(const MeshLoadResult&)> done);

/// What a render reports, each call on the receiver's thread (queued, never blocking the
/// worker). Any may be empty.
struct RenderReport {
    std::function<void(int done, int total)> progress;  ///< Tiles of the current pass.
    /// A tile of the first pass, tone-mapped to 8-bit sRGB, and where it goes in the image.
    std::function<void(const QImage& tile, const QRect& where)> tile;
    /// ok: written to the file; !ok with an empty error: cancelled (nothing written).
    std::function<void(bool ok, const QString& error)> done;
};

/// Renders `doc` at full quality in a worker thread, then writes it to `path` unless `cancel`
/// was set first; while `hold` is set its workers wait between tiles (RenderOptions::hold).
/// Reports go to `receiver`'s thread; when it is destroyed the render is cancelled and
/// waited for. Returns the worker (it deletes itself when done).
QThread* renderToFileAsync(QObject* receiver, const SceneDocument& doc, const QString& path,
                           int threads, EngineKind engine,
                           std::shared_ptr<std::atomic<bool>> cancel,
                           std::shared_ptr<const std::atomic<bool>> hold, RenderReport report);

/// Cancels every job started with `parent` and waits until their threads have stopped (a
/// closing window): no result is delivered. Returns within a tile of a render.
void cancelJobs(QWidget* parent);

}  // namespace rs::ui
