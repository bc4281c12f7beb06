// Stratified sample patterns for supersampling and sphere lights.
#include "integrator/sampling.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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

namespace {

/// What stratum k of a grid `cols` wide is: its cell and the hash keys of its jitter.
struct Stratum {
    float column, row;
    uint32_t keyX, keyY;
};
Stratum stratum(int k, int cols) {
    return {float(k % cols), float(k / cols), hashKey(uint32_t(2 * k)),
            hashKey(uint32_t(2 * k + 1))};
}

}  // namespace

DiskStrata::DiskStrata(int n)
    : cols(std::max(1, int(std::ceil(std::sqrt(double(n)))))), rows((n + cols - 1) / cols) {
    const std::size_t tabled = std::size_t(std::clamp(n, 0, kMaxSampleCount));
    column_.resize(tabled), row_.resize(tabled), keyX_.resize(tabled), keyY_.resize(tabled);
    for (std::size_t k = 0; k < tabled; ++k) {
        const Stratum s = stratum(int(k), cols);
        column_[k] = s.column, row_[k] = s.row, keyX_[k] = s.keyX, keyY_[k] = s.keyY;
    }
}

template <class F, class U>
void DiskStrata::point(F column, F row, U keyX, U keyY, uint32_t seed, F& x, F& y) const {
    // Strata on a cols x rows grid covering n (the last row may be partial), then
    // Shirley-Chiu concentric mapping keeps strata compact on the disk. Both branches of the
    // mapping are worked out and one is selected (per lane); the centre maps to itself.
    const F jx = unitOf(hashKeyed(seed, keyX));
    const F jy = unitOf(hashKeyed(seed, keyY));
    const F sx = 2.0f * (column + jx) / float(cols) - 1.0f;
    const F sy = 2.0f * (row + jy) / float(rows) - 1.0f;
    const auto wide = absLanes(sx) > absLanes(sy);
    const F r = select(wide, sx, sy);
    // phi = pi/4 (sy / sx) where wide, else pi/2 - a with a = pi/4 (sx / sy), whose cos and
    // sin are a's sin and cos: one polynomial on [-pi/4, pi/4] serves both branches.
    const F a = (kPi / 4.0f) * select(wide, sy / sx, sx / sy);
    F s, c;
    sinCosQuarter(a, s, c);
    const auto centre = (sx == 0.0f) & (sy == 0.0f);
    x = select(centre, F{}, r * select(wide, c, s));
    y = select(centre, F{}, r * select(wide, s, c));
}

Vec3 DiskStrata::sample(int k, uint32_t seed) const {
    const std::size_t i = std::size_t(k);
    const Stratum s =
        i < column_.size() ? Stratum{column_[i], row_[i], keyX_[i], keyY_[i]} : stratum(k, cols);
    float x, y;
    point(s.column, s.row, s.keyX, s.keyY, seed, x, y);
    return Vec3(x, y, 0.0f);
}

void DiskStrata::sampleLanes(int k, uint32_t seed, FloatLanes& x, FloatLanes& y) const {
    const std::size_t i = std::size_t(k);
    FloatLanes column, row;
    UintLanes keyX, keyY;
    std::memcpy(&column, column_.data() + i, sizeof column);
    std::memcpy(&row, row_.data() + i, sizeof row);
    std::memcpy(&keyX, keyX_.data() + i, sizeof keyX);
    std::memcpy(&keyY, keyY_.data() + i, sizeof keyY);
    point(column, row, keyX, keyY, seed, x, y);
}

Vec3 stratifiedDiskSample(int k, int n, uint32_t seed) {
    return DiskStrata(n).sample(k, seed);
}

}  // namespace rs
