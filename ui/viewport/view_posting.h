// The viewport's document on its way to the session, at the size the session traces for it.
#pragma once

#include <QObject>
#include <QSize>
#include <QTimer>
#include <functional>

#include "scene/document.h"

class QWidget;

namespace rs::ui {

class SessionController;

/// Posts the viewport's document (the open document seen through the view camera) to the
/// session at the frame size it traces: the widget's device pixels divided by the preview
/// divider (Blender's pixel size). While the window edge moves the size is not posted; once it
/// has rested kResizeSettleMs, it is.
class ViewPosting : public QObject {
    Q_OBJECT
public:
    /// How long a resize must rest before the session traces the new size.
    static constexpr int kResizeSettleMs = 120;

    /// Posts `document()` to `session` for `widget`.
    ViewPosting(const QWidget* widget, SessionController* session,
                std::function<SceneDocument()> document);

    /// Posts the document now, at the widget's size now.
    void post();
    /// The widget was resized: the first size is posted at once, a later one once it rests.
    void resized();
    /// Preview scale 1 / `divider` (1, 2 or 4; anything else means 1); false when it was so.
    bool setDivider(int divider);
    int divider() const { return divider_; }
    /// The size posted last: toTrace() when it was posted; empty until the first post.
    QSize postedSize() const { return posted_; }
    /// tracedFrameSize() of the widget as it is now.
    QSize toTrace() const;
    /// The size the session traces: the posted one, or before the first post, toTrace().
    QSize traced() const { return posted_.isEmpty() ? toTrace() : posted_; }

Q_SIGNALS:
    /// The document was posted (the view may have changed).
    void posted();

private:
    const QWidget* widget_;
    SessionController* session_;
    std::function<SceneDocument()> document_;
    int divider_ = 1;
    QSize posted_;   ///< Empty until the first post.
    QTimer settle_;  ///< Restarted by each resize; posts the new size when it fires.
};

}  // namespace rs::ui
