// The texture filter and the per-thread table of texel blocks it reads from.
#include "texture/texel_cache.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

namespace rs {

namespace {

constexpr int kBlockBits = 4;
constexpr int kBlock = 1 << kBlockBits;  // texels a side
constexpr int kBlockMask = kBlock - 1;
constexpr int kTableBits = 10;
constexpr std::size_t kTableSize = std::size_t(1) << kTableBits;

struct Block {
    const TexelSource* source = nullptr;
    int level = -1, bx = -1, by = -1;
    bool ok = false;
    float texels[kBlock * kBlock * 3];
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
            std::copy_n(rows + std::size_t(y * w * 3), std::size_t(w * 3),
                        texels + std::size_t(y * kBlock * 3));
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

/// Bilinear interpolation of the four texels around (s, t) at one level; s (and t unless
/// `clampT`) already wrapped into [0, 1].
bool bilinear(const TexelSource& source, int level, float s, float t, bool clampT, Color& out) {
    const int w = source.width[std::size_t(level)], h = source.height[std::size_t(level)];
    const float x = s * float(w) - 0.5f, y = t * float(h) - 0.5f;
    const float fx = floorInline(x), fy = floorInline(std::clamp(y, -1.0f, float(h)));
    const float ax = x - fx, ay = y - fy;
    // fx is in [-1, w - 1] for s in [0, 1]: the texel left of the first is the last.
    const int x0 = fx < 0.0f ? w - 1 : std::min(int(fx), w - 1);
    const int x1 = x0 + 1 == w ? 0 : x0 + 1;
    int y0, y1;
    if (clampT) {
        y0 = int(std::clamp(fy, 0.0f, float(h - 1)));
        y1 = int(std::clamp(fy + 1.0f, 0.0f, float(h - 1)));
    } else {
        y0 = fy < 0.0f ? h - 1 : std::min(int(fy), h - 1);
        y1 = y0 + 1 == h ? 0 : y0 + 1;
    }
    const float* p[4];  // (x0, y0), (x1, y0), (x0, y1), (x1, y1)
    if (const float* whole = source.residentLevel(level)) {
        const float* row0 = whole + std::size_t(y0) * std::size_t(w) * 3;
        const float* row1 = whole + std::size_t(y1) * std::size_t(w) * 3;
        p[0] = row0 + x0 * 3, p[1] = row0 + x1 * 3, p[2] = row1 + x0 * 3, p[3] = row1 + x1 * 3;
    } else {
        BlockTable& blocks = table();
        const Block* last = nullptr;
        const int xs[2] = {x0, x1}, ys[2] = {y0, y1};
        for (int k = 0; k < 4; ++k) {
            const int tx = xs[k & 1], ty = ys[k >> 1];
            if (!last || last->bx != tx >> kBlockBits || last->by != ty >> kBlockBits) {
                last = blocks.find(source, level, tx, ty);
                if (!last) return false;
            }
            p[k] = last->texels + ((ty & kBlockMask) * kBlock + (tx & kBlockMask)) * 3;
        }
    }
    const float w1 = ax * ay, w0 = ay - w1, w3 = ax - w1;  // (x1,y1), (x0,y1), (x1,y0)
    const float w2 = 1.0f - ax - w0;                       // (x0, y0)
    out = Color(w2 * p[0][0] + w3 * p[1][0] + w0 * p[2][0] + w1 * p[3][0],
                w2 * p[0][1] + w3 * p[1][1] + w0 * p[2][1] + w1 * p[3][1],
                w2 * p[0][2] + w3 * p[1][2] + w0 * p[2][2] + w1 * p[3][2]);
    return true;
}

/// The MIP levels a footprint of half-width `width` (level-0 texels) reads: the finer one
/// and how much of the next coarser one to blend in.
struct LevelPair {
    int fine = 0;
    float blend = 0.0f;
};

LevelPair levelsFor(const TexelSource& source, float width) {
    const float lod = width > 1.0f ? std::log2(width) : 0.0f;
    const int last = source.levels - 1;
    const int fine = lod >= float(last) ? last : int(lod);
    return {fine, fine >= last ? 0.0f : lod - float(fine)};
}

/// Trilinear: the two levels of `levels`, blended.
bool trilinear(const TexelSource& source, float s, float t, LevelPair levels, bool clampT,
               Color& out) {
    if (!bilinear(source, levels.fine, s, t, clampT, out)) return false;
    if (levels.blend <= 0.0f) return true;
    Color coarse;
    if (!bilinear(source, levels.fine + 1, s, t, clampT, coarse)) return false;
    out += (coarse - out) * levels.blend;
    return true;
}

}  // namespace
void setResidentTexelBudget(std::size_t bytes) {
    residentBudget.store(bytes);
}

const float* TexelSource::residentLevel(int level) const {
    auto& state = state_[std::size_t(level)];
    const unsigned char now = state.load(std::memory_order_acquire);
    if (now == kResident) return whole_[std::size_t(level)].get();
    if (now == kRefused) return nullptr;
    std::lock_guard lock(mutex_);
    if (state.load(std::memory_order_relaxed) == kUntried) {
        const std::size_t texels =
            std::size_t(width[std::size_t(level)]) * std::size_t(height[std::size_t(level)]);
        const std::size_t bytes = texels * 3 * sizeof(float);
        std::size_t spent = residentBytes.load();
        bool granted = false;
        while (texels <= kMaxResidentTexels && spent + bytes <= residentBudget.load() &&
               !(granted = residentBytes.compare_exchange_weak(spent, spent + bytes))) {
        }
        if (granted) {
            std::unique_ptr<float[]> texelsRead(new float[texels * 3]);
            if (fetch(level, 0, width[std::size_t(level)], 0, height[std::size_t(level)],
                      texelsRead.get())) {
                whole_[std::size_t(level)] = std::move(texelsRead);
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
    if (!(major < 1e30f))  // inf, NaN: the image's mean
        return trilinear(source, s, t, {source.levels - 1, 0.0f}, clampT, out);
    // Each sample filters over `width`; enough of them line the long axis.
    const float width = std::max(minor, major / float(kMaxAnisotropy));
    const LevelPair levels = levelsFor(source, width);
    const int samples = width > 0.0f ? std::clamp(int(major / width + 0.5f), 1, kMaxAnisotropy) : 1;
    if (samples == 1) return trilinear(source, s, t, levels, clampT, out);
    const float ms = xMajor ? dsdx : dsdy, mt = xMajor ? dtdx : dtdy;
    Color sum(0.0f);
    for (int i = 0; i < samples; ++i) {
        const float k = (float(i) + 0.5f) / float(samples) - 0.5f;
        float ss = s + ms * k, tt = t + mt * k;
        ss = wrapped(ss);
        if (!clampT) tt = wrapped(tt);
        Color c;
        if (!trilinear(source, ss, tt, levels, clampT, c)) return false;
        sum += c;
    }
    out = sum / float(samples);
    return true;
}

}  // namespace rs
