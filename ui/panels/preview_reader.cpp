// PreviewReader: a queue of files to preview, one thread that reads them, and the previews kept.
#include "panels/preview_reader.h"

#include <algorithm>

#include "texture/texture_store.h"
#include "texture/thumbnail.h"

namespace rs::ui {

namespace {

/// Previews kept; past this the kept ones are dropped (a bound, not an LRU: a preview is
/// cheap to make again next to what the user just chose).
constexpr std::size_t kMaxKept = 64;

PreviewPixels makePreview(const std::string& path, int readSide) {
    PreviewPixels p;
    std::string error;
    if (!TextureStore::shared().open(path, error)) {
        p.error = error;
        return p;
    }
    Thumbnail t = makeThumbnail(path, readSide);
    if (!t.ok()) {
        p.error = t.error.empty() ? "cannot read " + path : t.error;
        return p;
    }
    p.image = QImage(t.width, t.height, QImage::Format_RGB888);
    const std::size_t row = std::size_t(t.width) * 3;
    for (int y = 0; y < t.height; ++y)
        std::copy_n(t.rgb.data() + std::size_t(y) * row, row, p.image.scanLine(y));
    return p;
}

}  // namespace

PreviewReader& PreviewReader::shared() {
    static PreviewReader reader;
    return reader;
}

PreviewReader::~PreviewReader() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

std::optional<PreviewPixels> PreviewReader::find(const std::string& path, const FileStamp& stamp,
                                                 int readSide) const {
    std::lock_guard lock(mutex_);
    const auto it = made_.find(Key{path, stamp.exists, stamp.modified, stamp.size, readSide});
    if (it == made_.end()) return std::nullopt;
    return it->second;
}

void PreviewReader::request(const std::string& path, const FileStamp& stamp, int readSide,
                            const GuiMailbox& mailbox,
                            std::function<void(const PreviewPixels&)> done) {
    const Key key{path, stamp.exists, stamp.modified, stamp.size, readSide};
    {
        std::lock_guard lock(mutex_);
        if (const auto it = made_.find(key); it != made_.end()) {
            mailbox.post([done = std::move(done), preview = it->second] { done(preview); });
            return;
        }
        std::vector<Waiter>& waiters = waiting_[key];
        if (waiters.empty()) queue_.push_back(key);
        waiters.push_back({mailbox, std::move(done)});
        if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
    }
    wake_.notify_one();
}

void PreviewReader::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
        if (stopping_) return;
        const Key key = queue_.front();
        queue_.pop_front();
        lock.unlock();
        const PreviewPixels preview = makePreview(std::get<0>(key), std::get<4>(key));
        lock.lock();
        if (made_.size() >= kMaxKept) made_.clear();
        made_[key] = preview;
        std::vector<Waiter> waiters = std::move(waiting_[key]);
        waiting_.erase(key);
        for (Waiter& w : waiters)
            w.mailbox.post([done = std::move(w.done), preview] { done(preview); });
    }
}

}  // namespace rs::ui
