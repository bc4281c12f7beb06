// Compiles one lane loop source twice, so that one source gives both machine codes: into
// namespace avx2 (anonymous inside) under `#pragma GCC target("avx2")` with RS_LANES_AVX2
// defined, where core/avx2_dispatch.h defines RS_AVX2_DISPATCH, and into namespace baseline
// without. Not a header: a .cpp file includes core/avx2_dispatch.h with its other includes,
// defines RS_LANE_SOURCE as the quoted path of its lane source, then includes this file inside
// its own namespace; avx2Available() picks the instance to call.
//
// The lane source may touch raw data and its own inline functions only: a template of another
// header instantiated inside the AVX2 region would be compiled for AVX2 and could be linked
// into code that runs on any processor.
#if !defined(RS_LANE_SOURCE)
#error "define RS_LANE_SOURCE (the lane source's quoted path) before including lane_instances.inl"
#endif

#if defined(RS_AVX2_DISPATCH)
namespace avx2 {
namespace {
#pragma GCC push_options
#pragma GCC target("avx2")
#define RS_LANES_AVX2 1
#include RS_LANE_SOURCE
#undef RS_LANES_AVX2
#pragma GCC pop_options
}  // namespace
}  // namespace avx2
#endif

namespace baseline {
namespace {
#include RS_LANE_SOURCE
}  // namespace
}  // namespace baseline

#undef RS_LANE_SOURCE
