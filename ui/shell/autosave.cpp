// Autosave files: <folder>/<pid>-<start ms>.scene.json next to a QLockFile of the same name
// that the writing session holds. A scene file whose lock is free (its process is gone) is an
// orphan to offer for recovery.
#include "shell/autosave.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QStandardPaths>
#include <algorithm>

#include "document/scene_editor.h"
#include "document/scene_file_writer.h"
#include "io/scene_io.h"

namespace rs::ui {

namespace {

/// Top-level `x-` key naming the file the autosave is a modified copy of. An `x-` key, so an
/// autosave stays an ordinary scene file that validate and the CLI accept.
constexpr const char* kOriginKey = "x-raystudio-autosave-of";
const QString kSceneSuffix = QStringLiteral(".scene.json");

QString lockPathFor(const QString& scene) {
    return scene.left(scene.size() - kSceneSuffix.size()) + QStringLiteral(".lock");
}

/// `text` as a JSON string literal (Extras hold serialised JSON values).
std::string jsonString(const QString& text) {
    const QByteArray array = QJsonDocument(QJsonArray{text}).toJson(QJsonDocument::Compact);
    return array.mid(1, array.size() - 2).toStdString();
}

QString fromJsonString(const std::string& json) {
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray("[") + json.c_str() + "]");
    return doc.array().at(0).toString();
}

}  // namespace

Autosave::Autosave(SceneEditor* editor, QObject* parent) : QObject(parent), editor_(editor) {
    // Pid and start time: a later process reusing the pid must not overwrite an orphan.
    path_ = folder() +
            QStringLiteral("/%1-%2")
                .arg(QCoreApplication::applicationPid())
                .arg(QDateTime::currentMSecsSinceEpoch()) +
            kSceneSuffix;
    connect(editor_, &SceneEditor::documentChanged, this, [this] { changedSinceWrite_ = true; });
    connect(&timer_, &QTimer::timeout, this, [this] { writeNow(); });
    setIntervalMs(kDefaultSeconds * 1000);
}

Autosave::~Autosave() {
    discard();
}

void Autosave::setIntervalMs(int ms) {
    if (ms <= 0) {
        timer_.stop();
        discard();
        return;
    }
    timer_.start(ms);
}

bool Autosave::writeNow() {
    if (editor_->undoStack()->isClean()) {
        discard();  // Saved (or undone back to the saved state): nothing to recover.
        return true;
    }
    if (!changedSinceWrite_ && QFileInfo::exists(path_)) return true;
    if (!lock_) {
        // The lock first: a scene file without a live lock would look like a crash's.
        QDir().mkpath(folder());
        lock_ = std::make_unique<QLockFile>(lockPathFor(path_));
        if (!lock_->tryLock(0)) {
            lock_.reset();
            Q_EMIT failed(tr("cannot lock %1").arg(lockPathFor(path_)));
            return false;
        }
    }
    SceneDocument doc = editor_->document();
    doc.extras.emplace_back(kOriginKey, jsonString(editor_->filePath()));
    QString error;
    if (!writeSceneFile(path_, doc, error)) {
        Q_EMIT failed(tr("%1: %2").arg(path_, error));
        return false;
    }
    changedSinceWrite_ = false;
    return true;
}

void Autosave::discard() {
    QFile::remove(path_);
    lock_.reset();  // Unlocks, which removes the lock file.
    changedSinceWrite_ = true;
}

QString Autosave::folder() {
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
           QStringLiteral("/autosave");
}

std::vector<OrphanAutosave> Autosave::orphans() {
    std::vector<OrphanAutosave> found;
    const QDir dir(folder());
    for (const QFileInfo& info :
         dir.entryInfoList({QStringLiteral("*") + kSceneSuffix}, QDir::Files)) {
        QLockFile lock(lockPathFor(info.absoluteFilePath()));
        // Never stale by age: a session may run for days. A dead owner makes it stale.
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0)) continue;  // Its session is still running.
        found.push_back({info.absoluteFilePath(), info.lastModified()});
    }
    std::sort(found.begin(), found.end(), [](const OrphanAutosave& a, const OrphanAutosave& b) {
        return a.written > b.written;
    });
    return found;
}

bool Autosave::read(const QString& file, RecoveredDocument& out, QString& error) {
    SceneLoadResult result = loadScene(file.toStdString());
    if (!result.ok()) {
        error = QString::fromStdString(result.errorText());
        return false;
    }
    out.document = std::move(result.document);
    out.originalPath.clear();
    Extras& extras = out.document.extras;
    const auto origin = std::find_if(extras.begin(), extras.end(),
                                     [](const auto& e) { return e.first == kOriginKey; });
    if (origin != extras.end()) {
        out.originalPath = fromJsonString(origin->second);
        extras.erase(origin);
    }
    return true;
}

void Autosave::remove(const QString& file) {
    QFile::remove(file);
    QFile::remove(lockPathFor(file));
}

}  // namespace rs::ui
