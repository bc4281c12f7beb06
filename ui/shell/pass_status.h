// The status bar's report on the viewport's render: the last pass's wall time, kind, share of
// re-traced pixels and rays per second, the document updates per second, what the governor
// turned down, and images the render could not open.
#pragma once

#include <QObject>
#include <set>
#include <string>
#include <vector>

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

    /// The images the traced scene could not open (CompiledScene::problems(), each
    /// "/pointer: why"): those not said before go to stderr and the status bar (a texture
    /// deleted or broken on disk after the scene was opened, or one chosen in the designer).
    /// Each key is said once until it is mended.
    void showImageProblems(const std::vector<std::string>& problems);
    /// Keys the user was already told of (the warnings of the scene just opened); replaces
    /// those of an earlier scene.
    void imageProblemsSaid(std::set<std::string> pointers) { saidProblems_ = std::move(pointers); }

private:
    QStatusBar* bar_;
    std::set<std::string> saidProblems_;
    QLabel* frame_;
    QLabel* ups_;
    QLabel* retraced_;
    QLabel* pass_;
    QLabel* rays_;
    QLabel* governor_;
};

}  // namespace rs::ui
