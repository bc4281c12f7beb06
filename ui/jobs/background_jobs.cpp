// Worker threads with atomic cancellation and queued progress (no GUI-thread waiting).
#include "jobs/background_jobs.h"

#include <QCoreApplication>
#include <QPointer>
#include <QProgressDialog>
#include <QThread>
#include <atomic>
#include <exception>
#include <memory>
#include <string>

#include "core/failure_message.h"
#include "image/tonemap.h"
#include "integrator/render_to_file.h"
#include "jobs/gui_mailbox.h"

namespace rs::ui {

namespace {

const QString kJobDialogName = QStringLiteral("backgroundJob");

QProgressDialog* makeProgress(QWidget* parent, const QString& text, int maximum) {
    auto* dialog = new QProgressDialog(text, QObject::tr("Cancel"), 0, maximum, parent);
    dialog->setObjectName(kJobDialogName);  // cancelJobs() finds the jobs by their dialogs.
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(300);
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    dialog->setValue(0);
    return dialog;
}

/// Runs `work` on a new QThread that deletes itself when done. When `owner` is destroyed
/// (its window closes) the thread must be gone before the objects `work` reports to are:
/// `cancel` is set first so the wait ends at the work's next check, not when it completes.
/// Quitting the application sets it too, before any window is torn down.
/// `work` must catch whatever it throws (describeFailure says what it was): an exception that
/// escapes a QThread calls std::terminate and takes the unsaved document with it.
QThread* startWorker(QObject* owner, std::shared_ptr<std::atomic<bool>> cancel,
                     std::function<void()> work) {
    QThread* thread = QThread::create(std::move(work));
    QObject::connect(thread, &QThread::finished, thread, &QObject::deleteLater);
    QObject::connect(owner, &QObject::destroyed, thread, [thread, cancel] {
        *cancel = true;
        thread->wait();
    });
    if (QCoreApplication* app = QCoreApplication::instance())
        QObject::connect(app, &QCoreApplication::aboutToQuit, thread, [cancel] { *cancel = true; });
    thread->start();
    return thread;
}

/// Tile [x0, x1) x [y0, y1) of `image` as the display shows it (tone-mapped 8-bit sRGB).
QImage displayTile(const ImageRgb& image, int x0, int y0, int x1, int y1, ToneMap op,
                   float exposure) {
    QImage tile(x1 - x0, y1 - y0, QImage::Format_RGB888);
    for (int y = y0; y < y1; ++y) {
        uchar* line = tile.scanLine(y - y0);
        for (int x = x0; x < x1; ++x)
            toDisplay8(image.pixels[std::size_t(y) * std::size_t(image.width) + std::size_t(x)], op,
                       exposure, line + 3 * (x - x0));
    }
    return tile;
}

}  // namespace

void importMeshAsync(QWidget* parent, const QString& path, bool smoothNormals,
                     std::function<void(const MeshLoadResult&)> done) {
    QPointer<QProgressDialog> dialog =
        makeProgress(parent, QObject::tr("Loading %1 ...").arg(path), 0);
    auto cancelled = std::make_shared<std::atomic<bool>>(false);
    QObject::connect(dialog, &QProgressDialog::canceled, dialog,
                     [cancelled] { *cancelled = true; });
    const GuiMailbox toGui(parent ? static_cast<QObject*>(parent) : dialog.data());
    startWorker(dialog, cancelled, [=, file = path.toStdString()] {
        MeshLoadResult result;
        try {
            // Cancel stops the import child at once, not only the wait for it.
            MeshImportOptions options;
            options.cancel = cancelled.get();
            result = loadMesh(file, smoothNormals, options);
        } catch (...) {
            result = MeshLoadResult{};
            result.error = file + ": " + describeFailure(std::current_exception());
        }
        toGui.post([=] {
            if (dialog) {
                // Put away now: done() may open a modal error box, whose own event loop does
                // not run the deferred delete, and the dialog would stay on top of it, or
                // show itself there when its minimum duration ends (reset() stops that timer).
                dialog->reset();
                dialog->hide();
                dialog->deleteLater();
            }
            if (!*cancelled) done(result);
        });
    });
}

QThread* renderToFileAsync(QObject* receiver, const SceneDocument& doc, const QString& path,
                           int threads, EngineKind engine,
                           std::shared_ptr<std::atomic<bool>> cancel,
                           std::shared_ptr<const std::atomic<bool>> hold, RenderReport report) {
    const GuiMailbox toGui(receiver);
    return startWorker(receiver, cancel, [=, file = path.toStdString()] {
        std::string error;
        bool ok = false;
        try {
            RenderOptions options;
            options.threads = threads;
            options.cancel = cancel.get();
            options.hold = hold.get();
            if (report.progress)
                options.progress = [toGui, progress = report.progress](int d, int total) {
                    toGui.post([=] { progress(d, total); });
                };
            if (report.tile)
                options.tileDone = [toGui, tile = report.tile, op = doc.render.tonemap,
                                    exposure = doc.render.exposure](const ImageRgb& image, int x0,
                                                                    int y0, int x1, int y1) {
                    // Tone-mapped here, on the worker: the GUI thread only blits.
                    const QImage pixels = displayTile(image, x0, y0, x1, y1, op, exposure);
                    const QRect where(x0, y0, x1 - x0, y1 - y0);
                    toGui.post([=] { tile(pixels, where); });
                };
            ok = renderToFile(doc, engine, file, options, error);
        } catch (...) {
            error = "rendering " + file + " failed: " + describeFailure(std::current_exception());
        }
        toGui.post([=, done = report.done] {
            if (done) done(ok, QString::fromStdString(error));
        });
    });
}

void cancelJobs(QWidget* parent) {
    // Deleting a job's dialog cancels the job and waits for its thread (startWorker).
    for (QProgressDialog* dialog :
         parent->findChildren<QProgressDialog*>(kJobDialogName, Qt::FindDirectChildrenOnly))
        delete dialog;
}

}  // namespace rs::ui
