// Upper estimates of a render's rays and frame memory, and the check against the budget.
#include "integrator/cost_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene/shading_rules.h"

namespace rs {

namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string gib(uint64_t bytes) {
    return format("%.1f GiB", double(bytes) / double(1u << 30));
}

/// Rays of one camera sample's tree, from the kinds of surface it can meet.
double treeRays(const SceneDocument& doc) {
    bool mirror = false, glass = false;
    for (const Object& o : doc.objects) {
        if (!o.visible) continue;
        const Material* m = doc.findMaterial(o.material);
        if (!m) continue;  // The built-in grey diffuse.
        mirror = mirror || m->reflectivity > 0.0f;
        glass = glass || m->transparency > 0.0f;
    }
    // The kernel's recursion (scene/shading_rules.h): levels 0 to max_depth, each hit's
    // children at most kMostChildrenPerHit, none below min_weight.
    const double levels = treeLevels(doc.render.maxDepth);
    if (glass) {
        // Nodes of a full tree of that many levels, capped by the min_weight bound: the camera
        // ray, then at most 1 / min_weight rays on each level below it.
        constexpr double c = kMostChildrenPerHit;
        const double full = (std::pow(c, levels) - 1.0) / (c - 1.0);  // Finite to kMaxDepthLimit.
        const float w = doc.render.minWeight;
        return w > 0.0f ? std::min(full, 1.0 + (levels - 1.0) / double(w)) : full;
    }
    // A mirror reflects once per hit (glass's Fresnel split is what makes trees).
    return mirror ? levels : 1.0;
}

}  // namespace

CostEstimate estimateCost(const SceneDocument& doc) {
    const RenderSettings& s = doc.render;
    CostEstimate e;
    e.pixels = double(s.width) * double(s.height);
    e.samplesPerPixel = double(std::max(1, s.supersampling));
    e.extraCameraRays = s.supersampling > 1 ? 1.0 : 0.0;
    e.treeRays = treeRays(doc);
    for (const Light& l : doc.lights)
        e.shadowRaysPerHit += shadowRaysTowardLight(l.type != LightType::Point, s.shadowSamples);
    e.rays = e.pixels * (e.samplesPerPixel + e.extraCameraRays) * e.treeRays *
             (1.0 + e.shadowRaysPerHit);
    const uint64_t pixels = uint64_t(s.width) * uint64_t(s.height);
    // Linear colour and ids, normals for adaptive supersampling, and the converted image
    // (up to float RGB for EXR and HDR) while it is written.
    const uint64_t perPixel = 12 + 4 + (s.adaptiveSupersampling ? 12 : 0) + 12;
    e.frameBytes = pixels * perPixel;
    return e;
}

std::string budgetExceeded(const CostEstimate& e, const CostBudget& budget) {
    std::string text;
    if (!(e.rays <= budget.rays))
        text = "the render is estimated at " + format("%.3g", e.rays) +
               " rays, over the ray budget of " + format("%.3g", budget.rays) + " rays (" +
               format("%.0f", e.pixels) + " pixels x (" + format("%.0f", e.samplesPerPixel) +
               " samples" + (e.extraCameraRays > 0.0 ? " + 1" : "") + ") x " +
               format("%.4g", e.treeRays) + " rays per ray tree x (1 + " +
               format("%.0f", e.shadowRaysPerHit) + " shadow rays))";
    if (e.frameBytes > budget.bytes) {
        if (!text.empty()) text += "; ";
        text += "its frame buffers are estimated at " + gib(e.frameBytes) +
                ", over the memory budget of " + gib(budget.bytes);
    }
    return text;
}

}  // namespace rs
