// A permanent status-bar widget: temporary messages hide ordinary ones, and a render's
// progress must stay visible while the designer reports other things.
#include "jobs/render_status.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <algorithm>
#include <cmath>

#include "jobs/render_queue.h"

namespace rs::ui {

QString timeLeftText(double seconds) {
    if (seconds < 0.0) return {};
    if (seconds < 90.0)
        return QObject::tr("about %1 s left").arg(std::max(1, int(std::lround(seconds))));
    if (seconds < 5400.0) return QObject::tr("about %1 min left").arg(std::lround(seconds / 60.0));
    return QObject::tr("about %1 h left").arg(seconds / 3600.0, 0, 'f', 1);
}

namespace {
/// Room for this many wide characters of the file's name; longer names are elided.
constexpr int kShownNameChars = 14;
}  // namespace

RenderStatus::RenderStatus(RenderQueue* queue, QWidget* parent)
    : QWidget(parent),
      queue_(queue),
      label_(new QLabel(this)),
      bar_(new QProgressBar(this)),
      cancel_(new QPushButton(tr("Cancel"), this)) {
    setObjectName(QStringLiteral("renderStatus"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(label_);
    layout->addWidget(bar_);
    layout->addWidget(cancel_);
    bar_->setMaximumWidth(160);
    // A fixed width for the words, so the bar and Cancel stay put as they change (a moving
    // button misses clicks); a long file name is elided in the middle.
    label_->setFixedWidth(label_->fontMetrics().horizontalAdvance(
                              tr("Rendering %1: about 59 min left (99 queued)")
                                  .arg(QString(kShownNameChars, QLatin1Char('M')))) +
                          8);
    bar_->setRange(0, 1);
    bar_->setValue(0);
    cancel_->setObjectName(QStringLiteral("cancelRender"));
    cancel_->setToolTip(tr("Stop this render without writing its file (queued renders go on)"));
    cancel_->setFocusPolicy(Qt::NoFocus);  // Clicking it must not take the focus from a field.
    connect(cancel_, &QPushButton::clicked, queue_, &RenderQueue::cancelCurrent);
    connect(queue_, &RenderQueue::started, this, &RenderStatus::onStarted);
    connect(queue_, &RenderQueue::progressed, this, &RenderStatus::onProgress);
    connect(queue_, &RenderQueue::idle, this, &QWidget::hide);
    hide();
}

QString RenderStatus::text() const {
    return label_->text();
}

void RenderStatus::onStarted(const QString& path) {
    name_ = QFileInfo(path).fileName();
    left_.clear();
    bar_->setRange(0, 1);
    bar_->setValue(0);
    updateText();
    show();
}

void RenderStatus::onProgress(int done, int total, double secondsLeft) {
    bar_->setRange(0, total);
    bar_->setValue(done);
    left_ = timeLeftText(secondsLeft);
    updateText();
}

void RenderStatus::updateText() {
    const QString name = label_->fontMetrics().elidedText(
        name_, Qt::ElideMiddle,
        label_->fontMetrics().horizontalAdvance(QString(kShownNameChars, QLatin1Char('M'))));
    QString text = tr("Rendering %1").arg(name);
    if (!left_.isEmpty()) text += QStringLiteral(": ") + left_;
    if (const int n = queue_->queued()) text += tr(" (%1 queued)").arg(n);
    label_->setText(text);
    label_->setToolTip(name_);
}

}  // namespace rs::ui
