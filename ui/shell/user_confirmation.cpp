// Questions through replaceable handlers; the defaults are modal QMessageBox and QInputDialog.
#include "shell/user_confirmation.h"

#include <QInputDialog>
#include <QMessageBox>
#include <QPushButton>

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

namespace {
using ChoiceHandler =
    std::function<int(const QString& title, const QString& text, const QStringList& choices)>;
ChoiceHandler& choiceHandler() {
    static ChoiceHandler h;
    return h;
}
using TextHandler = std::function<std::optional<QString>(const QString& title, const QString& label,
                                                         const QString& initial)>;
TextHandler& textHandler() {
    static TextHandler h;
    return h;
}
}  // namespace

int choose(QWidget* parent, const QString& title, const QString& text, const QStringList& choices) {
    if (choiceHandler()) return choiceHandler()(title, text, choices);
    QMessageBox box(QMessageBox::Question, title, text, QMessageBox::NoButton, parent);
    std::vector<QPushButton*> buttons;
    for (const QString& c : choices) buttons.push_back(box.addButton(c, QMessageBox::AcceptRole));
    if (!buttons.empty()) box.setDefaultButton(buttons.front());
    box.exec();
    for (std::size_t i = 0; i < buttons.size(); ++i)
        if (box.clickedButton() == buttons[i]) return int(i);
    return -1;
}

void setChoiceHandler(ChoiceHandler h) {
    choiceHandler() = std::move(h);
}

std::optional<QString> askText(QWidget* parent, const QString& title, const QString& label,
                               const QString& initial) {
    if (textHandler()) return textHandler()(title, label, initial);
    bool ok = false;
    const QString text =
        QInputDialog::getText(parent, title, label, QLineEdit::Normal, initial, &ok);
    if (!ok) return std::nullopt;
    return text;
}

void setTextHandler(TextHandler h) {
    textHandler() = std::move(h);
}

}  // namespace rs::ui
