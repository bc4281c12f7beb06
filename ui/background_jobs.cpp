// Worker threads with atomic cancellation and queued progress (no GUI-thread waiting).
#include "background_jobs.h"

#include "image/image_io.h"
#include "integrator/renderer.h"
#include "snapshot/compiled_scene.h"

#include <QCoreApplication>
#include <QPointer>
#include <QProgressDialog>
#include <QThread>

#include <atomic>
#include <exception>
#include <memory>
#include <new>
#include <string>

namespace rs::ui {

namespace {

const QString kJobDialogName = QStringLiteral("backgroundJob");

/// What a worker's exception says to the user. A job's thread must never let one escape:
/// QThread would call std::terminate and take the unsaved document with it.
std::string describeFailure(std::exception_ptr failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const std::bad_alloc&) {
        return "out of memory";
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "unknown error";
    }
}

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
void startWorker(QObject* owner, std::shared_ptr<std::atomic<bool>> cancel,
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
}

}  // namespace

void importMeshAsync(QWidget* parent, const QString& path, bool smoothNormals,
                     std::function<void(const MeshLoadResult&)> done) {
    QPointer<QProgressDialog> dialog =
        makeProgress(parent, QObject::tr("Loading %1 ...").arg(path), 0);
    auto cancelled = std::make_shared<std::atomic<bool>>(false);
    QObject::connect(dialog, &QProgressDialog::canceled, dialog, [cancelled] { *cancelled = true; });
    QObject* receiver = parent ? static_cast<QObject*>(parent) : dialog.data();
    startWorker(dialog, cancelled, [=, file = path.toStdString()] {
        MeshLoadResult result;
        try {
            result = loadMesh(file, smoothNormals);
        } catch (...) {
            result = {nullptr, file + ": " + describeFailure(std::current_exception())};
        }
        QMetaObject::invokeMethod(receiver, [=] {
            if (dialog) dialog->deleteLater();
            if (!*cancelled) done(result);
        }, Qt::QueuedConnection);
    });
}

void renderToFileAsync(QWidget* parent, const SceneDocument& doc, const QString& path,
                       int threads, std::function<void(bool ok, const QString& error)> done) {
    QPointer<QProgressDialog> dialog = makeProgress(parent, QObject::tr("Rendering %1 ...").arg(path), 1);
    // Not window-modal: Qt refuses the window manager's close of a window a modal dialog
    // blocks, so the main window could not be closed during a render. The render works on
    // its own copy of the document, so editing meanwhile is harmless.
    dialog->setWindowModality(Qt::NonModal);
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    QObject::connect(dialog, &QProgressDialog::canceled, dialog, [cancel] { *cancel = true; });
    QObject* receiver = parent ? static_cast<QObject*>(parent) : dialog.data();
    startWorker(dialog, cancel, [=, file = path.toStdString()] {
        std::string error = imageSizeError(doc.render.width, doc.render.height);
        bool ok = false;
        if (error.empty()) {
            try {
                const CompiledScene scene(doc);
                RenderOptions options;
                options.threads = threads;
                options.cancel = cancel.get();
                options.progress = [receiver, dialog](int doneTiles, int total) {
                    QMetaObject::invokeMethod(receiver, [=] {
                        if (!dialog) return;
                        dialog->setMaximum(total);
                        dialog->setValue(doneTiles);
                    }, Qt::QueuedConnection);
                };
                const RenderResult result = renderImage(scene, options);
                ok = !result.cancelled &&
                     writeImage(file, result.image, doc.render.tonemap, doc.render.exposure, error);
            } catch (...) {
                error = "rendering " + file + " failed: " + describeFailure(std::current_exception());
            }
        }
        QMetaObject::invokeMethod(receiver, [=] {
            if (dialog) dialog->deleteLater();
            done(ok, QString::fromStdString(error));
        }, Qt::QueuedConnection);
    });
}

void cancelJobs(QWidget* parent) {
    // Deleting a job's dialog cancels the job and waits for its thread (startWorker).
    for (QProgressDialog* dialog :
         parent->findChildren<QProgressDialog*>(kJobDialogName, Qt::FindDirectChildrenOnly))
        delete dialog;
}

}  // namespace rs::ui
