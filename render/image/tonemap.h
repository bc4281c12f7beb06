// HDR to display mapping: exposure, tone operator, sRGB encoding.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/math.h"
#include "scene/document.h"

namespace rs {

/// Applies exposure (stops) and the operator; the result is display-linear in [0, 1].
Color toneMap(const Color& hdr, ToneMap op, float exposure);
/// sRGB transfer function for one display-linear channel in [0, 1].
float srgbEncode(float linear);
/// Inverse of srgbEncode.
float srgbDecode(float encoded);
/// Tone maps and encodes one pixel to 8-bit sRGB.
void toDisplay8(const Color& hdr, ToneMap op, float exposure, uint8_t rgb[3]);
/// toDisplay8 of `count` pixels into 3 * `count` bytes (the viewport's rows: exposure's gain
/// is computed once, the sRGB step is a table lookup, and a pixel whose colour has the bits
/// of its left neighbour's copies its bytes; the same bytes as pixel by pixel).
void toDisplay8(const Color* hdr, std::size_t count, ToneMap op, float exposure, uint8_t* rgb);

}  // namespace rs
