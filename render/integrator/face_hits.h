// Where the hits of a level lie and which way they face: the shading points of a batch of
// closest hits (the trace kernel's first step of shading a level).
#pragma once

#include <cstddef>
#include <cstdint>

#include "integrator/light_sampling.h"

namespace rs {

/// For rays [0, n) of a level (origins o, directions d) and their hits: each hit's point
/// p = o + t d, its normal turned toward the ray and the direction -d to the viewer into `sp`,
/// four rays at a time with the bits of the one-ray computation; inside[i] = 1 where the
/// normal had to be turned (the ray is inside: thesis Algorithm 6).
void faceHits(const float* ox, const float* oy, const float* oz, const float* dx, const float* dy,
              const float* dz, const HitBatch& hits, std::size_t n, ShadingPoints& sp,
              uint8_t* inside);

}  // namespace rs
