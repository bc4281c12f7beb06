// The rules of the illumination equation (scenes/FORMAT.md) that more than one part of the
// engine must follow: the trace kernel applies them, and what predicts or bounds its work (the
// snapshot's highlight cut-off, the render cost estimate) derives from them here instead of
// restating them. A test of each pair (tests/unit/shading_rules_test.cpp, cost_bound_test.cpp)
// fails when the two disagree.
#pragma once

#include <algorithm>
#include <cmath>

namespace rs {

/// A highlight term specular * (R.V)^shininess below this is left out: far below a float
/// colour's resolution (and the 8-bit display's 1/255), so no image changes by it.
inline constexpr float kNegligibleHighlight = 1e-7f;

/// The R.V below which the highlight of a material with `specular` and `shininess` is under
/// kNegligibleHighlight, capped at 1 (0 when it has no highlight). The kernel skips the
/// costly pow below it (light_sampling.cpp, addSampleTerm), the same on every render path.
inline float highlightCutoff(float specular, float shininess) {
    if (!(specular > 0.0f && shininess > 0.0f)) return 0.0f;
    return std::min(1.0f, std::pow(kNegligibleHighlight / specular, 1.0f / shininess));
}

/// A ray tree's recursion: the camera ray is depth 0, and a hit at a depth below max_depth
/// spawns at most a reflection and a refraction ray.
inline constexpr int kMostChildrenPerHit = 2;
inline constexpr bool spawnsChildren(int depth, int maxDepth) {
    return depth < maxDepth;
}
/// The depths a tree's rays can have, by spawnsChildren: 0 to max_depth.
inline constexpr int treeLevels(int maxDepth) {
    return maxDepth + 1;
}
/// A child whose accumulated weight falls below min_weight is not traced (so the weights of
/// one depth's rays, which sum to at most 1, allow at most 1 / min_weight of them).
inline constexpr bool weightTraced(float weight, float minWeight) {
    return weight >= minWeight;
}

/// Shadow rays a shading point sends toward one light: none without shadow samples, else
/// `shadowSamples` over a sphere light's disk, or one toward a light sampled at its centre.
inline constexpr int shadowRaysTowardLight(bool overDisk, int shadowSamples) {
    return shadowSamples <= 0 ? 0 : overDisk ? shadowSamples : 1;
}

}  // namespace rs
