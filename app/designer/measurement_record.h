// What the designer's measurement records while it drives a gesture: each posted mouse event,
// each frame presented, each document posted and pass finished, and the GUI thread's probe.
// The driver (drag_measurement.cpp) fills it; the analysis (measurement_analysis.cpp) reads it.
#pragma once

#include <QEvent>
#include <QObject>
#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

#include "adapter/session_terms.h"
#include "display/frame_view.h"

namespace rs::ui {

using MeasureClock = std::chrono::steady_clock;

inline double msBetween(MeasureClock::time_point a, MeasureClock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

/// One posted mouse event: when it was due (its event time), when the viewport had handled
/// it, and the controller's request serial after it (an edit when it went up).
struct Input {
    MeasureClock::time_point due, dispatched, handled;
    uint64_t request = 0;
};

/// A frame the viewport presented, and when.
struct Present {
    MeasureClock::time_point time;
    PresentedFrame frame;
};

/// Everything one measurement recorded, in the order it happened.
struct Recording {
    std::vector<Input> inputs;
    std::vector<Present> presents;
    std::vector<uint64_t> wholeSerials;                 ///< Whole frames handed over (ascending).
    std::vector<std::pair<uint64_t, uint64_t>> posted;  ///< (request serial, generation).
    std::vector<std::pair<MeasureClock::time_point, PassInfo>> passes;
    uint64_t completed = 0;         ///< The newest generation the session completed.
    std::vector<double> probeGaps;  ///< Gaps between the GUI thread's 1 ms probe ticks.
};

/// Notes when each mouse event reaches the viewport, to time its handling.
class DispatchRecorder : public QObject {
public:
    explicit DispatchRecorder(std::vector<Input>& inputs) : inputs_(inputs) {}
    bool eventFilter(QObject*, QEvent* e) override {
        const auto t = e->type();
        if ((t == QEvent::MouseButtonPress || t == QEvent::MouseMove ||
             t == QEvent::MouseButtonRelease) &&
            next_ < inputs_.size())
            inputs_[next_++].dispatched = MeasureClock::now();
        return false;
    }

private:
    std::vector<Input>& inputs_;
    std::size_t next_ = 0;
};

}  // namespace rs::ui
