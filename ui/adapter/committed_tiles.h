// The tiles the session committed since the display last looked: worker threads announce
// them, the GUI thread's hand-over takes them, and a hand-over that could not copy holds them
// for the next look.
#pragma once

#include <QRect>
#include <cstdint>
#include <mutex>
#include <vector>

namespace rs::ui {

/// Tiles waiting for the display (SessionController::displayFrame). add() is called on worker
/// threads, the rest on the GUI thread only.
class CommittedTiles {
public:
    /// What one hand-over copies.
    struct Batch {
        std::vector<QRect> tiles;
        bool everything = false;  ///< Too many to list: copy the frame whole.
        uint64_t generation = 0;  ///< The highest generation any of them was announced with.
    };

    /// A tile [x0, x1) x [y0, y1) of `generation` was committed (worker threads).
    void add(int x0, int y0, int x1, int y1, uint64_t generation);
    /// Every tile announced so far and those held back. The generation is the highest ever
    /// announced: the copy that follows holds every tile announced before it.
    Batch take();
    /// A hand-over took `batch` but could not copy it: the next take() returns it again.
    void hold(Batch batch) { held_ = std::move(batch); }

private:
    std::mutex mutex_;  ///< Guards the announced tiles (worker threads add, the GUI drains).
    std::vector<QRect> announced_;
    uint64_t announcedGeneration_ = 0;
    bool overflowed_ = false;  ///< More than kMaxListed since the last take().
    Batch held_;               ///< GUI thread only.
};

}  // namespace rs::ui
