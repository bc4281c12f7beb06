// HDR to display mapping: exposure, the four tone operators of the scene format, sRGB encoding.
#include "image/tonemap.h"

#include <algorithm>
#include <cmath>

namespace rs {

namespace {

/// Radiance that the Linear operator maps to display white. Whitted scenes with a few
/// unit-intensity lights reach 2-3 on lit highlights; 4 keeps those unclipped while a
/// plain diffuse surface under one light (about 1) still lands at a visible quarter.
constexpr float kLinearWhite = 4.0f;

/// Inputs above this are display white for every operator; capping keeps x*x finite in ACES.
constexpr float kLargestRadiance = 1.0e4f;

/// NaN and negative radiance become 0 (a bad sample must not poison a whole pixel as NaN),
/// +inf becomes the largest radiance we map.
float sanitize(float x) {
    if (!(x > 0.0f)) return 0.0f;  // also catches NaN
    return std::min(x, kLargestRadiance);
}

float clamp01(float x) {
    return std::clamp(x, 0.0f, 1.0f);
}

Color clamp01(const Color& c) {
    return Color(clamp01(c.x), clamp01(c.y), clamp01(c.z));
}

/// Krzysztof Narkowicz, "ACES Filmic Tone Mapping Curve" (2015): a rational fit of the ACES
/// RRT+ODT, used as published on the exposed value.
float acesNarkowicz(float x) {
    constexpr float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    return clamp01((x * (a * x + b)) / (x * (c * x + d) + e));
}

}  // namespace

Color toneMap(const Color& hdr, ToneMap op, float exposure) {
    const float gain = std::exp2(exposure);
    const Color x(sanitize(hdr.x * gain), sanitize(hdr.y * gain), sanitize(hdr.z * gain));
    switch (op) {
        case ToneMap::Clamp:
            return clamp01(x);
        case ToneMap::Linear:
            // Image-independent on purpose: the viewport must not pump while tiles arrive.
            return clamp01(x / kLinearWhite);
        case ToneMap::Reinhard: {
            // Map luminance with L/(1+L) and scale the colour by the same factor, so hues
            // stay put instead of desaturating per channel. Saturated bright colours can
            // still exceed 1 in one channel; those are clipped.
            const float lum = luminance(x);
            if (lum <= 0.0f) return Color(0.0f);
            const float scale = (lum / (1.0f + lum)) / lum;
            return clamp01(x * scale);
        }
        case ToneMap::Aces:
            return Color(acesNarkowicz(x.x), acesNarkowicz(x.y), acesNarkowicz(x.z));
    }
    return clamp01(x);
}

float srgbEncode(float linear) {
    const float x = std::isnan(linear) ? 0.0f : clamp01(linear);
    if (x <= 0.0031308f) return 12.92f * x;
    return 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

float srgbDecode(float encoded) {
    const float x = std::isnan(encoded) ? 0.0f : clamp01(encoded);
    if (x <= 0.04045f) return x / 12.92f;
    return std::pow((x + 0.055f) / 1.055f, 2.4f);
}

void toDisplay8(const Color& hdr, ToneMap op, float exposure, uint8_t rgb[3]) {
    const Color d = toneMap(hdr, op, exposure);
    for (int i = 0; i < 3; ++i) {
        // srgbEncode stays in [0, 1], so the rounded value always fits a byte.
        rgb[i] = static_cast<uint8_t>(std::lround(srgbEncode(d[i]) * 255.0f));
    }
}

}  // namespace rs
