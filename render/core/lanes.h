// Four float or integer lanes (GCC vector extensions: one SSE2 register, the x86-64 baseline,
// so the lanes cost no ABI note and need no run-time dispatch) and the few operations light
// sampling needs on them, each with a scalar overload of the same name: one template body is
// then both the one-sample and the four-sample code. Every operation is lane-wise IEEE (or
// integer) arithmetic, so lane k has the bits the scalar overload gives (with
// -ffp-contract=off, which the library is built with: no multiply-add is fused).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace rs {

inline constexpr int kLaneWidth = 4;
using FloatLanes = float __attribute__((vector_size(16)));
using UintLanes = uint32_t __attribute__((vector_size(16)));
using MaskLanes = int32_t __attribute__((vector_size(16)));  ///< A comparison's result.

/// Every lane v.
inline FloatLanes splat(float v) {
    return FloatLanes{v, v, v, v};
}

/// Four floats from p, and four to p (any alignment).
inline FloatLanes loadLanes(const float* p) {
    FloatLanes v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
}
inline void storeLanes(float* p, FloatLanes v) {
    __builtin_memcpy(p, &v, sizeof v);
}
/// Elements [first, first + 4) of an array of `count` floats as lanes: one load when all
/// four are there, else one at a time with element `first` in the places past the end.
/// (Lanes filled one by one through memory and read back as a vector would wait on store
/// forwarding; a whole group never does.)
inline FloatLanes gatherLanes(const float* p, std::size_t first, std::size_t count) {
    if (first + kLaneWidth <= count) return loadLanes(p + first);
    FloatLanes v{};
    for (std::size_t k = 0; k < std::size_t(kLaneWidth); ++k)
        v[k] = p[first + k < count ? first + k : first];
    return v;
}

/// float of values below 2^31 (converted as the signed integers they equal): one SSE2
/// conversion per lane, where unsigned lanes take several.
inline float toFloat31(uint32_t v) {
    return float(int32_t(v));
}
inline FloatLanes toFloat31(UintLanes v) {
    return __builtin_convertvector(reinterpret_cast<MaskLanes>(v), FloatLanes);
}

/// |v| (the sign bit cleared, as std::abs does).
inline float absLanes(float v) {
    return std::abs(v);
}
inline FloatLanes absLanes(FloatLanes v) {
    return reinterpret_cast<FloatLanes>(reinterpret_cast<UintLanes>(v) & 0x7fffffffu);
}

/// Whether the mask holds anywhere (the one mask, or any lane).
inline bool anyLane(bool m) {
    return m;
}
inline bool anyLane(MaskLanes m) {
    return (m[0] | m[1] | m[2] | m[3]) != 0;
}

inline float select(bool m, float a, float b) {
    return m ? a : b;
}
inline FloatLanes select(MaskLanes m, FloatLanes a, FloatLanes b) {
    return m ? a : b;
}

inline float sqrtLanes(float v) {
    return std::sqrt(v);
}
/// (SSE's sqrtps where there is SSE: correctly rounded, as each lane's std::sqrt, in one
/// instruction instead of four calls guarded for errno.)
inline FloatLanes sqrtLanes(FloatLanes v) {
#if defined(__SSE__)
    return __builtin_ia32_sqrtps(v);
#else
    for (int k = 0; k < kLaneWidth; ++k) v[k] = std::sqrt(v[k]);
    return v;
#endif
}

/// m ? s * v^e : 0, lane by lane through the scalar std::pow, which runs only where m holds.
inline float scaledPowWhere(bool m, float s, float v, float e) {
    return m ? s * std::pow(v, e) : 0.0f;
}
inline FloatLanes scaledPowWhere(MaskLanes m, FloatLanes s, FloatLanes v, FloatLanes e) {
    FloatLanes r{};
    for (int k = 0; k < kLaneWidth; ++k)
        if (m[k]) r[k] = scaledPowWhere(true, s[k], v[k], e[k]);
    return r;
}

/// sin and cos of a in [-pi/4, pi/4] (one, or each lane): Cephes' sinf and cosf polynomials
/// for that range (no range reduction), within 2 ulp of the library functions there. One
/// template body, lane-wise arithmetic only, so lane k has the bits of the scalar call.
template <class F>
inline void sinCosQuarter(F a, F& s, F& c) {
    const F z = a * a;
    s = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * a + a;
    c = (((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
         0.5f * z) +
        1.0f;
}

}  // namespace rs
