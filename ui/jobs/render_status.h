// The status bar's part for Render Image: what renders, how far, the time left, and Cancel.
#pragma once

#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace rs::ui {

class RenderQueue;

/// Follows a RenderQueue; hidden while nothing renders.
class RenderStatus : public QWidget {
    Q_OBJECT
public:
    explicit RenderStatus(RenderQueue* queue, QWidget* parent = nullptr);

    QPushButton* cancelButton() const { return cancel_; }
    /// "Rendering name.png: about 12 s left (1 queued)".
    QString text() const;

private:
    void onStarted(const QString& path);
    void onProgress(int done, int total, double secondsLeft);
    void updateText();

    RenderQueue* queue_;
    QLabel* label_;
    QProgressBar* bar_;
    QPushButton* cancel_;
    QString name_;
    QString left_;
};

/// "about 12 s left", "about 3 min left"; empty while unknown (negative).
QString timeLeftText(double seconds);

}  // namespace rs::ui
