// ViewPosting: the traced size, the preview divider and the resize that must rest first.
#include "viewport/view_posting.h"

#include <QWidget>

#include "adapter/session_controller.h"
#include "viewport/view_projection.h"

namespace rs::ui {

ViewPosting::ViewPosting(const QWidget* widget, SessionController* session,
                         std::function<SceneDocument()> document)
    : widget_(widget), session_(session), document_(std::move(document)) {
    settle_.setSingleShot(true);
    settle_.setInterval(kResizeSettleMs);
    connect(&settle_, &QTimer::timeout, this, &ViewPosting::post);
}

QSize ViewPosting::toTrace() const {
    return tracedFrameSize(widget_->size() * widget_->devicePixelRatioF(), divider_);
}

void ViewPosting::post() {
    settle_.stop();
    posted_ = toTrace();
    session_->requestUpdate(document_());
    Q_EMIT posted();
}

void ViewPosting::resized() {
    // While the window edge moves, the old frame stays (letterboxed); the session restarts
    // at the new size once it rests.
    if (posted_.isEmpty())
        post();
    else
        settle_.start();
}

bool ViewPosting::setDivider(int divider) {
    divider = validPreviewDivider(divider) ? divider : 1;
    if (divider == divider_) return false;
    divider_ = divider;
    return true;
}

}  // namespace rs::ui
