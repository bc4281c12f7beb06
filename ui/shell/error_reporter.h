// One place where the designer reports errors to the user, so tests can intercept them.
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

}  // namespace rs::ui
