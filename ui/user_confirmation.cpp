// Confirmations through a replaceable handler; the default is a modal QMessageBox.
#include "user_confirmation.h"

#include <QMessageBox>

namespace rs::ui {

namespace {
std::function<bool(const QString&, const QString&)>& handler() {
    static std::function<bool(const QString&, const QString&)> h;
    return h;
}
}  // namespace

bool confirm(QWidget* parent, const QString& title, const QString& text) {
    if (handler()) return handler()(title, text);
    return QMessageBox::warning(parent, title, text, QMessageBox::Yes | QMessageBox::Cancel,
                                QMessageBox::Cancel) == QMessageBox::Yes;
}

bool ask(QWidget* parent, const QString& title, const QString& text) {
    if (handler()) return handler()(title, text);
    return QMessageBox::question(parent, title, text, QMessageBox::Yes | QMessageBox::No,
                                 QMessageBox::No) == QMessageBox::Yes;
}

void setConfirmationHandler(std::function<bool(const QString& title, const QString& text)> h) {
    handler() = std::move(h);
}

}  // namespace rs::ui
