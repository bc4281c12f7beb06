// The shadow rays of centre-sampled lights (a point light, or any light when sphere lights
// are not sampled), four shading points at a time, and their answers back to the points.
#pragma once

#include <cstddef>
#include <cstdint>

#include "integrator/light_sampling.h"

namespace rs {

/// Where shadow rays are written: one array per field, indexed by ray.
struct ShadowRayArrays {
    float *ox, *oy, *oz, *dx, *dy, *dz, *tmax;
    uint32_t* light;
};

/// The shadow rays of light `light`'s centre samples `centres` from points [first, end) of
/// `pts` (first a multiple of kLaneWidth): one per listed sample, in point order, written at
/// out[r], out[r + 1], ...; returns the index past the last one. Each ray has the bits of
/// shadowOrigin and shadowLength for its point alone.
std::size_t writeCentreShadows(const ShadingPoints& pts, const CentreSamples& centres,
                               std::size_t first, std::size_t end, float eps, uint32_t light,
                               const ShadowRayArrays& out, std::size_t r);

/// The answers to those rays back to their points: blocked[j] = listed[j] & occluded[r'],
/// r' counting the listed samples on from r, for j in [first, end); returns the index past
/// the last answer read.
std::size_t readCentreAnswers(const CentreSamples& centres, std::size_t first, std::size_t end,
                              const uint8_t* occluded, uint8_t* blocked, std::size_t r);

}  // namespace rs
