// When the display hears that new pixels are in the frame: at once after a quiet spell, then
// at most every kMinIntervalMs (the display's refresh; faster would only copy more often).
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <atomic>
#include <functional>

namespace rs::ui {

/// Paces SessionController::frameUpdated. announce() is called on worker threads, the rest on
/// the GUI thread.
class FramePacer {
public:
    /// Shortest time between two calls of `due`.
    static constexpr int kMinIntervalMs = 16;

    /// `due` runs on the GUI thread when the display should take new pixels.
    explicit FramePacer(std::function<void()> due);

    /// Worker threads: tiles were committed. True for the first since `due` last ran: the
    /// caller then has schedule() run on the GUI thread.
    bool announce() { return !pending_.exchange(true); }
    /// `due` now, or when kMinIntervalMs have passed since it last ran.
    void schedule();
    /// A hand-over found the frame busy: `due` again in `ms`, whether or not tiles come.
    void retry(int ms);

private:
    void fire();

    std::function<void()> due_;
    std::atomic<bool> pending_{false};  ///< Announced, and `due` has not run since.
    QTimer timer_;
    QElapsedTimer lastDue_;  ///< Since `due` last ran.
};

}  // namespace rs::ui
