// A small preview of an image file for the designer: 8-bit sRGB RGB pixels, read through
// OpenImageIO so that every format the renderer reads (EXR and HDR included) has one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rs {

/// An image resized to fit a square of the side asked for, aspect kept.
struct Thumbnail {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;  ///< width * height * 3 bytes, sRGB-encoded, rows top down.
    std::string error;              ///< Why there is none (names the file); empty when fine.
    bool ok() const { return error.empty() && width > 0 && height > 0; }
};

/// Reads `path` and resizes it (filtered) so that its larger side is `maxSide` pixels (a
/// small image is enlarged, so that it can be seen). Integer files (PNG, JPEG, 8/16-bit TIFF) are
/// taken as sRGB already; float and half files (EXR, HDR) are linear and are encoded to sRGB,
/// clamped to [0, 1]. Grey files are shown grey; alpha is dropped. Of a MIP-mapped file, the
/// smallest level still at least `maxSide` wide or high is read, so a large tiled texture is not
/// read whole.
Thumbnail makeThumbnail(const std::string& path, int maxSide);

}  // namespace rs
