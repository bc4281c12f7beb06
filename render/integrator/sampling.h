// Deterministic per-pixel sampling: hashed random numbers and stratified patterns.
#pragma once

#include "core/math.h"
#include "scene/document.h"

#include <cstdint>
#include <vector>

namespace rs {

/// A 32-bit integer hash (lowbias32); the same inputs give the same numbers on every thread,
/// so images do not depend on the thread count or on which tiles were re-rendered.
inline uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

/// hashCombine's second key, worked out ahead where it is used with many first keys.
inline uint32_t hashKey(uint32_t b) { return hash32(b) + 0x9e3779b9U; }
/// hashCombine(a, b) given hashKey(b).
inline uint32_t hashKeyed(uint32_t a, uint32_t key) { return hash32(a ^ key); }
/// Hash of several keys.
inline uint32_t hashCombine(uint32_t a, uint32_t b) { return hashKeyed(a, hashKey(b)); }

/// Uniform float in [0, 1) from a hash.
inline float hashToUnit(uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); }

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
    int cols, rows;

private:
    struct Stratum {
        float column, row;    ///< k % cols and k / cols.
        uint32_t keyX, keyY;  ///< hashKey(2k) and hashKey(2k + 1).
    };
    Stratum stratum(int k) const;
    /// Strata k < kMaxSampleCount (the format's limit); documents built in code may ask for
    /// more, whose strata are worked out when sampled.
    std::vector<Stratum> strata_;
};

}  // namespace rs
