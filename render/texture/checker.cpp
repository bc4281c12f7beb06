// The solid checker's box filter: per-axis averages of a square wave, multiplied, for four
// points at a time (texture/checker_lanes.inl), AVX2 where the processor has it.
#include "texture/checker.h"

#include <cstddef>

#include "core/avx2_dispatch.h"
#include "core/floor_lanes.h"
#include "core/lanes.h"

namespace rs {

namespace {

/// Half-widths below this (in cells) take the point value: the difference of the triangle
/// wave at the ends would lose its digits to cancellation long before the answer changed.
constexpr double kPointHalfWidth = 1e-6;
/// Beyond this half-width (in cells) the average is below 1e-6 in magnitude: 0.
constexpr double kFlatHalfWidth = 1e6;

}  // namespace

#define RS_LANE_SOURCE "texture/checker_lanes.inl"
#include "core/lane_instances.inl"

void checkerOddFractions(std::size_t count, const CheckerPoints& in, float* odd) {
#if defined(RS_AVX2_DISPATCH)
    if (avx2Available()) return avx2::oddFractionsOf(count, in, odd);
#endif
    baseline::oddFractionsOf(count, in, odd);
}

float checkerOddFraction(const Vec3& p, const Vec3& halfWidth, float scale) {
    const CheckerPoints in{&p.x, &p.y, &p.z, &halfWidth.x, &halfWidth.y, &halfWidth.z, &scale};
    float odd = 0.0f;
    baseline::oddFractionsOf(1, in, &odd);
    return odd;
}

}  // namespace rs
