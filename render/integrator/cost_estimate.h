// Cost budget of a full render: an upper estimate of its rays and memory from the document
// alone (before anything is compiled or allocated), and the limits a render must stay under
// unless the user insists (raystudio-cli render --force, the designer's Render Image prompt).
#pragma once

#include <cstdint>
#include <string>

#include "scene/document.h"

namespace rs {

/// Default ray budget: 1e11 rays, a quarter of an hour at 100 Mrays/s (the reference room
/// renders at about 120 Mrays/s on two cores). The estimate is an upper bound, so a render
/// refused here may well finish sooner; --force renders it anyway.
inline constexpr double kDefaultRayBudget = 1e11;
/// Default memory budget for the render's frame buffers: 8 GiB.
inline constexpr uint64_t kDefaultMemoryBudget = uint64_t(8) << 30;

/// What a full render of a document is expected to cost, at most.
struct CostEstimate {
    double pixels = 0.0;
    double samplesPerPixel = 0.0;
    /// Camera rays a pixel may get beyond its samples: one when there are several (an
    /// adaptive render traces the centre first, a plain one with ids the id pass besides).
    double extraCameraRays = 0.0;
    /// Rays per camera sample: camera, reflected and refracted rays of one ray tree.
    double treeRays = 0.0;
    /// Shadow rays per shading point: one per point light, shadow_samples per sphere light.
    double shadowRaysPerHit = 0.0;
    /// pixels x (samples + extra) x tree rays x (1 + shadow rays): every ray it may trace.
    double rays = 0.0;
    /// Frame buffers of a full render (colour, ids, adaptive buffers, the written image).
    uint64_t frameBytes = 0;
};

/// The limits estimates are held to.
struct CostBudget {
    double rays = kDefaultRayBudget;
    uint64_t bytes = kDefaultMemoryBudget;
};

/// Estimates the cost of rendering `doc` at its render settings. The ray tree of a scene with
/// glass splits at every hit, so it grows like min(2^depth, depth / min_weight): a ray whose
/// weight falls below render.min_weight is not traced, and the weights of one level's rays sum
/// to at most 1, so no level holds more than 1 / min_weight of them. Mirrors alone give a chain
/// of depth + 1 rays; diffuse scenes one.
CostEstimate estimateCost(const SceneDocument& doc);

/// Empty when `estimate` is within `budget`; otherwise a message naming the estimate and the
/// budget it exceeds.
std::string budgetExceeded(const CostEstimate& estimate, const CostBudget& budget = {});

}  // namespace rs
