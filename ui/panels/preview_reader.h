// The designer's image previews, read on a thread of their own: decoding and scaling a
// 4096 x 4096 PNG takes about a second, which the GUI thread must not spend.
#pragma once

#include <QImage>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "core/input_file.h"
#include "jobs/gui_mailbox.h"

namespace rs::ui {

/// An image file's preview: 8-bit sRGB pixels (made on the reader's thread, as QImage allows;
/// copies share them), or the sentence why there is none (the renderer's own check first, so
/// it is the error a render would report).
struct PreviewPixels {
    QImage image;
    std::string error;
};

/// Makes previews one at a time on one background thread and keeps each while its file stays
/// the same (path, modification time and size): panels are rebuilt on every selection change,
/// and a file is read once. Every call is thread-safe.
class PreviewReader {
public:
    static PreviewReader& shared();
    ~PreviewReader();  ///< Finishes the preview being made, then stops the thread.
    PreviewReader(const PreviewReader&) = delete;
    PreviewReader& operator=(const PreviewReader&) = delete;

    /// The preview of `path` as `stamp` says it is on disk, at most `readSide` pixels on its
    /// larger side, if it has been made.
    std::optional<PreviewPixels> find(const std::string& path, const FileStamp& stamp,
                                      int readSide) const;
    /// Makes that preview on the reader's thread (once, however many ask meanwhile), keeps it,
    /// then posts `done` with it through `mailbox`.
    void request(const std::string& path, const FileStamp& stamp, int readSide,
                 const GuiMailbox& mailbox, std::function<void(const PreviewPixels&)> done);

private:
    PreviewReader() = default;
    using Key = std::tuple<std::string, bool, long long, std::uintmax_t, int>;
    struct Waiter {
        GuiMailbox mailbox;
        std::function<void(const PreviewPixels&)> done;
    };
    void run();

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::map<Key, PreviewPixels> made_;
    std::map<Key, std::vector<Waiter>> waiting_;  ///< Asked for, not made yet.
    std::deque<Key> queue_;                       ///< The keys of waiting_, oldest first.
    bool stopping_ = false;
    std::thread thread_;  ///< Started by the first request.
};

}  // namespace rs::ui
