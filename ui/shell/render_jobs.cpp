// RenderJobs: the render queue wired to its window, the status bar and the viewport's drags.
#include "shell/render_jobs.h"

#include <QMainWindow>
#include <QStatusBar>

#include "adapter/session_controller.h"
#include "jobs/render_queue.h"
#include "jobs/render_status.h"
#include "jobs/render_window.h"
#include "shell/error_reporter.h"
#include "shell/user_confirmation.h"

namespace rs::ui {

RenderJobs::RenderJobs(SessionController* session, QMainWindow* window)
    : QObject(window), owner_(window), queue_(new RenderQueue(window)) {
    // The viewport first: while the user drags or orbits, Render Image waits between tiles.
    connect(session, &SessionController::interactionChanged, queue_, &RenderQueue::setHeld);
    window_ = new RenderWindow(window);
    connect(queue_, &RenderQueue::started, this, [this](const QString& path, int w, int h) {
        window_->begin(path, w, h);
        if (!window_->isVisible()) window_->showOver(owner_);
    });
    connect(queue_, &RenderQueue::tileReady, window_, &RenderWindow::putTile);
    connect(queue_, &RenderQueue::finished, this, &RenderJobs::onFinished);
}

void RenderJobs::onFinished(const QString& path, bool ok, const QString& error) {
    if (ok) {
        window_->end(tr("done"));
        owner_->statusBar()->showMessage(tr("Rendered %1").arg(path), 5000);
    } else if (!error.isEmpty()) {
        window_->end(tr("failed"));
        reportError(owner_, tr("Cannot render image"), error);
    } else {
        window_->end(tr("cancelled"));
        owner_->statusBar()->showMessage(tr("Render cancelled"), 3000);
    }
}

void RenderJobs::addStatusField(QStatusBar* bar) {
    status_ = new RenderStatus(queue_, owner_);
    bar->insertPermanentWidget(0, status_);
}

void RenderJobs::showWindow() {
    window_->show();
    window_->raise();
}

bool RenderJobs::maybeCancel() {
    if (!queue_->busy()) return true;
    const int queued = queue_->queued();
    const QString text =
        queued
            ? tr("A render is running and %1 more are queued. Cancel them and close?").arg(queued)
            : tr("A render is running. Cancel it and close?");
    return confirm(owner_, tr("Render running"), text);
}

void RenderJobs::closeAll() {
    // A render still running would keep the process alive after the window is gone.
    queue_->cancelAll();
    window_->close();  // A window of the main window, not a reason to stay open.
}

}  // namespace rs::ui
