// Render -> Render Image jobs: each a snapshot of the document, run one at a time in the
// background while the designer stays editable, with progress and an estimate of the time left.
#pragma once

#include <QElapsedTimer>
#include <QImage>
#include <QObject>
#include <QPointer>
#include <QRect>
#include <QString>
#include <atomic>
#include <deque>
#include <memory>

#include "accel/ray_engine.h"
#include "scene/document.h"

class QThread;

namespace rs::ui {

/// Renders queued on the GUI thread, traced in a worker one at a time.
class RenderQueue : public QObject {
    Q_OBJECT
public:
    explicit RenderQueue(QObject* parent = nullptr);
    /// Cancels everything and waits for the running render's thread (cancelAll).
    ~RenderQueue() override;

    /// Queues a render of `doc` (copied now: later edits do not reach it) into `path`; it
    /// starts at once when nothing else runs.
    void enqueue(const SceneDocument& doc, const QString& path, int threads,
                 EngineKind engine = EngineKind::Embree);
    /// Stops the running render (nothing is written); the next queued one then starts.
    void cancelCurrent();
    /// Drops the queued renders, stops the running one and waits until its thread is gone
    /// (within a tile): a closing window. No finished() is emitted for any of them, only idle().
    void cancelAll();

    bool busy() const { return running_ != nullptr; }
    /// Holds the renders (their workers wait between tiles) while the user edits in the
    /// viewport, which then has the cores; released, they go on where they were. The time
    /// held is left out of the estimate of the time left.
    void setHeld(bool held);
    bool held() const { return hold_->load(); }
    /// Renders waiting behind the running one.
    int queued() const { return int(waiting_.size()); }

Q_SIGNALS:
    /// A render began: an image of width x height into `path`.
    void started(const QString& path, int width, int height);
    /// A tile of the running render, tone-mapped, at `where` in its image.
    void tileReady(const QImage& tile, const QRect& where);
    /// Tiles done of the current pass, and the seconds left (negative while unknown).
    void progressed(int done, int total, double secondsLeft);
    /// A render ended: ok when written; !ok with an empty error when cancelled.
    void finished(const QString& path, bool ok, const QString& error);
    /// Nothing runs or waits any more.
    void idle();

private:
    struct Job {
        SceneDocument doc;
        QString path;
        int threads = 0;
        EngineKind engine = EngineKind::Embree;
    };
    struct Running {
        quint64 serial = 0;  ///< Tells a late report of a cancelled render from the current one.
        QString path;
        std::shared_ptr<std::atomic<bool>> cancel;
        QPointer<QThread> thread;
        QElapsedTimer clock;
        qint64 heldMs = 0;  ///< Time held so far, not counting a hold that runs now.
    };
    std::shared_ptr<std::atomic<bool>> hold_ = std::make_shared<std::atomic<bool>>(false);
    QElapsedTimer heldSince_;
    void startNext();
    bool isCurrent(quint64 serial) const { return running_ && running_->serial == serial; }
    void onDone(quint64 serial, bool ok, const QString& error);

    std::deque<Job> waiting_;
    std::unique_ptr<Running> running_;
    quint64 serials_ = 0;
};

}  // namespace rs::ui
