// GuiMailbox: a std::mutex-guarded list of calls and one queued wake-up event per burst.
#include "jobs/gui_mailbox.h"

#include <QCoreApplication>
#include <QEvent>
#include <QObject>
#include <mutex>
#include <vector>

namespace rs::ui {

struct GuiMailbox::State {
    std::mutex mutex;
    std::vector<std::function<void()>> calls;
    Waker* waker = nullptr;  ///< Null once the context is gone; guarded by mutex.
};

/// Lives on the context's thread as its child; runs the calls when woken, and closes the
/// mailbox when the context deletes it.
class GuiMailbox::Waker : public QObject {
public:
    static QEvent::Type wakeType() {
        static const auto type = QEvent::Type(QEvent::registerEventType());
        return type;
    }

    Waker(QObject* context, std::shared_ptr<State> state)
        : QObject(context), state_(std::move(state)) {}

    ~Waker() override {
        std::vector<std::function<void()>> dropped;
        {
            std::lock_guard lock(state_->mutex);
            state_->waker = nullptr;
            dropped.swap(state_->calls);
        }
        // `dropped` is destroyed here, outside the lock: captured objects may be heavy.
    }

    bool event(QEvent* e) override {
        if (e->type() != wakeType()) return QObject::event(e);
        std::vector<std::function<void()>> calls;
        {
            std::lock_guard lock(state_->mutex);
            calls.swap(state_->calls);
        }
        // A call may delete the context (closing a window); the state outlives this object.
        const std::shared_ptr<State> keep = state_;
        for (std::function<void()>& call : calls) {
            {
                std::lock_guard lock(keep->mutex);
                if (!keep->waker) return true;
            }
            call();
        }
        return true;
    }

private:
    std::shared_ptr<State> state_;
};

GuiMailbox::GuiMailbox(QObject* context) : state_(std::make_shared<State>()) {
    state_->waker = new Waker(context, state_);
}

void GuiMailbox::post(std::function<void()> call) const {
    std::lock_guard lock(state_->mutex);
    if (!state_->waker) return;
    const bool wake = state_->calls.empty();
    state_->calls.push_back(std::move(call));
    // Posted under the lock so the waker cannot be destroyed in between; postEvent is
    // thread-safe and takes ownership of the event.
    if (wake) QCoreApplication::postEvent(state_->waker, new QEvent(Waker::wakeType()));
}

}  // namespace rs::ui
