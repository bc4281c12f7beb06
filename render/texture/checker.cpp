// The solid checker's box filter: per-axis averages of a square wave, multiplied.
#include "texture/checker.h"

#include <cmath>

namespace rs {

namespace {

/// Half-widths below this (in cells) take the point value: the difference of the triangle
/// wave at the ends would lose its digits to cancellation long before the answer changed.
constexpr double kPointHalfWidth = 1e-6;
/// Beyond this half-width (in cells) the average is below 1e-6 in magnitude: 0.
constexpr double kFlatHalfWidth = 1e6;

/// The +-1 square wave: +1 on cells with an even floor, -1 on odd ones.
double squareWave(double c) {
    const double cell = floorInline(c);
    const double parity = cell - 2.0 * floorInline(0.5 * cell);  // 0 or 1, exact in double
    return 1.0 - 2.0 * parity;
}

/// The integral of the square wave from 0 to c: a triangle wave of period 2 between 0 and 1.
double squareIntegral(double c) {
    const double m = c - 2.0 * floorInline(0.5 * c);  // in [0, 2)
    return 1.0 - std::abs(m - 1.0);
}

/// The square wave's average over [c - h, c + h] (cell units) as a fraction: the average is
/// `numerator` / `denominator`, so that a product over the axes takes one division.
struct Average {
    double numerator, denominator;
};

Average squareAverage(double c, double h) {
    if (!std::isfinite(c)) return {0.0, 1.0};
    if (!(h >= kPointHalfWidth)) return {squareWave(c), 1.0};  // also a NaN half-width
    if (h >= kFlatHalfWidth) return {0.0, 1.0};
    return {squareIntegral(c + h) - squareIntegral(c - h), 2.0 * h};
}

}  // namespace

float checkerOddFraction(const Vec3& p, const Vec3& halfWidth, float scale) {
    if (!(scale > 0.0f) || !std::isfinite(scale)) return 0.0f;
    const double inv = 1.0 / double(scale);
    double numerator = 1.0, denominator = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double c = double(p[axis]) * inv + kCheckerTolerance;
        const double h = std::abs(double(halfWidth[axis])) * inv;
        const Average a = squareAverage(c, h);
        numerator *= a.numerator;
        denominator *= a.denominator;
        if (numerator == 0.0) break;
    }
    return float(0.5 - 0.5 * (numerator / denominator));
}

}  // namespace rs
