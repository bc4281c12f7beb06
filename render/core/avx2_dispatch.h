// Where a lane loop is compiled twice (core/lane_instances.inl), the run-time choice between
// its AVX2 and its baseline machine code.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
/// Defined where core/lane_instances.inl compiles an AVX2 instance beside the baseline one
/// (GCC on x86-64: its `#pragma GCC target` inside one translation unit).
#define RS_AVX2_DISPATCH 1
#include <immintrin.h>
#elif defined(__SSE2__)
#include <immintrin.h>
#endif

namespace rs {

/// Whether the AVX2 instances may run: compiled (RS_AVX2_DISPATCH) and the processor has
/// AVX2. Asked once per process.
inline bool avx2Available() {
#if defined(RS_AVX2_DISPATCH)
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
#else
    return false;
#endif
}

}  // namespace rs
