// Deterministic per-pixel sampling: hashed random numbers and stratified patterns.
#pragma once

#include <cstdint>
#include <vector>

#include "core/lanes.h"
#include "core/math.h"
#include "scene/document.h"

namespace rs {

/// hash32 of one key (U = uint32_t) or of each lane of UintLanes.
template <class U>
inline U hashBits(U x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

/// A 32-bit integer hash (lowbias32); the same inputs give the same numbers on every thread,
/// so images do not depend on the thread count or on which tiles were re-rendered.
inline uint32_t hash32(uint32_t x) {
    return hashBits(x);
}

/// hashCombine's second key, worked out ahead where it is used with many first keys.
inline uint32_t hashKey(uint32_t b) {
    return hash32(b) + 0x9e3779b9U;
}
/// hashCombine(a, b) given hashKey(b) (one key, or a lane of keys).
template <class U>
inline U hashKeyed(uint32_t a, U key) {
    return hashBits(a ^ key);
}
/// Hash of several keys.
inline uint32_t hashCombine(uint32_t a, uint32_t b) {
    return hashKeyed(a, hashKey(b));
}

/// hashToUnit of one hash or of each lane. h >> 8 < 2^24 converts exactly as signed, which
/// SSE2 does in one instruction (unsigned lanes take several).
template <class U>
inline auto unitOf(U h) {
    return toFloat31(h >> 8) * (1.0f / 16777216.0f);
}
/// Uniform float in [0, 1) from a hash.
inline float hashToUnit(uint32_t h) {
    return unitOf(h);
}

/// Position of sample `k` of `n` inside a pixel, in [0, 1)^2: a regular sub-grid at cell
/// centres when n is a perfect square, otherwise n-rooks stratified jitter seeded by `seed`.
Vec3 pixelSampleOffset(int k, int n, uint32_t seed);

/// Sample `k` of `n` on the disk of radius 1 (z = 0), stratified by a concentric mapping of
/// a sub-grid with hashed jitter. Used for sphere lights: the disk faces the shading point.
Vec3 stratifiedDiskSample(int k, int n, uint32_t seed);

/// stratifiedDiskSample's grid for n samples, worked out once for all k (and every light and
/// shading point): each stratum's cell and the hash keys of its jitter.
struct DiskStrata {
    explicit DiskStrata(int n);
    /// stratifiedDiskSample(k, n, seed), for 0 <= k < n.
    Vec3 sample(int k, uint32_t seed) const;
    /// Samples k ... k + kLaneWidth - 1 at once, their x and y (z is 0) lane by lane: the
    /// bits of sample() for each. Needs k + kLaneWidth <= laned().
    void sampleLanes(int k, uint32_t seed, FloatLanes& x, FloatLanes& y) const;
    /// How many strata sampleLanes may reach.
    int laned() const { return int(column_.size()); }
    int cols, rows;

private:
    template <class F, class U>
    void point(F column, F row, U keyX, U keyY, uint32_t seed, F& x, F& y) const;
    /// Strata k < kMaxSampleCount (the format's limit) as structure of arrays: k % cols,
    /// k / cols, hashKey(2k), hashKey(2k + 1). Documents built in code may ask for more,
    /// whose strata are worked out when sampled.
    std::vector<float> column_, row_;
    std::vector<uint32_t> keyX_, keyY_;
};

}  // namespace rs
