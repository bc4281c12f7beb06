// HDR to display mapping: exposure, the four tone operators of the scene format, sRGB encoding.
#include "image/tonemap.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

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

/// toneMap with exposure's gain (2^stops) already computed.
Color toneMapGain(const Color& hdr, ToneMap op, float gain) {
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

/// The 8-bit code of display-linear `d` in [0, 1]: srgbEncode scaled and rounded.
uint8_t encode8(float d) {
    return static_cast<uint8_t>(std::lround(srgbEncode(d) * 255.0f));
}

/// Where encode8 steps up: at[k - 1] is the smallest float in [0, 1] whose code is at least
/// k. Found by bisection on the bit patterns (ordered like the values for floats >= 0), so the
/// table is encode8 itself, evaluated 255 x 30 times once; the code is monotonic in d.
struct Srgb8Steps {
    static constexpr uint32_t kOne = 0x3f800000u;  // 1.0f, code 255.
    static constexpr int kBucketShift = 16;        // buckets of 2^16 patterns: 1/128 apart
    /// at[255] is above every input: code 255 has no step after it.
    float at[256];
    /// The code of each bucket's first pattern. Within a bucket (a relative width of 1/128)
    /// the code rises by at most one (sRGB's slope falls slower than the buckets narrow
    /// towards 0: a code step is 2.3 buckets wide at 1, wider below), so code() takes one
    /// compare, without a branch (the viewport tone-maps every pixel it shows on the GUI thread).
    uint8_t bucketStart[(kOne >> kBucketShift) + 1];
    Srgb8Steps() {
        uint32_t lo = 0;  // encode8 of every pattern below lo is < k.
        for (int k = 1; k <= 255; ++k) {
            uint32_t hi = kOne;
            while (lo < hi) {
                const uint32_t mid = lo + (hi - lo) / 2;
                if (encode8(std::bit_cast<float>(mid)) >= k)
                    hi = mid;
                else
                    lo = mid + 1;
            }
            at[k - 1] = std::bit_cast<float>(lo);
        }
        at[255] = 2.0f;
        int code = 0;
        for (uint32_t b = 0; b <= (kOne >> kBucketShift); ++b) {
            const float first = std::bit_cast<float>(b << kBucketShift);
            while (code < 255 && at[code] <= first) ++code;
            bucketStart[b] = uint8_t(code);
        }
    }
    /// encode8(d) for d in [0, 1]: the number of steps at or below d, counted on from the
    /// code of d's bucket (-0.0 is bucket 0).
    uint8_t code(float d) const {
        const uint32_t bits = std::min(std::bit_cast<uint32_t>(d) & 0x7fffffffu, kOne);
        const int i = bucketStart[bits >> kBucketShift];
        return uint8_t(i + int(at[i] <= d));
    }
};

const Srgb8Steps& srgb8Steps() {
    static const Srgb8Steps steps;
    return steps;
}

}  // namespace

Color toneMap(const Color& hdr, ToneMap op, float exposure) {
    return toneMapGain(hdr, op, std::exp2(exposure));
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
    toDisplay8(&hdr, 1, op, exposure, rgb);
}

namespace {

/// Whether two colours have the same bits (then they map to the same bytes, NaNs included).
bool sameBits(const Color& a, const Color& b) {
    return std::memcmp(&a, &b, sizeof(Color)) == 0;
}

/// toDisplay8's row loop for one operator (chosen once a row, not per pixel).
template <ToneMap Op>
void toDisplay8Row(const Color* hdr, std::size_t count, float gain, uint8_t* rgb) {
    const Srgb8Steps& steps = srgb8Steps();
    for (std::size_t i = 0; i < count; ++i) {
        // An undersampled pass repeats one value over each block's pixels: a pixel equal to
        // its left neighbour takes its bytes instead of being mapped again.
        if (i > 0 && sameBits(hdr[i], hdr[i - 1])) {
            std::memcpy(rgb + 3 * i, rgb + 3 * (i - 1), 3);
            continue;
        }
        // toneMap stays in [0, 1] (NaN sanitised), the table's domain.
        const Color d = toneMapGain(hdr[i], Op, gain);
        for (int c = 0; c < 3; ++c) rgb[3 * i + std::size_t(c)] = steps.code(d[c]);
    }
}

}  // namespace

void toDisplay8(const Color* hdr, std::size_t count, ToneMap op, float exposure, uint8_t* rgb) {
    const float gain = std::exp2(exposure);
    switch (op) {
        case ToneMap::Clamp:
            return toDisplay8Row<ToneMap::Clamp>(hdr, count, gain, rgb);
        case ToneMap::Linear:
            return toDisplay8Row<ToneMap::Linear>(hdr, count, gain, rgb);
        case ToneMap::Reinhard:
            return toDisplay8Row<ToneMap::Reinhard>(hdr, count, gain, rgb);
        case ToneMap::Aces:
            return toDisplay8Row<ToneMap::Aces>(hdr, count, gain, rgb);
    }
    toDisplay8Row<ToneMap::Clamp>(hdr, count, gain, rgb);
}

}  // namespace rs
