// Render Image in the background, as the main window shows it: the queue of renders, the
// Render window their tiles appear in, the status-bar field with progress and Cancel, and
// the messages when one ends.
#pragma once

#include <QObject>

class QMainWindow;
class QStatusBar;

namespace rs::ui {

class RenderQueue;
class RenderStatus;
class RenderWindow;
class SessionController;

/// The designer's full-quality renders (GUI thread). The queue waits between tiles while the
/// user drags or orbits in the viewport (`session`'s interaction).
class RenderJobs : public QObject {
    Q_OBJECT
public:
    RenderJobs(SessionController* session, QMainWindow* window);

    /// Adds the progress and Cancel field, leftmost of `bar`'s permanent widgets: a running
    /// render is what the user looks for first.
    void addStatusField(QStatusBar* bar);
    /// Render -> Show Render Window.
    void showWindow();
    /// Asks before a close cancels running renders; true when none runs or the user agrees.
    bool maybeCancel();
    /// The window closes: cancels every render and closes the Render window with it.
    void closeAll();

    RenderQueue* queue() const { return queue_; }
    RenderWindow* window() const { return window_; }
    RenderStatus* status() const { return status_; }

private:
    /// A render ended: `ok`, failed with `error`, or cancelled (no error).
    void onFinished(const QString& path, bool ok, const QString& error);

    QMainWindow* owner_;
    RenderQueue* queue_;
    RenderWindow* window_;
    RenderStatus* status_ = nullptr;
};

}  // namespace rs::ui
