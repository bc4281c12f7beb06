// Document updates per second, as the status bar shows them: counted over each second.
#pragma once

#include <QTimer>
#include <functional>

namespace rs::ui {

/// Counts updates and, once a second, takes the count as the rate. GUI thread.
class UpdateRate {
public:
    /// `changed` runs with the new rate whenever a second's count differs from the last,
    /// including the fall to 0.
    explicit UpdateRate(std::function<void(double perSecond)> changed);

    /// One update was posted.
    void count() { ++thisSecond_; }
    /// Updates over the last whole second.
    double perSecond() const { return perSecond_; }

private:
    void onSecond();

    std::function<void(double)> changed_;
    int thisSecond_ = 0;
    double perSecond_ = 0.0;
    QTimer timer_;
};

}  // namespace rs::ui
