// When the viewport takes the session's new pixels: at once while the user drags, orbits or
// turns the wheel, at a slower pace while the frame is still, and at once when a pass ends.
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <cstdint>
#include <functional>

namespace rs::ui {

/// Hand-over pacing of the viewport. On two cores the GUI thread's hand-over, tone mapping and
/// painting run ahead of the session's tracers (which sit below it): while nobody looks at the
/// frame move, showing it at the display's 60 Hz as its tiles come in only takes cores from the
/// tracers. A still frame is shown at most every `stillIntervalMs` (its first tiles at once);
/// while the user interacts, or within `inputQuietMs` of a discrete input such as a wheel step,
/// every hand-over the controller offers is taken; a pass that completes is shown at once.
/// Times are milliseconds on one steady clock of the caller's (no clock is read here).
class RepaintPacing {
public:
    /// 4 hand-overs a second while still: a frame that takes less (the reference room's full
    /// frame in the viewport: 45-180 ms on two shared cores) is shown when its pass ends, so its
    /// hand-over, tone mapping and paint no longer interrupt its tracers; a slow one still
    /// shows its progress.
    static constexpr int kStillIntervalMs = 250;
    /// A wheel step's view changes keep coming for about this long after it.
    static constexpr int kInputQuietMs = 250;

    explicit RepaintPacing(int stillIntervalMs = kStillIntervalMs, int inputQuietMs = kInputQuietMs)
        : interval_(stillIntervalMs), quiet_(inputQuietMs) {}

    /// A drag, orbit, pan or gesture holds the mouse (on) or has ended (off).
    void setInteracting(bool on) { interacting_ = on; }
    /// A discrete input that changes the view at `nowMs` (a wheel step).
    void input(int64_t nowMs) { lastInput_ = nowMs; }
    /// A pass completed: its last tiles are handed over at once.
    void passCompleted() { completion_ = true; }
    /// A hand-over succeeded at `nowMs`.
    void handedOver(int64_t nowMs) {
        lastHandOver_ = nowMs;
        completion_ = false;
    }

    /// How long new pixels that arrive at `nowMs` wait before they are handed over (0: now).
    int64_t delay(int64_t nowMs) const;

private:
    int interval_;
    int quiet_;
    bool interacting_ = false;
    bool completion_ = false;
    static constexpr int64_t kNever = INT64_MIN;
    int64_t lastInput_ = kNever;
    int64_t lastHandOver_ = kNever;
};

/// RepaintPacing on a steady clock of its own, with the timer that brings a still frame's
/// next hand-over: the viewport asks it before each hand-over whether to wait.
class HandoverPace {
public:
    /// `due` is called when a hand-over that had to wait may happen.
    explicit HandoverPace(std::function<void()> due);

    /// Replaces the pace (tests slow a still frame's to an hour), counting the frame shown
    /// now as just handed over.
    void setPacing(const RepaintPacing& pacing);
    /// A discrete input that changes the view now (a wheel step).
    void input() { pacing_.input(clock_.elapsed()); }
    /// A pass completed: its last tiles are handed over at once.
    void passCompleted() { pacing_.passCompleted(); }
    /// A hand-over succeeded now.
    void handedOver() { pacing_.handedOver(clock_.elapsed()); }
    /// New pixels are ready while the user does (`interacting`) or does not drag: true when
    /// they must wait (the timer then calls `due` once the pace allows), false to take them
    /// now.
    bool waits(bool interacting);

private:
    RepaintPacing pacing_;
    QElapsedTimer clock_;
    QTimer timer_;  ///< A still frame's next hand-over.
};

}  // namespace rs::ui
