// CommittedTiles: the worker threads' tile announcements, drained by the GUI's hand-over.
#include "adapter/committed_tiles.h"

#include <algorithm>
#include <utility>

namespace rs::ui {

namespace {
/// More committed tiles than this between two looks: copy the frame whole instead.
constexpr std::size_t kMaxListedTiles = 16384;
}  // namespace

void CommittedTiles::add(int x0, int y0, int x1, int y1, uint64_t generation) {
    std::lock_guard lock(mutex_);
    if (announced_.size() < kMaxListedTiles)
        announced_.emplace_back(QPoint(x0, y0), QPoint(x1 - 1, y1 - 1));
    else
        overflowed_ = true;
    announcedGeneration_ = std::max(announcedGeneration_, generation);
}

CommittedTiles::Batch CommittedTiles::take() {
    Batch batch;
    {
        std::lock_guard lock(mutex_);
        batch.tiles.swap(announced_);
        batch.everything = overflowed_;
        overflowed_ = false;
        batch.generation = announcedGeneration_;
    }
    batch.tiles.insert(batch.tiles.end(), held_.tiles.begin(), held_.tiles.end());
    held_.tiles.clear();
    batch.everything = batch.everything || std::exchange(held_.everything, false);
    batch.generation = std::max(batch.generation, std::exchange(held_.generation, 0));
    return batch;
}

}  // namespace rs::ui
