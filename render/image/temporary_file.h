// Sibling paths for atomic writes: write next to the target, then rename over it.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace rs {

/// A sibling of `path` that no concurrent writer picks: same folder (so the final rename is
/// atomic on one file system) and same extension (so OIIO picks the same format for it).
std::filesystem::path temporarySibling(const std::filesystem::path& path);

/// Writes `path` atomically: `write` fills a temporary sibling (returning false, with
/// `error` set, on failure), which is then renamed over `path`. Readers and crashes never see
/// a half-written file, and a failed write leaves any previous file untouched.
bool writeAtomically(const std::string& path,
                     const std::function<bool(const std::filesystem::path& tmp)>& write,
                     std::string& error);

}  // namespace rs
