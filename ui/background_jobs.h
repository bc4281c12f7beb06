// Long jobs off the GUI thread: mesh import and the final-quality render, each behind a
// progress dialog, reporting back on the GUI thread.
#pragma once

#include "io/mesh_io.h"
#include "scene/document.h"

#include <QString>

#include <functional>

class QWidget;

namespace rs::ui {

/// Loads `path` in a worker thread with a busy progress dialog; `done` runs on the GUI thread
/// (not at all when the user cancelled).
void importMeshAsync(QWidget* parent, const QString& path, bool smoothNormals,
                     std::function<void(const MeshLoadResult&)> done);

/// Renders `doc` at full quality in a worker thread with a progress bar and Cancel, then
/// writes it to `path`; `done(ok, error)` runs on the GUI thread (error empty on cancel).
void renderToFileAsync(QWidget* parent, const SceneDocument& doc, const QString& path,
                       int threads, std::function<void(bool ok, const QString& error)> done);

/// Cancels every job started with `parent` and waits until their threads have stopped (a
/// closing window): no result is delivered. Returns within a tile of a render.
void cancelJobs(QWidget* parent);

}  // namespace rs::ui
