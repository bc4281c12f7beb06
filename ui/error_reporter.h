// One place where the designer reports errors to the user and asks yes/no questions, so
// tests can intercept them.
#pragma once

#include <QString>
#include <functional>

class QWidget;

namespace rs::ui {

/// Shows an error (a message box by default).
void reportError(QWidget* parent, const QString& title, const QString& text);
/// Replaces how errors are shown (tests record them instead); an empty function restores
/// the message box.
void setErrorHandler(std::function<void(const QString& title, const QString& text)> handler);

/// Asks a yes/no question (a message box by default); true for yes.
bool askYesNo(QWidget* parent, const QString& title, const QString& text);
/// Replaces how questions are asked (tests answer them); an empty function restores the box.
void setQuestionHandler(std::function<bool(const QString& title, const QString& text)> handler);

}  // namespace rs::ui
