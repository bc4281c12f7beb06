// Merging part files back into the final image, refusing sets that are not one whole render.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "image/part_file.h"

namespace rs {

/// The image the parts make up, and what their headers agree on.
struct MergedImage {
    ImageRgb image;
    std::vector<ObjectId> ids;  ///< When every part has ids; empty otherwise.
    PartHeader header;          ///< The first part's header (shared fingerprint, size, tone map).
};

/// Checks that `headers` (read from `paths`) are every part 0..N-1 of one render exactly once:
/// same fingerprint, part count and image size, none missing, none doubled. Empty when they
/// are; otherwise every problem found, one per line, each naming the files involved.
std::string partSetError(const std::vector<std::string>& paths,
                         const std::vector<PartHeader>& headers);

/// Reads, checks and merges the part files. False with `error` (one problem a line) when a
/// file cannot be read or the set is not whole.
bool mergeParts(const std::vector<std::string>& paths, MergedImage& merged, std::string& error);

}  // namespace rs
