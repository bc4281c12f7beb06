// The session's tile arena: its size for a thread count.
#include "session/tile_arena.h"

#include <tbb/info.h>

namespace rs {

int TileArena::size(int threads) {
    return threads > 0 ? threads : tbb::info::default_concurrency();
}

}  // namespace rs
