// MainWindow's side of crash recovery: offering a crashed session's autosave at start.
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>

#include "document/scene_editor.h"
#include "io/scene_io.h"
#include "shell/autosave.h"
#include "shell/error_reporter.h"
#include "shell/main_window.h"

namespace rs::ui {

void MainWindow::setAutosaveIntervalMs(int ms) {
    autosave_->setIntervalMs(ms);
}

bool MainWindow::offerRecovery(RecoveryAnswer answer) {
    const std::vector<OrphanAutosave> orphans = Autosave::orphans();
    if (orphans.empty()) return false;
    const OrphanAutosave& newest = orphans.front();
    RecoveredDocument recovered;
    QString error;
    if (!Autosave::read(newest.file, recovered, error)) {
        // Kept, not deleted: the user may still want to look at it by hand.
        reportError(this, tr("Cannot recover autosave"),
                    tr("%1 could not be read:\n\n%2").arg(newest.file, error));
        return false;
    }
    const QString name = recovered.originalPath.isEmpty()
                             ? tr("an untitled scene")
                             : QFileInfo(recovered.originalPath).fileName();
    if (answer == RecoveryAnswer::Ask) {
        QMessageBox box(QMessageBox::Question, tr("Recover unsaved changes?"),
                        tr("RayStudio did not exit cleanly. Unsaved changes to %1 were autosaved "
                           "at %2.\n\nRecover them, or discard them for good?")
                            .arg(name, QLocale().toString(newest.written, QLocale::ShortFormat)),
                        QMessageBox::NoButton, this);
        QPushButton* recover = box.addButton(tr("Recover"), QMessageBox::AcceptRole);
        QPushButton* discard = box.addButton(tr("Discard"), QMessageBox::DestructiveRole);
        box.addButton(tr("Not Now"), QMessageBox::RejectRole);
        box.setDefaultButton(recover);
        box.exec();
        if (box.clickedButton() == recover)
            answer = RecoveryAnswer::Recover;
        else if (box.clickedButton() == discard)
            answer = RecoveryAnswer::Discard;
        else
            return false;  // Offered again at the next start.
    }
    if (answer == RecoveryAnswer::Discard) {
        Autosave::remove(newest.file);
        return false;
    }
    // The saved file (when it still opens) is the undo base: one Undo shows what was lost.
    SceneDocument base;
    if (!recovered.originalPath.isEmpty()) {
        SceneLoadResult saved = loadScene(recovered.originalPath.toStdString());
        if (saved.ok()) base = std::move(saved.document);
    }
    editor_->resetDocument(std::move(base), recovered.originalPath);
    editor_->edit(tr("Recover autosave"), std::move(recovered.document));
    // This session's own autosave first, so a second crash right now loses nothing.
    if (autosave_->intervalMs() > 0) autosave_->writeNow();
    Autosave::remove(newest.file);
    statusBar()->showMessage(tr("Recovered unsaved changes to %1").arg(name), 5000);
    return true;
}

}  // namespace rs::ui
