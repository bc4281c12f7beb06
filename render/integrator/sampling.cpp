// Stratified sample patterns for supersampling and sphere lights.
#include "integrator/sampling.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rs {

namespace {
int exactSqrt(int n) {
    int r = int(std::lround(std::sqrt(double(n))));
    return r * r == n ? r : 0;
}
}  // namespace

Vec3 pixelSampleOffset(int k, int n, uint32_t seed) {
    if (n <= 1) return Vec3(0.5f, 0.5f, 0.0f);
    if (int r = exactSqrt(n)) {
        return Vec3((float(k % r) + 0.5f) / float(r), (float(k / r) + 0.5f) / float(r), 0.0f);
    }
    // n-rooks: one sample per column and per row, rows assigned by a hashed permutation.
    // The permutation is k -> (a*k + b) mod n with a coprime to n.
    uint32_t h = hash32(seed);
    uint32_t a = 1 + (h % uint32_t(n));
    while (std::gcd(a, uint32_t(n)) != 1) a = a % uint32_t(n) + 1;
    uint32_t row = (a * uint32_t(k) + (h >> 16)) % uint32_t(n);
    float jx = hashToUnit(hashCombine(seed, uint32_t(2 * k)));
    float jy = hashToUnit(hashCombine(seed, uint32_t(2 * k + 1)));
    return Vec3((float(k) + jx) / float(n), (float(row) + jy) / float(n), 0.0f);
}

DiskStrata::DiskStrata(int n)
    : cols(std::max(1, int(std::ceil(std::sqrt(double(n)))))), rows((n + cols - 1) / cols) {
    strata_.resize(std::size_t(std::clamp(n, 0, kMaxSampleCount)));
    for (std::size_t k = 0; k < strata_.size(); ++k) strata_[k] = stratum(int(k));
}

DiskStrata::Stratum DiskStrata::stratum(int k) const {
    return {float(k % cols), float(k / cols), hashKey(uint32_t(2 * k)), hashKey(uint32_t(2 * k + 1))};
}

Vec3 DiskStrata::sample(int k, uint32_t seed) const {
    // Strata on a cols x rows grid covering n (the last row may be partial), then
    // Shirley-Chiu concentric mapping keeps strata compact on the disk.
    const Stratum cell = std::size_t(k) < strata_.size() ? strata_[std::size_t(k)] : stratum(k);
    float jx = hashToUnit(hashKeyed(seed, cell.keyX));
    float jy = hashToUnit(hashKeyed(seed, cell.keyY));
    float sx = 2.0f * (cell.column + jx) / float(cols) - 1.0f;
    float sy = 2.0f * (cell.row + jy) / float(rows) - 1.0f;
    if (sx == 0.0f && sy == 0.0f) return Vec3(0.0f);
    float r, phi;
    if (std::abs(sx) > std::abs(sy)) {
        r = sx;
        phi = (kPi / 4.0f) * (sy / sx);
    } else {
        r = sy;
        phi = (kPi / 2.0f) - (kPi / 4.0f) * (sx / sy);
    }
    return Vec3(r * std::cos(phi), r * std::sin(phi), 0.0f);
}

Vec3 stratifiedDiskSample(int k, int n, uint32_t seed) { return DiskStrata(n).sample(k, seed); }

}  // namespace rs
