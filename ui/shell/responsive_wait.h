// Slow file work off the GUI thread: the window keeps painting and answering the window
// system while a 100,000-object scene is read or written.
#pragma once

#include <QEventLoop>
#include <QMetaObject>
#include <atomic>
#include <cstddef>
#include <exception>
#include <optional>
#include <thread>
#include <utility>

namespace rs::ui {

/// Files at least this large are read and written off the GUI thread: below it, the work
/// takes a few tens of milliseconds and a nested event loop would only add re-entrancy.
inline constexpr long long kResponsiveFileBytes = 1LL << 20;
/// Documents of at least this many objects (about 2 MB of scene file) are saved so.
inline constexpr std::size_t kResponsiveObjects = 10000;

/// Runs `work` on a thread of its own and returns its result (or rethrows its exception).
/// Meanwhile this thread runs a local event loop that paints, runs timers and answers the
/// window system, but holds back the user's input (delivered afterwards), so nothing can be
/// edited, opened or saved under the work, as a modal dialog's loop does.
template <class Work>
auto runWhileResponsive(Work work) -> decltype(work()) {
    using Result = decltype(work());
    std::optional<Result> result;
    std::exception_ptr failure;
    QEventLoop loop;
    std::thread worker([&] {
        try {
            result.emplace(work());
        } catch (...) {
            failure = std::current_exception();
        }
        // Queued: the loop quits once it runs, even if it has not started yet.
        QMetaObject::invokeMethod(
            &loop, [&loop] { loop.quit(); }, Qt::QueuedConnection);
    });
    loop.exec(QEventLoop::ExcludeUserInputEvents);
    worker.join();
    if (failure) std::rethrow_exception(failure);
    return std::move(*result);
}

}  // namespace rs::ui
