// An OpenImageIO reader that gives another file's sRGB-encoded pixels as linear half floats.
#pragma once

#include <OpenImageIO/imageio.h>

namespace rs {

/// The sRGB EOTF (IEC 61966-2-1), exact: c / 12.92 up to 0.04045, else ((c + 0.055) / 1.055)^2.4.
float srgbToLinear(float c);

/// True for the pixel formats whose colours we take as sRGB-encoded: 8- and 16-bit integers
/// (PNG, JPEG, most TIFF). Float and half files (EXR, HDR, float TIFF) are linear.
bool isSrgbEncoded(OIIO::TypeDesc format);

/// An ImageInput::Creator for ImageCache::add_file: the reader it makes opens the named file
/// with its ordinary reader and hands the cache every colour channel decoded from sRGB to
/// linear (alpha stays as stored), as half floats, for every subimage and MIP level, tiled or
/// not. Filtering and MIP-mapping then average linear radiance, as they must: a far black and
/// white pattern averages to 0.5, not to the 0.21 that decoding a filtered sRGB value gives.
/// Texels cost 2 bytes a channel in the cache instead of 1 (8-bit files).
OIIO::ImageInput* createSrgbLinearInput();

}  // namespace rs
