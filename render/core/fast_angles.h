// atan2 without a library call, for texture coordinates looked up per ray.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/lanes.h"
#include "core/math.h"

namespace rs {

/// atan2(y, x) in [-pi, pi] without a library call (libm's atan2f, and asinf for a
/// sphere's latitude, were a tenth of the cost of a textured sphere or a sky): the octant's
/// ratio in [0, 1] through Abramowitz and Stegun's 4.4.49 polynomial, within 2e-8 radians
/// (a 16k-wide texture's texel is 4e-4). atan2Polynomial(0, 0) is 0; the sign of a zero y
/// is not kept (-0 gives +0). F is float, or FloatLanes (core/lanes.h) for four at once
/// (the same operations lane by lane, so the same bits as one float alone).
template <class F>
inline F atan2Polynomial(F y, F x) {
    const F ax = absLanes(x), ay = absLanes(y);
    const F big = ax < ay ? ay : ax, small = ay < ax ? ay : ax;  // std::max, std::min
    const F a = small / big, q = a * a;
    F r = -0.0040540580f * q + 0.0218612288f;
    r = r * q - 0.0559098861f;
    r = r * q + 0.0964200441f;
    r = r * q - 0.1390853351f;
    r = r * q + 0.1994653599f;
    r = r * q - 0.3332985605f;
    r = (r * q + 0.9999993329f) * a;
    r = ay > ax ? 0.5f * kPi - r : r;
    r = x < 0.0f ? kPi - r : r;
    r = y < 0.0f ? -r : r;
    return big > 0.0f ? r : F{};
}

}  // namespace rs
