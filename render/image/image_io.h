// Image files through OpenImageIO; the format follows the extension.
#pragma once

#include <string>

#include "image/image.h"
#include "scene/document.h"

namespace rs {

/// Writes `image`. PNG/JPEG/TIFF get tone-mapped 8-bit sRGB; EXR and HDR get linear float
/// radiance. Unknown extension or write failure: false with `error` naming path and cause.
bool writeImage(const std::string& path, const ImageRgb& image, ToneMap op, float exposure,
                std::string& error);
/// Empty when `path`'s extension is one writeImage writes; otherwise a message naming it and
/// the supported ones (for checking an output path before rendering into it).
std::string imageFormatError(const std::string& path);
/// Reads an image as linear floats (8-bit files are sRGB-decoded). False with `error` on failure.
bool readImage(const std::string& path, ImageRgb& image, std::string& error);

}  // namespace rs
