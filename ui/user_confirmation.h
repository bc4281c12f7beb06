// One place where the designer asks the user to confirm something costly, so tests can answer.
#pragma once

#include <QString>
#include <functional>

class QWidget;

namespace rs::ui {

/// Asks a yes/no question (a warning message box by default); true means go ahead.
bool confirm(QWidget* parent, const QString& title, const QString& text);
/// Replaces how questions are asked (tests answer them); an empty function restores the box.
void setConfirmationHandler(std::function<bool(const QString& title, const QString& text)> handler);

}  // namespace rs::ui
