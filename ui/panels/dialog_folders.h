// Where file dialogs open: the folder the user last chose a file of that kind in, remembered
// across runs, else the open document's folder, else the home folder.
#pragma once

#include <QString>

namespace rs::ui {

/// The kinds of file a dialog asks for; each remembers its own folder.
enum class FileKind { Scene, Mesh, Image };

/// The folder a dialog for `kind` opens in. `documentPath` is the open scene's file (may be
/// empty); a remembered folder that no longer exists is passed over.
QString dialogFolder(FileKind kind, const QString& documentPath);
/// Remembers the folder of `chosenPath` (a file the user picked) for `kind`; empty: nothing.
void rememberDialogFolder(FileKind kind, const QString& chosenPath);

}  // namespace rs::ui
