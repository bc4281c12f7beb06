// One worker at a time: the renders share the cores with the viewport's session already.
#include "jobs/render_queue.h"

#include <QThread>

#include "jobs/background_jobs.h"

namespace rs::ui {

RenderQueue::RenderQueue(QObject* parent) : QObject(parent) {}

RenderQueue::~RenderQueue() {
    blockSignals(true);  // Whoever listens may be half torn down with the window.
    cancelAll();
}

void RenderQueue::enqueue(const SceneDocument& doc, const QString& path, int threads,
                          EngineKind engine) {
    waiting_.push_back({doc, path, threads, engine});
    if (!running_) startNext();
}

void RenderQueue::setHeld(bool held) {
    if (held == hold_->load()) return;
    hold_->store(held);
    if (held) {
        heldSince_.start();
    } else if (running_ && heldSince_.isValid()) {
        running_->heldMs += heldSince_.elapsed();
    }
}

void RenderQueue::cancelCurrent() {
    if (running_) *running_->cancel = true;
}

void RenderQueue::cancelAll() {
    waiting_.clear();
    if (!running_) return;
    *running_->cancel = true;
    // Its reports still queued find no current render and are dropped (isCurrent).
    const QPointer<QThread> thread = running_->thread;
    running_.reset();
    if (thread) thread->wait();
    Q_EMIT idle();
}

void RenderQueue::startNext() {
    if (waiting_.empty()) {
        Q_EMIT idle();
        return;
    }
    const Job job = std::move(waiting_.front());
    waiting_.pop_front();
    running_ = std::make_unique<Running>();
    running_->serial = ++serials_;
    running_->path = job.path;
    running_->cancel = std::make_shared<std::atomic<bool>>(false);
    running_->clock.start();
    const quint64 self = running_->serial;
    Q_EMIT started(job.path, job.doc.render.width, job.doc.render.height);

    RenderReport report;
    report.progress = [this, self](int done, int total) {
        if (!isCurrent(self)) return;  // A cancelled render's late report.
        // Linear in tiles: tiles of one image cost alike on average, and the estimate
        // settles as more of them are done.
        const qint64 holding = hold_->load() && heldSince_.isValid() ? heldSince_.elapsed() : 0;
        const double seconds =
            double(running_->clock.elapsed() - running_->heldMs - holding) / 1000.0;
        const double left = done > 0 ? seconds * double(total - done) / double(done) : -1.0;
        Q_EMIT progressed(done, total, left);
    };
    report.tile = [this, self](const QImage& tile, const QRect& where) {
        if (isCurrent(self)) Q_EMIT tileReady(tile, where);
    };
    report.done = [this, self](bool ok, const QString& error) { onDone(self, ok, error); };
    running_->thread = renderToFileAsync(this, job.doc, job.path, job.threads, job.engine,
                                         running_->cancel, hold_, std::move(report));
}

void RenderQueue::onDone(quint64 serial, bool ok, const QString& error) {
    if (!isCurrent(serial)) return;  // Dropped by cancelAll().
    const QString path = running_->path;
    running_.reset();
    Q_EMIT finished(path, ok, error);
    startNext();
}

}  // namespace rs::ui
