// Carries the render session's error() callback to the GUI thread. It sits between the
// session and SessionController (whose other callbacks it forwards unchanged), so the
// controller itself needs no change to report a failed render.
#pragma once

#include <QString>
#include <functional>

#include "jobs/gui_mailbox.h"
#include "session/session_observer.h"

namespace rs::ui {

/// A SessionObserver that forwards to `next` and queues errors to `onError` on `context`'s
/// thread (construct it there). Must outlive the session it observes (declare it before the
/// session's owner).
class SessionErrorRelay : public SessionObserver {
public:
    SessionErrorRelay(SessionObserver* next, QObject* context,
                      std::function<void(const QString& message)> onError);

    void tileDone(int x0, int y0, int x1, int y1, uint64_t generation) override {
        next_->tileDone(x0, y0, x1, y1, generation);
    }
    void passDone(const PassInfo& info) override { next_->passDone(info); }
    void frameComplete(uint64_t generation) override { next_->frameComplete(generation); }
    void error(const std::string& message) override;

private:
    SessionObserver* next_;
    GuiMailbox mailbox_;  ///< To context's thread.
    std::function<void(const QString&)> onError_;
};

}  // namespace rs::ui
