// Internal to the session: an edit's marks applied to the frame, a block at a time (the only
// writes an edit makes: states and flags, under the session's exclusive frame lock).
#pragma once

#include "session/deep_frame.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rs {

/// The marks of `mask` in block b of `frame`: pixels whose entry is set go stale, lose their
/// deferred records and get the re-traced overlay flag; the others lose that flag. The tile's
/// state counts follow, updated once for the block.
void applyBlockMarks(DeepFrame& frame, std::size_t b, const std::vector<uint8_t>& mask);

}  // namespace rs
