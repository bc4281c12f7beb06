// SessionErrorRelay: errors from the session's threads become queued GUI-thread calls.
#include "adapter/session_error_relay.h"

namespace rs::ui {

SessionErrorRelay::SessionErrorRelay(SessionObserver* next, QObject* context,
                                     std::function<void(const QString&)> onError)
    : next_(next), mailbox_(context), onError_(std::move(onError)) {}

void SessionErrorRelay::error(const std::string& message) {
    next_->error(message);
    // Queued: the session's scheduler thread must not touch widgets. A call queued to a
    // destroyed context is dropped.
    mailbox_.post([this, text = QString::fromStdString(message)] { onError_(text); });
}

}  // namespace rs::ui
