// Sibling paths for atomic writes: write next to the target, then rename over it.
#pragma once

#include <filesystem>

namespace rs {

/// A sibling of `path` that no concurrent writer picks: same folder (so the final rename is
/// atomic on one file system) and same extension (so OIIO picks the same format for it).
std::filesystem::path temporarySibling(const std::filesystem::path& path);

}  // namespace rs
