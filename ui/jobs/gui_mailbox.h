// GuiMailbox: calls from the render threads, run on the GUI thread in the order posted.
//
// Every hand-over from a session worker, the session's scheduler or a background job to the
// widgets goes through here. The calls and their data cross under a std::mutex, and Qt's
// event queue carries only a data-free wake-up. That keeps the happens-before edge in code
// ThreadSanitizer sees: Debian's Qt is not instrumented, so a lambda queued with
// QMetaObject::invokeMethod looks to TSan like memory written on one thread and read on
// another with no synchronisation between (tests/gui tsan stage, packaging/setup.sh).
// Wake-ups coalesce: a burst of posts costs one event.
#pragma once

#include <functional>
#include <memory>

class QObject;

namespace rs::ui {

/// A copyable handle; copies post into the same mailbox, from any thread.
class GuiMailbox {
public:
    /// Calls run on `context`'s thread (the GUI thread) and are dropped, unrun, once
    /// `context` is destroyed; later posts are ignored. Construct on the GUI thread.
    explicit GuiMailbox(QObject* context);

    /// Thread-safe. `call` runs later on the context's thread, after every call posted
    /// before it (from any thread).
    void post(std::function<void()> call) const;

private:
    struct State;
    class Waker;
    std::shared_ptr<State> state_;
};

}  // namespace rs::ui
