// The status bar's report on the viewport's render: the last pass's wall time, kind, share of
// re-traced pixels and rays per second, the document updates per second, and what the
// governor turned down.
#pragma once

#include <QObject>

class QLabel;
class QStatusBar;
class QWidget;

namespace rs {
struct PassInfo;
}

namespace rs::ui {

/// The permanent status-bar fields that follow the session's passes (GUI thread).
class PassStatus : public QObject {
    Q_OBJECT
public:
    /// Adds the fields to `bar`, each as wide as its widest text; `window` owns them.
    PassStatus(QStatusBar* bar, QWidget* window);

    /// A pass finished (SessionController::passFinished).
    void showPass(const PassInfo& info);
    /// The document updates sent per second changed (SessionController::updateRateChanged).
    void showUpdateRate(double perSecond);
    /// The viewport's render failed.
    void showFailed();

private:
    QLabel* frame_;
    QLabel* ups_;
    QLabel* retraced_;
    QLabel* pass_;
    QLabel* rays_;
    QLabel* governor_;
};

}  // namespace rs::ui
