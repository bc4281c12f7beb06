// floor() on the lanes of a GCC vector, exact, without SSE4.1's round instructions.
#pragma once

#include <type_traits>

namespace rs {

/// floor() of each lane of a GCC vector of floats or doubles, exact: rounding |x| to an
/// integer by adding and subtracting 2^23 (float) or 2^52 (double), where the type's spacing
/// reaches 1 and above which every value is an integer, then stepping down where that
/// rounded up. NaNs and infinities pass through. Needs -ffp-contract=off and no fast-math
/// (the sum and difference must not be folded away).
template <class V>
inline V floorLanes(V x) {
    using T = std::remove_cvref_t<decltype(x[0])>;
    constexpr T big = std::is_same_v<T, double> ? T(4503599627370496.0) : T(8388608.0);
    const V ax = x < T(0) ? -x : x;
    V r = (ax + big) - big;
    r = ax < big ? r : ax;
    const V rx = x < T(0) ? -r : r;
    return rx > x ? rx - T(1) : rx;
}

}  // namespace rs
