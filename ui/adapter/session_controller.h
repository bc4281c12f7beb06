// Qt adapter around RenderSession: observer callbacks become queued, coalesced signals paced
// to the display, and the frame is handed to the display without waiting on the session.
#pragma once

#include <QObject>
#include <QTimer>
#include <memory>
#include <optional>

#include "accel/ray_engine.h"
#include "adapter/committed_tiles.h"
#include "adapter/frame_pacer.h"
#include "adapter/posted_look.h"
#include "adapter/session_terms.h"
#include "adapter/update_rate.h"
#include "display/display_frame.h"
#include "display/frame_storage.h"
#include "jobs/gui_mailbox.h"

Q_DECLARE_METATYPE(rs::PassInfo)

namespace rs {
class CompiledScene;
class RenderSession;
}  // namespace rs

namespace rs::ui {

/// What the rooms outside the adapter may ask of the render session: its settings, the
/// snapshot it traces, where to trace first and which edit it has reached. The session itself
/// (its frame, its waits, its updates) stays inside the adapter.
class SessionHandle {
public:
    explicit SessionHandle(RenderSession& session) : session_(session) {}

    void setObserver(SessionObserver* observer);
    void setThreads(int threads);
    void setPolicy(const InteractionPolicy& policy);
    InteractionPolicy policy() const;
    void setEngine(EngineKind engine);
    /// Traces around frame pixel (px, py) first.
    void setFocus(float px, float py);
    /// The generation of the document posted last.
    uint64_t generation() const;
    /// The compiled scene the session traces (null before the first update).
    std::shared_ptr<const CompiledScene> snapshot() const;

private:
    RenderSession& session_;
};

/// Owns the session; lives on the GUI thread; never blocks it on rendering.
class SessionController : public QObject, public SessionObserver {
    Q_OBJECT
public:
    explicit SessionController(int threads, QObject* parent = nullptr);
    ~SessionController() override;

    /// The session's settings and snapshot (the session itself stays here).
    SessionHandle& session() { return handle_; }

    /// Posts `doc` to the session. The first request of an event-loop pass goes at once;
    /// further ones in the same pass (mouse events queued while the thread was busy) collapse
    /// into one, posted when the pass ends. The session coalesces the rest (the latest wins).
    void requestUpdate(const SceneDocument& doc);
    /// Sends a pending update now (tests and drag release use it). The session applies it on
    /// its own thread: this returns at once.
    void flushUpdate();
    /// Flushes, then waits (up to a second) until the session has applied the document
    /// posted last, and returns its snapshot: for one-off actions that need the edits in the
    /// scene (Frame Selection), never per event.
    std::shared_ptr<const CompiledScene> appliedSnapshot();
    /// beginInteraction / endInteraction on the session, flushing pending updates first.
    void beginInteraction(ObjectId moving);
    void endInteraction();

    /// Updates per second over the last second.
    double updatesPerSecond() const { return updateRate_.perSecond(); }

    /// Whether displayFrame may wait for the session's frame lock.
    enum class FrameWait { Block, TryOnly };
    /// The frame to show now (GUI thread). One frame, refreshed in place: only the tiles
    /// committed since the last call are copied, under a short lock. Exposure and tone
    /// mapping are those of the document posted last, which edits that trace nothing change.
    /// TryOnly (the repaints frameUpdated asks for): when a tile commit or an edit holds the
    /// lock, the frame is returned as it was and frameUpdated comes again shortly.
    std::shared_ptr<const DisplayFrame> displayFrame(FrameWait wait = FrameWait::Block);
    /// Whether displayFrame hands over normals and ray costs too (only while a debug view
    /// shows them). Turning it on makes the next displayFrame copy them whole: call it with
    /// FrameWait::Block then.
    void setDebugBuffers(bool on) { frame_->debugBuffers = on; }
    /// Cost of handing frames to the display, for the designer's measurement.
    struct HandoverStats {
        int count = 0;
        double totalMs = 0.0;
        double maxMs = 0.0;
        double copyMs = 0.0;  ///< Of totalMs, the part spent copying (the rest waits for the lock).
        int busy = 0;         ///< TryOnly hand-overs that found the lock held and came back later.
    };
    const HandoverStats& handoverStats() const { return handover_; }
    /// Counts requestUpdate calls; documentPosted says which generation carried them.
    uint64_t requestSerial() const { return requestSerial_; }

    // SessionObserver (worker threads).
    void tileDone(int x0, int y0, int x1, int y1, uint64_t generation) override;
    void passDone(const PassInfo& info) override;
    void frameComplete(uint64_t generation) override;

Q_SIGNALS:
    /// New pixels are in the frame: at once after a quiet spell, then at most every
    /// kMinFrameIntervalMs (the display's refresh; faster would only copy more often).
    void frameUpdated();
    /// A pass finished (GUI thread).
    void passFinished(const rs::PassInfo& info);
    /// Every pixel is final for `generation` (GUI thread).
    void frameCompleted(quint64 generation);
    /// The document of requests up to `requestSerial` went to the session as `generation`.
    void documentPosted(quint64 requestSerial, quint64 generation);
    /// displayFrame produced DisplayFrame::serial `serial`; `whole`: no pixel of it shows an
    /// older document than the rest (RenderSession::wholeMark), i.e. not a pass cut short.
    void frameHandedOver(quint64 serial, bool whole);
    /// updatesPerSecond() changed (checked once a second, including the fall to 0).
    void updateRateChanged(double updatesPerSecond);
    /// beginInteraction (true) or endInteraction (false) was called.
    void interactionChanged(bool interacting);

public:
    /// Shortest time between two frameUpdated signals.
    static constexpr int kMinFrameIntervalMs = FramePacer::kMinIntervalMs;

private:
    void onUpdateTimer();
    /// Copies `batch` into the displayed frame under the frame lock (or only tries to take it,
    /// `tryOnly`). False when it did not: the lock was held, or `onlyWhole` and the frame is
    /// not whole since `wholeMark`. Sets `whole`.
    bool copyFrame(CommittedTiles::Batch& batch, bool tryOnly, bool onlyWhole, uint64_t wholeMark,
                   bool& whole);

    friend struct SessionControllerTestAccess;  ///< The GUI tests reach the whole session.

    std::unique_ptr<RenderSession> session_;
    SessionHandle handle_{*session_};
    GuiMailbox mailbox_;  ///< Worker callbacks to the GUI thread.
    /// When frameUpdated is emitted for committed tiles.
    FramePacer pacer_{[this] { Q_EMIT frameUpdated(); }};
    QTimer updateTimer_;
    std::optional<SceneDocument> pendingDoc_;
    uint64_t requestSerial_ = 0;
    uint64_t postedGeneration_ = 0;  ///< Generation of the document posted last.
    PostedLook postedLook_;          ///< Display settings of the document posted last.
    CommittedTiles tiles_;           ///< Committed since displayFrame() last copied.
    std::shared_ptr<DisplayFrame> frame_ = std::make_shared<DisplayFrame>();
    /// Room for frames of the size posted, made off this thread before they come.
    FrameStorageMaker frameStorage_;
    uint64_t frameSessionGeneration_ = 0;  ///< Session generation at the last refresh.
    HandoverStats handover_;
    bool interacting_ = false;  ///< Between beginInteraction and endInteraction.
    UpdateRate updateRate_{[this](double rate) { Q_EMIT updateRateChanged(rate); }};
};

}  // namespace rs::ui
