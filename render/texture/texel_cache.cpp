// The texture filter and the per-thread table of texel blocks it reads from.
#include "texture/texel_cache.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

namespace rs {

namespace {

constexpr int kBlockBits = 4;
constexpr int kBlock = 1 << kBlockBits;  // texels a side
constexpr int kBlockMask = kBlock - 1;
constexpr int kTableBits = 10;
constexpr std::size_t kTableSize = std::size_t(1) << kTableBits;
/// Footprints whose long half-axis is at most this (level-0 texels) take one sample.
constexpr float kMagnifyingHalfAxis = 0.5f;

struct Block {
    const TexelSource* source = nullptr;
    int level = -1, bx = -1, by = -1;
    bool ok = false;
    float texels[kBlock * kBlock * 4];  // RGB and a spare lane: one 16-byte load a texel
};

/// This thread's blocks, allocated on its first lookup.
class BlockTable {
public:
    /// The block holding texel (x, y) of `level`, fetched from the source on a miss; null
    /// when the source could not deliver it.
    const Block* find(const TexelSource& source, int level, int x, int y) {
        const int bx = x >> kBlockBits, by = y >> kBlockBits;
        const std::uintptr_t key = reinterpret_cast<std::uintptr_t>(&source);
        const std::size_t slot = (std::size_t(bx) * 0x9E3779B1u ^ std::size_t(by) * 0x85EBCA77u ^
                                  std::size_t(level) * 0xC2B2AE3Du ^ (key >> 4) * 0x27D4EB2Fu) >>
                                     (32 - kTableBits) &
                                 (kTableSize - 1);
        Block& b = blocks_[slot];
        if (b.source != &source || b.level != level || b.bx != bx || b.by != by) {
            b.source = &source;
            b.level = level;
            b.bx = bx;
            b.by = by;
            b.ok = fill(source, level, bx, by, b.texels);
        }
        return b.ok ? &b : nullptr;
    }

private:
    static bool fill(const TexelSource& source, int level, int bx, int by, float* texels) {
        const int x0 = bx * kBlock, y0 = by * kBlock;
        const int x1 = std::min(x0 + kBlock, source.width[std::size_t(level)]);
        const int y1 = std::min(y0 + kBlock, source.height[std::size_t(level)]);
        float rows[kBlock * kBlock * 3];
        if (!source.fetch(level, x0, x1, y0, y1, rows)) return false;
        const int w = x1 - x0;
        for (int y = 0; y < y1 - y0; ++y)
            for (int x = 0; x < w; ++x) {
                const float* from = rows + std::size_t((y * w + x) * 3);
                float* to = texels + std::size_t((y * kBlock + x) * 4);
                to[0] = from[0], to[1] = from[1], to[2] = from[2], to[3] = 0.0f;
            }
        return true;
    }

    std::unique_ptr<Block[]> blocks_{new Block[kTableSize]};
};

std::atomic<std::size_t> residentBudget{std::size_t(128) << 20};
std::atomic<std::size_t> residentBytes{0};

BlockTable& table() {
    thread_local BlockTable blocks;
    return blocks;
}

/// x - floor(x): the fraction that wraps a texture coordinate into [0, 1].
inline float wrapped(float x) {
    return x - floorInline(x);
}

inline Float4 loadTexel(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
/// A 16-bit texel's channels as floats in [0, 65535].
inline Float4 loadTexel(const std::uint16_t* p) {
    using U16x4 = std::uint16_t __attribute__((vector_size(8)));
    using I32x4 = std::int32_t __attribute__((vector_size(16)));
    U16x4 v;
    std::memcpy(&v, p, sizeof v);
    return __builtin_convertvector(__builtin_convertvector(v, I32x4), Float4);
}

/// One MIP level as a lookup reads it: whole in memory (as floats or, for textures in
/// [0, 1], 16-bit fractions), or in blocks.
struct Level {
    const void* whole = nullptr;
    bool sixteenBit = false;
    int index = 0, w = 1, h = 1;
};

Level levelOf(const TexelSource& source, int index) {
    Level l;
    l.whole = source.residentLevel(index);
    l.sixteenBit = source.unitRange;
    l.index = index;
    l.w = source.width[std::size_t(index)];
    l.h = source.height[std::size_t(index)];
    return l;
}

/// Where (s, t) falls among a level's texels: the columns and rows of the four around it
/// and the weights of (x0, y0), (x1, y0), (x0, y1), (x1, y1); s (and t unless `clampT`)
/// already wrapped into [0, 1].
struct Footing {
    int x0, x1, y0, y1;
    float w00, w10, w01, w11;
};

[[gnu::always_inline]] inline Footing footing(const Level& l, float s, float t, bool clampT) {
    const int w = l.w, h = l.h;
    const float x = s * float(w) - 0.5f, y = t * float(h) - 0.5f;
    // x >= -0.5 and y clamped to [-1, h]: truncation after adding one floors them.
    const int ix = int(x + 1.0f) - 1, iy = int(std::clamp(y, -1.0f, float(h)) + 1.0f) - 1;
    const float ax = x - float(ix), ay = y - float(iy);
    Footing f;
    // ix is in [-1, w - 1] for s in [0, 1]: the texel left of the first is the last.
    f.x0 = ix < 0 ? w - 1 : std::min(ix, w - 1);
    f.x1 = f.x0 + 1 == w ? 0 : f.x0 + 1;
    if (clampT) {
        f.y0 = std::clamp(iy, 0, h - 1);
        f.y1 = std::clamp(iy + 1, 0, h - 1);
    } else {
        f.y0 = iy < 0 ? h - 1 : std::min(iy, h - 1);
        f.y1 = f.y0 + 1 == h ? 0 : f.y0 + 1;
    }
    f.w11 = ax * ay, f.w01 = ay - f.w11, f.w10 = ax - f.w11;
    f.w00 = 1.0f - ax - f.w01;
    return f;
}

template <class T, int Stride>
inline Float4 bilinearWhole(const T* whole, int w, const Footing& f) {
    const T* row0 = whole + std::size_t(f.y0) * std::size_t(w) * Stride;
    const T* row1 = whole + std::size_t(f.y1) * std::size_t(w) * Stride;
    return loadTexel(row0 + f.x0 * Stride) * f.w00 + loadTexel(row0 + f.x1 * Stride) * f.w10 +
           loadTexel(row1 + f.x0 * Stride) * f.w01 + loadTexel(row1 + f.x1 * Stride) * f.w11;
}

/// Bilinear interpolation of the four texels around (s, t) at one level; false when a block
/// could not be fetched.
[[gnu::always_inline]] inline bool bilinear(const TexelSource& source, const Level& l, float s,
                                            float t, bool clampT, Float4& out) {
    const Footing f = footing(l, s, t, clampT);
    if (l.whole) {
        if (l.sixteenBit) {
            out = bilinearWhole<std::uint16_t, 4>(static_cast<const std::uint16_t*>(l.whole), l.w,
                                                  f) *
                  (1.0f / 65535.0f);
        } else {
            out = bilinearWhole<float, 4>(static_cast<const float*>(l.whole), l.w, f);
        }
        return true;
    }
    BlockTable& blocks = table();
    const Block* last = nullptr;
    const int xs[2] = {f.x0, f.x1}, ys[2] = {f.y0, f.y1};
    const float weights[4] = {f.w00, f.w10, f.w01, f.w11};
    Float4 sum = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int k = 0; k < 4; ++k) {
        const int tx = xs[k & 1], ty = ys[k >> 1];
        if (!last || last->bx != tx >> kBlockBits || last->by != ty >> kBlockBits) {
            last = blocks.find(source, l.index, tx, ty);
            if (!last) return false;
        }
        sum += loadTexel(last->texels + ((ty & kBlockMask) * kBlock + (tx & kBlockMask)) * 4) *
               weights[k];
    }
    out = sum;
    return true;
}

/// The MIP levels a footprint of half-width `width` (level-0 texels) reads: the finer one
/// and how much of the next coarser one to blend in.
struct LevelPair {
    int fine = 0;
    float blend = 0.0f;
};

/// log2(x) for finite x >= 1 without a library call (2.6% of a textured frame): the exponent
/// plus ln(1 + m) / ln 2 for the mantissa 1 + m by Abramowitz and Stegun's 4.1.44, within
/// 1.5e-5 (a blend weight off by that much changes no colour that can be seen).
inline float log2AtLeastOne(float x) {
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int exponent = int(bits >> 23) - 127;
    bits = (bits & 0x007FFFFFu) | 0x3F800000u;
    float mantissa;
    std::memcpy(&mantissa, &bits, sizeof mantissa);
    const float m = mantissa - 1.0f;
    const float ln =
        m * (0.99949556f +
             m * (-0.49190896f + m * (0.28947478f + m * (-0.13606275f + m * 0.03215845f))));
    return float(exponent) + ln * 1.44269504f;
}

LevelPair levelsFor(const TexelSource& source, float width) {
    const float lod = width > 1.0f ? log2AtLeastOne(width) : 0.0f;
    const int last = source.levels - 1;
    const int fine = lod >= float(last) ? last : int(lod);
    return {fine, fine >= last ? 0.0f : lod - float(fine)};
}

/// Trilinear: `fine` and, weighted `blend`, `coarse`.
[[gnu::always_inline]] inline bool trilinear(const TexelSource& source, const Level& fine,
                                             const Level& coarse, float blend, float s, float t,
                                             bool clampT, Float4& out) {
    if (!bilinear(source, fine, s, t, clampT, out)) return false;
    if (blend <= 0.0f) return true;
    Float4 c;
    if (!bilinear(source, coarse, s, t, clampT, c)) return false;
    out += (c - out) * blend;
    return true;
}

}  // namespace
void setResidentTexelBudget(std::size_t bytes) {
    residentBudget.store(bytes);
}

const void* TexelSource::residentLevel(int level) const {
    auto& state = state_[std::size_t(level)];
    const unsigned char now = state.load(std::memory_order_acquire);
    if (now == kResident) return whole_[std::size_t(level)].get();
    if (now == kRefused) return nullptr;
    std::lock_guard lock(mutex_);
    if (state.load(std::memory_order_relaxed) == kUntried) {
        const std::size_t texels =
            std::size_t(width[std::size_t(level)]) * std::size_t(height[std::size_t(level)]);
        const std::size_t texelBytes = unitRange ? 4 * sizeof(std::uint16_t) : 4 * sizeof(float);
        const std::size_t bytes = texels * texelBytes;
        std::size_t spent = residentBytes.load();
        bool granted = false;
        while (texels <= kMaxResidentTexels && spent + bytes <= residentBudget.load() &&
               !(granted = residentBytes.compare_exchange_weak(spent, spent + bytes))) {
        }
        if (granted) {
            std::unique_ptr<float[]> rgb(new float[texels * 3]);
            if (fetch(level, 0, width[std::size_t(level)], 0, height[std::size_t(level)],
                      rgb.get())) {
                std::unique_ptr<unsigned char[]> kept(new unsigned char[bytes]);
                for (std::size_t i = 0; i < texels; ++i) {
                    if (unitRange) {
                        std::uint16_t q[4] = {0, 0, 0, 0};
                        for (int c = 0; c < 3; ++c)
                            q[c] = std::uint16_t(
                                std::clamp(rgb[3 * i + std::size_t(c)], 0.0f, 1.0f) * 65535.0f +
                                0.5f);
                        std::memcpy(kept.get() + i * texelBytes, q, sizeof q);
                    } else {
                        const float f[4] = {rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], 0.0f};
                        std::memcpy(kept.get() + i * texelBytes, f, sizeof f);
                    }
                }
                whole_[std::size_t(level)] = std::move(kept);
                state.store(kResident, std::memory_order_release);
                return whole_[std::size_t(level)].get();
            }
            residentBytes.fetch_sub(bytes);
        }
        state.store(kRefused, std::memory_order_release);
    }
    return state.load(std::memory_order_relaxed) == kResident ? whole_[std::size_t(level)].get()
                                                              : nullptr;
}

bool filteredLookup(const TexelSource& source, float s, float t, float dsdx, float dtdx, float dsdy,
                    float dtdy, bool clampT, Color& out) {
    if (source.levels <= 0) return false;
    s = wrapped(s);
    if (!clampT) t = wrapped(t);
    // The footprint's half-axes in level-0 texels: the derivatives span the whole footprint,
    // and a level is chosen where half of it covers a texel (as OpenImageIO does).
    const float w0 = 0.5f * float(source.width[0]), h0 = 0.5f * float(source.height[0]);
    const float xs = dsdx * w0, xt = dtdx * h0, ys = dsdy * w0, yt = dtdy * h0;
    const float lenX = std::sqrt(xs * xs + xt * xt), lenY = std::sqrt(ys * ys + yt * yt);
    const bool xMajor = lenX >= lenY;
    const float major = xMajor ? lenX : lenY, minor = xMajor ? lenY : lenX;
    LevelPair levels{source.levels - 1, 0.0f};  // inf, NaN: the image's mean
    int samples = 1;
    if (major < 1e30f) {
        // Each sample filters over `width`; enough of them line the long axis.
        const float width = std::max(minor, major / float(kMaxAnisotropy));
        levels = levelsFor(source, width);
        // Within half a texel of the centre the footprint magnifies: bilinear interpolation
        // alone is the filter, and samples along it would differ by less than a texel.
        if (width > 0.0f && major > kMagnifyingHalfAxis)
            samples = std::clamp(int(major / width + 0.5f), 1, kMaxAnisotropy);
    }
    const Level fine = levelOf(source, levels.fine);
    const Level coarse = levels.blend > 0.0f ? levelOf(source, levels.fine + 1) : fine;
    Float4 sum;
    if (samples == 1) {
        if (!trilinear(source, fine, coarse, levels.blend, s, t, clampT, sum)) return false;
    } else {
        const float ms = xMajor ? dsdx : dsdy, mt = xMajor ? dtdx : dtdy;
        sum = Float4{0.0f, 0.0f, 0.0f, 0.0f};
        for (int i = 0; i < samples; ++i) {
            const float k = (float(i) + 0.5f) / float(samples) - 0.5f;
            float ss = s + ms * k, tt = t + mt * k;
            ss = wrapped(ss);
            if (!clampT) tt = wrapped(tt);
            Float4 c;
            if (!trilinear(source, fine, coarse, levels.blend, ss, tt, clampT, c)) return false;
            sum += c;
        }
        sum *= 1.0f / float(samples);
    }
    out = Color(sum[0], sum[1], sum[2]);
    return true;
}

}  // namespace rs
