// Material previews for the Materials dock, as Blender shows them: each material on a small
// sphere over a checkered floor and backdrop, traced by RayStudio's own renderer in one
// low-priority background thread (the viewport keeps the cores) and cached by content.
#pragma once

#include <QCache>
#include <QImage>
#include <QObject>
#include <QString>
#include <atomic>
#include <deque>
#include <memory>
#include <set>
#include <string>
#include <thread>

#include "jobs/gui_mailbox.h"
#include "scene/document.h"

namespace rs::ui {

/// The scene a preview traces, `side` x `side` pixels: `material` on a unit sphere at the
/// origin over a checkered floor, in front of a checkered wall (so mirror and glass show
/// something to reflect and bend), lit by one light. Under `environment` when it has one (the
/// wall then gives way to it), else a neutral grey background.
SceneDocument materialPreviewScene(const Material& material, const Environment& environment,
                                   int side);

/// Everything a preview depends on: the material's fields (not its name or `x-` keys), the
/// environment when present, the image files' stamps (a file re-saved on disk is a new
/// preview), and the size. Equal keys give the same picture.
std::string materialPreviewKey(const Material& material, const Environment& environment, int side);

/// What the list shows until the preview is ready: a disc of the material's base colour (a
/// checker's two colours; an image's neutral grey), `side` x `side` pixels.
QImage materialSwatch(const Material& material, int side);

/// Renders previews one at a time, each on a thread of its own below the GUI's priority
/// (started and joined by this object, so ThreadSanitizer sees the hand-over; the image comes
/// back through a GuiMailbox, as background_jobs.h's results do). Requests
/// are made on the GUI thread; a newer request for a material cancels and replaces its older
/// one (rapid edits render only the latest content), and a result whose request was replaced
/// is dropped.
class MaterialPreviews : public QObject {
    Q_OBJECT
public:
    explicit MaterialPreviews(QObject* parent = nullptr);
    ~MaterialPreviews() override;

    /// The preview of `material` (named by its name) under `environment` at `side` pixels:
    /// returned at once when one of that content was rendered before, else null, and
    /// previewReady follows once it is (unless a newer request for that name came first).
    QImage request(const Material& material, const Environment& environment, int side);
    /// Drops the waiting and running requests of materials not named in `names` (deleted or
    /// renamed).
    void retain(const std::set<std::string>& names);

    /// Test hooks: renders started so far, and whether any is waiting or running.
    int rendersStarted() const { return started_; }
    bool busy() const { return running_ != nullptr || !waiting_.empty(); }

Q_SIGNALS:
    /// The preview of material `name` with content `key` (materialPreviewKey) is `image`.
    void previewReady(const QString& name, const QString& key, const QImage& image);

private:
    struct Job {
        std::string name;
        std::string key;
        SceneDocument scene;
        std::shared_ptr<std::atomic<bool>> cancel;
    };
    void startNext();
    void finished(const std::shared_ptr<Job>& job, const QImage& image);

    GuiMailbox toGui_;
    std::thread worker_;                        ///< Traces running_; joined when its image is back.
    QCache<QString, QImage> cache_;             ///< By key.
    std::deque<std::shared_ptr<Job>> waiting_;  ///< At most one per name.
    std::shared_ptr<Job> running_;
    int started_ = 0;
};

}  // namespace rs::ui
