// Autosave and crash recovery, as Blender does it: while the document has unsaved changes it
// is written every few seconds to the user's state folder; a clean exit removes the file, so
// an autosave found at start whose session is no longer running belongs to a crash.
#pragma once

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <vector>

#include "scene/document.h"

namespace rs::ui {

class SceneEditor;

/// An autosave left by a session that is no longer running.
struct OrphanAutosave {
    QString file;       ///< The autosaved scene.
    QDateTime written;  ///< When it was last written.
};

/// What an autosave holds: the document and the file it was a modified copy of.
struct RecoveredDocument {
    SceneDocument document;
    QString originalPath;  ///< Empty for a document that was never saved.
};

/// Writes this session's autosave on a timer while the editor's document is modified.
class Autosave : public QObject {
    Q_OBJECT
public:
    /// Default interval, in seconds, of Preferences' "Autosave every".
    static constexpr int kDefaultSeconds = 60;

    explicit Autosave(SceneEditor* editor, QObject* parent = nullptr);
    /// Removes this session's autosave: leaving normally is never a crash.
    ~Autosave() override;

    /// Autosaves every `ms` milliseconds; 0 turns autosave off (and removes the file).
    void setIntervalMs(int ms);
    int intervalMs() const { return timer_.isActive() ? timer_.interval() : 0; }
    /// Writes the document now if it changed since the last autosave and is not saved;
    /// removes the autosave when the document is saved. False when a write failed.
    bool writeNow();
    /// Removes this session's autosave (clean exit, or the changes were discarded).
    void discard();
    /// This session's autosave file (it exists only while there is something to recover).
    QString path() const { return path_; }

    /// The folder autosaves live in (AppLocalDataLocation/autosave).
    static QString folder();
    /// Autosaves of sessions that are no longer running, newest first.
    static std::vector<OrphanAutosave> orphans();
    /// Reads an autosave; false with `error` set when it does not parse.
    static bool read(const QString& file, RecoveredDocument& out, QString& error);
    /// Deletes an orphan autosave.
    static void remove(const QString& file);

Q_SIGNALS:
    /// An autosave could not be written (the status bar shows it; no dialog every minute).
    void failed(const QString& error);

private:
    SceneEditor* editor_;
    QTimer timer_;
    QString path_;
    std::unique_ptr<QLockFile> lock_;  ///< Held while this session runs: marks it alive.
    bool changedSinceWrite_ = false;
};

}  // namespace rs::ui
