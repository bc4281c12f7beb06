// One place where the designer asks the user to confirm something costly, or a plain yes/no
// question, so tests can answer.
#pragma once

#include <QString>
#include <functional>

class QWidget;

namespace rs::ui {

/// Asks a yes/no question (a warning message box by default); true means go ahead.
bool confirm(QWidget* parent, const QString& title, const QString& text);
/// Asks a plain yes/no question (a question box, No by default); true means yes.
bool ask(QWidget* parent, const QString& title, const QString& text);
/// Replaces how questions are asked (confirm's and ask's) (tests answer them); an empty function
/// restores the box.
void setConfirmationHandler(std::function<bool(const QString& title, const QString& text)> handler);

}  // namespace rs::ui
