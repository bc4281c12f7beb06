// A Vec3 in the lanes of an SSE vector, for code that works on points four floats at a time.
#pragma once

#include <cstring>

#include "core/math.h"

#if defined(__SSE2__)
#include <immintrin.h>

namespace rs {

/// v's x, y and z as lanes 0-2 (lane 3 is 0), read with two loads: x and y as one 8-byte
/// load, copied since a Vec3 is only 4-byte aligned (a load through a double pointer would be
/// a misaligned access).
inline __m128 lanes(const Vec3& v) {
    double xy;
    std::memcpy(&xy, &v.x, sizeof xy);
    return _mm_movelh_ps(_mm_castpd_ps(_mm_set_sd(xy)), _mm_load_ss(&v.z));
}

}  // namespace rs
#endif
