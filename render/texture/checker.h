// POV-Ray's solid checker, box-filtered analytically over a ray's footprint.
#pragma once

#include <cstddef>

#include "core/math.h"

namespace rs {

/// POV-Ray adds a small constant to each coordinate, in cell units, before taking floor() so
/// that a surface lying exactly on a cell boundary (the plane y = 0 under a checker of any
/// scale) falls in one cell instead of flickering between two with the rounding of its hit
/// points. POV-Ray 1.0 to 3.6 add Small_Tolerance / SMALL_TOLERANCE = 0.001; 3.7 adds
/// EPSILON = 1e-10 in double precision (core/material/pattern.cpp, CheckerPattern::Evaluate:
/// floor(x + EPSILON) + floor(y + EPSILON) + floor(z + EPSILON), odd -> the second colour).
/// Our hit points are floats, whose rounding (some 1e-7 of the distances involved) is far
/// larger than 1e-10, so the 3.7 constant would not hold a plane at y = 0 in one cell; we add
/// the older SMALL_TOLERANCE. Either way a point on a boundary belongs to the cell above it,
/// as in every POV-Ray; the two rules differ only within 0.001 cell below a boundary.
inline constexpr double kCheckerTolerance = 0.001;

/// The odd fraction of POV-Ray's solid checker with cells of side `scale` in object space.
/// Cell (i, j, k) = (floor(x/s + tol), floor(y/s + tol), floor(z/s + tol)) with s = `scale`
/// and tol = kCheckerTolerance; the cell is "even" (the first colour, 0) when i + j + k is
/// even and "odd" (the second colour, 1) otherwise.
///
/// Returns the fraction of the axis-aligned box centred at `p` with half-widths `halfWidth`
/// (object units, >= 0) that is odd: the exact box filter of the pattern. The checker is
/// 1/2 - 1/2 sq(x) sq(y) sq(z), with sq the +-1 square wave of period 2 cells; the average of
/// a separable product over an axis-aligned box is the product of the per-axis averages, and
/// the average of a square wave over an interval is the difference of its integral (a
/// triangle wave) at the ends, divided by the width. A half-width of 0 (or below a millionth
/// of a cell) on an axis takes the point value on that axis. Very wide boxes tend to 1/2.
/// A non-positive or non-finite `scale` gives 0 (the first colour everywhere).
float checkerOddFraction(const Vec3& p, const Vec3& halfWidth, float scale);

/// Many points' checker inputs, axis by axis (structure of arrays): point i is
/// (px[i], py[i], pz[i]) with half-widths (hx[i], hy[i], hz[i]) and cells of side scale[i].
struct CheckerPoints {
    const float *px, *py, *pz, *hx, *hy, *hz, *scale;
};

/// checkerOddFraction of `count` points into odd[0, count), several points at a time: each
/// answer is bit for bit the one checkerOddFraction gives that point alone.
void checkerOddFractions(std::size_t count, const CheckerPoints& in, float* odd);

}  // namespace rs
