// One place where the designer asks the user something: to confirm something costly, a plain
// yes/no question, a choice among a few answers, or a line of text; so tests can answer.
#pragma once

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

class QWidget;

namespace rs::ui {

/// Asks a yes/no question (a warning message box by default); true means go ahead.
bool confirm(QWidget* parent, const QString& title, const QString& text);
/// Asks a plain yes/no question (a question box, No by default); true means yes.
bool ask(QWidget* parent, const QString& title, const QString& text);
/// Replaces how questions are asked (confirm's and ask's) (tests answer them); an empty function
/// restores the box.
void setConfirmationHandler(std::function<bool(const QString& title, const QString& text)> handler);

/// Asks the user to pick one of `choices` (one button each, the first the default); returns
/// its index, or -1 when the box is closed without a pick.
int choose(QWidget* parent, const QString& title, const QString& text, const QStringList& choices);
/// Replaces how choose() asks (tests answer); an empty function restores the box.
void setChoiceHandler(
    std::function<int(const QString& title, const QString& text, const QStringList& choices)>
        handler);

/// Asks for one line of text, offering `initial`; nullopt when cancelled.
std::optional<QString> askText(QWidget* parent, const QString& title, const QString& label,
                               const QString& initial);
/// Replaces how askText() asks (tests answer); an empty function restores the dialog.
void setTextHandler(std::function<std::optional<QString>(const QString& title, const QString& label,
                                                         const QString& initial)>
                        handler);

}  // namespace rs::ui
