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
    std::uint64_t source = 0;  ///< Its source's serial (0: none; serials start at 1).
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
        const std::uint64_t key = source.serial;
        const std::size_t slot =
            (std::size_t(bx) * 0x9E3779B1u ^ std::size_t(by) * 0x85EBCA77u ^
             std::size_t(level) * 0xC2B2AE3Du ^ std::size_t(key) * 0x27D4EB2Fu) >>
                (32 - kTableBits) &
            (kTableSize - 1);
        Block& b = blocks_[slot];
        if (b.source != key || b.level != level || b.bx != bx || b.by != by) {
            b.source = key;
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
std::atomic<std::uint64_t> lastSerial{0};

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

using Float8 = float __attribute__((vector_size(32)));
/// Two neighbouring texels of a row, (x, y) in lanes 0-3 and (x + 1, y) in lanes 4-7.
/// (Out parameters: a 32-byte vector returned by value would change the ABI with AVX.)
inline void loadPair(const float* p, Float8& v) {
    std::memcpy(&v, p, sizeof v);
}
/// Two neighbouring 16-bit texels as floats in [0, 65535].
inline void loadPair(const std::uint16_t* p, Float8& out) {
    using U16x8 = std::uint16_t __attribute__((vector_size(16)));
    using I32x8 = std::int32_t __attribute__((vector_size(32)));
    U16x8 v;
    std::memcpy(&v, p, sizeof v);
    out = __builtin_convertvector(__builtin_convertvector(v, I32x8), Float8);
}

/// The bilinear blend of texels (x0, y0), (x1, y0) (`top`, lanes 0-3 and 4-7) and (x0, y1),
/// (x1, y1) (`bottom`): down the columns by `ay`, then across by `ax`. Every path computes
/// it this way, so whole levels and blocks give the same bits.
inline Float4 blend(const Float8& top, const Float8& bottom, float ax, float ay) {
    const Float8 columns = top + (bottom - top) * ay;
    Float4 left, right;
    std::memcpy(&left, &columns, sizeof left);
    std::memcpy(&right, reinterpret_cast<const char*>(&columns) + sizeof left, sizeof right);
    return left + (right - left) * ax;
}

/// One MIP level as a lookup reads it: whole in memory (as floats or, for textures in
/// [0, 1], 16-bit fractions; each row one texel longer than the level, repeating its first
/// texel), or in blocks.
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
/// and the fractions across (ax) and down (ay); s (and t unless `clampT`) already wrapped
/// into [0, 1].
struct Footing {
    int x0, x1, y0, y1;
    float ax, ay;
};

template <bool ClampT>
[[gnu::always_inline]] inline Footing footing(int w, int h, float s, float t) {
    const float x = s * float(w) - 0.5f, y = t * float(h) - 0.5f;
    // x >= -0.5 and y clamped to [-1, h]: truncation after adding one floors them.
    const int ix = int(x + 1.0f) - 1, iy = int(std::clamp(y, -1.0f, float(h)) + 1.0f) - 1;
    Footing f;
    f.ax = x - float(ix), f.ay = y - float(iy);
    // ix is in [-1, w - 1] for s in [0, 1]: the texel left of the first is the last.
    f.x0 = ix < 0 ? w - 1 : std::min(ix, w - 1);
    f.x1 = f.x0 + 1 == w ? 0 : f.x0 + 1;
    if (ClampT) {
        f.y0 = std::clamp(iy, 0, h - 1);
        f.y1 = std::clamp(iy + 1, 0, h - 1);
    } else {
        f.y0 = iy < 0 ? h - 1 : std::min(iy, h - 1);
        f.y1 = f.y0 + 1 == h ? 0 : f.y0 + 1;
    }
    return f;
}

/// A whole level's texels as the filter reads them: rows of w + 1 texels (the last repeats
/// the first, so a texel's right neighbour always lies next to it in memory).
template <class T>
struct Whole {
    const T* texels;
    int w, h;
};

template <class T, bool ClampT>
[[gnu::always_inline]] inline Float4 bilinearWhole(const Whole<T>& l, float s, float t) {
    const Footing f = footing<ClampT>(l.w, l.h, s, t);
    const std::size_t stride = std::size_t(l.w + 1) * 4;
    const T* column = l.texels + std::size_t(f.x0) * 4;
    Float8 top, bottom;
    loadPair(column + std::size_t(f.y0) * stride, top);
    loadPair(column + std::size_t(f.y1) * stride, bottom);
    return blend(top, bottom, f.ax, f.ay);
}

/// Bilinear interpolation of the four texels around (s, t) at a level read in blocks; false
/// when a block could not be fetched.
template <bool ClampT>
bool bilinearBlocks(const TexelSource& source, const Level& l, float s, float t, Float4& out) {
    const Footing f = footing<ClampT>(l.w, l.h, s, t);
    BlockTable& blocks = table();
    const Block* last = nullptr;
    const int xs[2] = {f.x0, f.x1}, ys[2] = {f.y0, f.y1};
    Float4 texel[4];
    for (int k = 0; k < 4; ++k) {
        const int tx = xs[k & 1], ty = ys[k >> 1];
        if (!last || last->bx != tx >> kBlockBits || last->by != ty >> kBlockBits) {
            last = blocks.find(source, l.index, tx, ty);
            if (!last) return false;
        }
        texel[k] = loadTexel(last->texels + ((ty & kBlockMask) * kBlock + (tx & kBlockMask)) * 4);
    }
    Float8 top, bottom;
    std::memcpy(&top, &texel[0], sizeof top);
    std::memcpy(&bottom, &texel[2], sizeof bottom);
    out = blend(top, bottom, f.ax, f.ay);
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

/// Where the samples of one lookup lie: `samples` points spread evenly along (ms, mt) about
/// (s, t), each read trilinearly at `fine` and, weighted `blend`, the next coarser level.
struct Spread {
    float s, t, ms, mt, blend;
    int samples;
};

template <bool ClampT>
[[gnu::always_inline]] inline void samplePoint(const Spread& a, int i, float step, float& s,
                                               float& t) {
    const float k = (float(i) + 0.5f) * step - 0.5f;
    s = wrapped(a.s + a.ms * k);
    t = ClampT ? a.t + a.mt * k : wrapped(a.t + a.mt * k);
}

using Int4 = std::int32_t __attribute__((vector_size(16)));

/// floor(x) lane by lane, for |x| < 2^31.
inline Float4 floorLanes(const Float4& x) {
    const Float4 t = __builtin_convertvector(__builtin_convertvector(x, Int4), Float4);
    return t > x ? t - 1.0f : t;
}

/// footing() of four points at once, at levels of fw x fh texels (w x h as integers), lane by
/// lane; the same operations, so each lane gets footing()'s bits. Whole levels need no x1:
/// their rows repeat the first texel at the end.
struct FootingLanes {
    Int4 x0, y0, y1;
    Float4 ax, ay;
};
template <bool ClampT>
[[gnu::always_inline]] inline FootingLanes footingLanes(const Float4& s, const Float4& t,
                                                        const Float4& fw, const Float4& fh,
                                                        const Int4& w, const Int4& h) {
    const Float4 x = s * fw - 0.5f, y = t * fh - 0.5f;
    const Float4 yc = y < -1.0f ? Float4{} - 1.0f : (y > fh ? fh : y);
    const Int4 ix = __builtin_convertvector(x + 1.0f, Int4) - 1;
    const Int4 iy = __builtin_convertvector(yc + 1.0f, Int4) - 1;
    FootingLanes f;
    f.ax = x - __builtin_convertvector(ix, Float4);
    f.ay = y - __builtin_convertvector(iy, Float4);
    f.x0 = ix < 0 ? w - 1 : (ix < w - 1 ? ix : w - 1);
    if (ClampT) {
        const Int4 below = iy + 1;
        f.y0 = iy < 0 ? Int4{} : (iy < h - 1 ? iy : h - 1);
        f.y1 = below < 0 ? Int4{} : (below < h - 1 ? below : h - 1);
    } else {
        f.y0 = iy < 0 ? h - 1 : (iy < h - 1 ? iy : h - 1);
        f.y1 = f.y0 + 1 == h ? Int4{} : f.y0 + 1;
    }
    return f;
}

/// The filter over two whole levels: no call and no lock, only loads. The bilinear samples
/// of a lookup (each sample point at the fine level and, when `blend` > 0, the coarse one)
/// find their texels four at a time in vector lanes; each is then two loads of two texels.
template <class T, bool ClampT>
Float4 filterWhole(const Whole<T>& fine, const Whole<T>& coarse, const Spread& a, float scale) {
    // One point (the lanes would be half empty), or points this far out (they would overflow
    // the lanes' integer conversion): one at a time.
    if (a.samples == 1 || !(std::abs(a.ms) < 1e6f && std::abs(a.mt) < 1e6f)) {
        const float step = 1.0f / float(a.samples);
        Float4 sum = {0.0f, 0.0f, 0.0f, 0.0f};
        for (int i = 0; i < a.samples; ++i) {
            float s = a.s, t = a.t;
            if (a.samples > 1) samplePoint<ClampT>(a, i, step, s, t);
            Float4 c = bilinearWhole<T, ClampT>(fine, s, t);
            if (a.blend > 0.0f) c += (bilinearWhole<T, ClampT>(coarse, s, t) - c) * a.blend;
            sum += c;
        }
        return sum * (step * scale);
    }
    const bool both = a.blend > 0.0f;
    const int lanes = a.samples * (both ? 2 : 1);
    const float step = 1.0f / float(a.samples);
    // Lane l of a group of four: sample l (one level), or sample l / 2 at level l % 2.
    const Int4 odd = both ? Int4{0, -1, 0, -1} : Int4{0, 0, 0, 0};
    const Float4 laneSample =
        both ? Float4{0.0f, 0.0f, 1.0f, 1.0f} : Float4{0.0f, 1.0f, 2.0f, 3.0f};
    const float groupSamples = both ? 2.0f : 4.0f;
    const Float4 fw = odd ? float(coarse.w) : float(fine.w);
    const Float4 fh = odd ? float(coarse.h) : float(fine.h);
    const Int4 w = odd ? coarse.w : fine.w, h = odd ? coarse.h : fine.h;
    const float fineWeight = (both ? 1.0f - a.blend : 1.0f) * step * scale;
    const float coarseWeight = a.blend * step * scale;
    const T* base[2] = {fine.texels, coarse.texels};
    const std::size_t stride[2] = {std::size_t(fine.w + 1) * 4, std::size_t(coarse.w + 1) * 4};
    Float4 sum = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int first = 0; first < lanes; first += 4) {
        const Float4 k = (laneSample + (float(first) / 4.0f * groupSamples + 0.5f)) * step - 0.5f;
        Float4 s = a.s + a.ms * k, t = a.t + a.mt * k;
        s -= floorLanes(s);
        if (!ClampT) t -= floorLanes(t);
        const FootingLanes f = footingLanes<ClampT>(s, t, fw, fh, w, h);
        const int count = std::min(4, lanes - first);
        for (int l = 0; l < count; ++l) {
            const int level = odd[l] ? 1 : 0;
            const T* column = base[level] + std::size_t(f.x0[l]) * 4;
            Float8 top, bottom;
            loadPair(column + std::size_t(f.y0[l]) * stride[level], top);
            loadPair(column + std::size_t(f.y1[l]) * stride[level], bottom);
            sum += blend(top, bottom, f.ax[l], f.ay[l]) * (level ? coarseWeight : fineWeight);
        }
    }
    return sum;
}

/// The same filter where a level is read in blocks (or only one of the two is whole).
template <bool ClampT>
bool filterBlocks(const TexelSource& source, const Level& fine, const Level& coarse,
                  const Spread& a, Float4& out) {
    const auto bilinear = [&](const Level& l, float s, float t, Float4& c) {
        if (!l.whole) return bilinearBlocks<ClampT>(source, l, s, t, c);
        if (l.sixteenBit)
            c = bilinearWhole<std::uint16_t, ClampT>(
                    {static_cast<const std::uint16_t*>(l.whole), l.w, l.h}, s, t) *
                (1.0f / 65535.0f);
        else
            c = bilinearWhole<float, ClampT>({static_cast<const float*>(l.whole), l.w, l.h}, s, t);
        return true;
    };
    const float step = a.samples == 1 ? 1.0f : 1.0f / float(a.samples);
    Float4 sum = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int i = 0; i < a.samples; ++i) {
        float s = a.s, t = a.t;
        if (a.samples > 1) samplePoint<ClampT>(a, i, step, s, t);
        Float4 c, d;
        if (!bilinear(fine, s, t, c)) return false;
        if (a.blend > 0.0f) {
            if (!bilinear(coarse, s, t, d)) return false;
            c += (d - c) * a.blend;
        }
        sum += c;
    }
    out = a.samples == 1 ? sum : sum * step;
    return true;
}

}  // namespace
void setResidentTexelBudget(std::size_t bytes) {
    residentBudget.store(bytes);
}

std::size_t residentTexelBytes() {
    return residentBytes.load();
}

TexelSource::TexelSource() : serial(++lastSerial) {}

TexelSource::~TexelSource() {
    for (int level = 0; level < kMaxMipLevels; ++level)
        if (whole_[std::size_t(level)]) residentBytes.fetch_sub(wholeBytes(level));
}

std::size_t TexelSource::wholeBytes(int level) const {
    const std::size_t w = std::size_t(width[std::size_t(level)]);
    const std::size_t h = std::size_t(height[std::size_t(level)]);
    const std::size_t texelBytes = unitRange ? 4 * sizeof(std::uint16_t) : 4 * sizeof(float);
    return (w + 1) * h * texelBytes;  // each row's first texel twice
}

const void* TexelSource::decideResident(int level) const {
    auto& state = state_[std::size_t(level)];
    std::lock_guard lock(mutex_);
    if (state.load(std::memory_order_relaxed) == kUntried) {
        const std::size_t w = std::size_t(width[std::size_t(level)]);
        const std::size_t h = std::size_t(height[std::size_t(level)]);
        const std::size_t texels = w * h;
        const std::size_t texelBytes = unitRange ? 4 * sizeof(std::uint16_t) : 4 * sizeof(float);
        const std::size_t bytes = wholeBytes(level);
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
                for (std::size_t k = 0; k < (w + 1) * h; ++k) {
                    const std::size_t i = k / (w + 1) * w + k % (w + 1) % w;  // source texel
                    if (unitRange) {
                        std::uint16_t q[4] = {0, 0, 0, 0};
                        for (int c = 0; c < 3; ++c)
                            q[c] = std::uint16_t(
                                std::clamp(rgb[3 * i + std::size_t(c)], 0.0f, 1.0f) * 65535.0f +
                                0.5f);
                        std::memcpy(kept.get() + k * texelBytes, q, sizeof q);
                    } else {
                        const float f[4] = {rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], 0.0f};
                        std::memcpy(kept.get() + k * texelBytes, f, sizeof f);
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
    const float squareX = xs * xs + xt * xt, squareY = ys * ys + yt * yt;
    // Both half-axes within half a texel (most sky lookups): the finest level, one sample,
    // as the general choice below would make, without its square roots and logarithm.
    LevelPair levels{0, 0.0f};
    int samples = 1;
    bool xMajor = true;
    if (!(squareX <= 0.25f && squareY <= 0.25f)) {
        const float lenX = std::sqrt(squareX), lenY = std::sqrt(squareY);
        xMajor = lenX >= lenY;
        const float major = xMajor ? lenX : lenY, minor = xMajor ? lenY : lenX;
        levels = {source.levels - 1, 0.0f};  // inf, NaN: the image's mean
        if (major < 1e30f) {
            // Each sample filters over `width`; enough of them line the long axis.
            const float width = std::max(minor, major / float(kMaxAnisotropy));
            levels = levelsFor(source, width);
            // Within half a texel of the centre the footprint magnifies: bilinear
            // interpolation alone is the filter, and samples along it would differ by less
            // than a texel.
            if (width > 0.0f && major > kMagnifyingHalfAxis)
                samples = std::clamp(int(major / width + 0.5f), 1, kMaxAnisotropy);
        }
    }
    Spread spread{s, t, 0.0f, 0.0f, levels.blend, samples};
    if (samples > 1) {
        spread.ms = xMajor ? dsdx : dsdy;
        spread.mt = xMajor ? dtdx : dtdy;
    }
    // The levels as scalars, not as Level records: a record chosen by a condition was
    // assembled on the stack and read back whole, a store-forwarding stall a lookup.
    const int fi = levels.fine, ci = levels.blend > 0.0f ? levels.fine + 1 : levels.fine;
    const void* fineWhole = source.residentLevel(fi);
    const void* coarseWhole = ci == fi ? fineWhole : source.residentLevel(ci);
    const int fw = source.width[std::size_t(fi)], fh = source.height[std::size_t(fi)];
    const int cw = source.width[std::size_t(ci)], ch = source.height[std::size_t(ci)];
    Float4 sum;
    if (fineWhole && coarseWhole) {
        if (source.unitRange) {
            using W = Whole<std::uint16_t>;
            const W f{static_cast<const std::uint16_t*>(fineWhole), fw, fh};
            const W c{static_cast<const std::uint16_t*>(coarseWhole), cw, ch};
            constexpr float kScale = 1.0f / 65535.0f;
            sum = clampT ? filterWhole<std::uint16_t, true>(f, c, spread, kScale)
                         : filterWhole<std::uint16_t, false>(f, c, spread, kScale);
        } else {
            using W = Whole<float>;
            const W f{static_cast<const float*>(fineWhole), fw, fh};
            const W c{static_cast<const float*>(coarseWhole), cw, ch};
            sum = clampT ? filterWhole<float, true>(f, c, spread, 1.0f)
                         : filterWhole<float, false>(f, c, spread, 1.0f);
        }
    } else {
        const Level fine = levelOf(source, fi), coarse = levelOf(source, ci);
        if (!(clampT ? filterBlocks<true>(source, fine, coarse, spread, sum)
                     : filterBlocks<false>(source, fine, coarse, spread, sum)))
            return false;
    }
    out = Color(sum[0], sum[1], sum[2]);
    return true;
}

namespace {

/// magnifiedSpots at a whole level of w x h texels: filterWhole's one-sample path in lanes.
template <class T>
void magnifiedWhole(const T* texels, int w, int h, const Float4& s, const Float4& t, float scale,
                    Color* out) {
    const FootingLanes f =
        footingLanes<true>(s, t, Float4{} + float(w), Float4{} + float(h), Int4{} + w, Int4{} + h);
    const std::size_t stride = std::size_t(w + 1) * 4;
    for (int l = 0; l < 4; ++l) {
        const T* column = texels + std::size_t(f.x0[l]) * 4;
        Float8 top, bottom;
        loadPair(column + std::size_t(f.y0[l]) * stride, top);
        loadPair(column + std::size_t(f.y1[l]) * stride, bottom);
        const Float4 c = (Float4{} + blend(top, bottom, f.ax[l], f.ay[l])) * scale;
        out[l] = Color(c[0], c[1], c[2]);
    }
}

}  // namespace

bool magnifiedSpots(const TexelSource& source, const EnvironmentSpot* spots, Color* out) {
    if (source.levels <= 0) return false;
    // The four spots' fields, lane by lane (each spot is four floats: one row).
    static_assert(sizeof(EnvironmentSpot) == sizeof(Float4));
    Float4 row[4];
    std::memcpy(row, spots, sizeof row);
    const Float4 st01 = __builtin_shufflevector(row[0], row[1], 0, 1, 4, 5);
    const Float4 st23 = __builtin_shufflevector(row[2], row[3], 0, 1, 4, 5);
    const Float4 wide01 = __builtin_shufflevector(row[0], row[1], 2, 3, 6, 7);
    const Float4 wide23 = __builtin_shufflevector(row[2], row[3], 2, 3, 6, 7);
    Float4 s = __builtin_shufflevector(st01, st23, 0, 2, 4, 6);
    const Float4 t = __builtin_shufflevector(st01, st23, 1, 3, 5, 7);
    const Float4 ds = __builtin_shufflevector(wide01, wide23, 0, 2, 4, 6);
    const Float4 dt = __builtin_shufflevector(wide01, wide23, 1, 3, 5, 7);
    // filteredLookup's test for one magnified sample at level 0, with derivatives (ds, 0) and
    // (0, dt): the zero terms add nothing to the squares. Coordinates must be finite.
    const float w0 = 0.5f * float(source.width[0]), h0 = 0.5f * float(source.height[0]);
    const Float4 xs = ds * w0, yt = dt * h0;
    const Int4 magnified =
        (xs * xs <= 0.25f) & (yt * yt <= 0.25f) & (s - s == 0.0f) & (t - t == 0.0f);
    if (!(magnified[0] & magnified[1] & magnified[2] & magnified[3])) return false;
    const void* whole = source.residentLevel(0);
    if (!whole) return false;
    s -= floorLanes(s);  // wrapped()
    const int w = source.width[0], h = source.height[0];
    if (source.unitRange)
        magnifiedWhole(static_cast<const std::uint16_t*>(whole), w, h, s, t, 1.0f / 65535.0f, out);
    else
        magnifiedWhole(static_cast<const float*>(whole), w, h, s, t, 1.0f, out);
    return true;
}

}  // namespace rs
