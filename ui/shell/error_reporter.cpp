// Error reporting through a replaceable handler; the default is a modal QMessageBox.
#include "shell/error_reporter.h"

#include <QMessageBox>

namespace rs::ui {

namespace {
std::function<void(const QString&, const QString&)>& handler() {
    static std::function<void(const QString&, const QString&)> h;
    return h;
}
}  // namespace

void reportError(QWidget* parent, const QString& title, const QString& text) {
    if (handler()) {
        handler()(title, text);
        return;
    }
    QMessageBox::critical(parent, title, text);
}

void setErrorHandler(std::function<void(const QString& title, const QString& text)> h) {
    handler() = std::move(h);
}

}  // namespace rs::ui
