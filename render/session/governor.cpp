// Governor ladder, prediction and feedback.
#include "session/governor.h"

#include <algorithm>

namespace rs {

InteractionPolicy Governor::policyForLevel(const InteractionPolicy& base, int level) {
    InteractionPolicy p = base;
    // Deferred shadows are completed after release; half resolution keeps every material.
    if (level >= 1 && p.shadows == MovingShadows::Full) p.shadows = MovingShadows::Deferred;
    if (level >= 2 && p.resolution == MovingResolution::Full) p.resolution = MovingResolution::Half;
    // From here on the picture shows something else: white glass, blocks, a box.
    if (level >= 3) {
        p.refraction = RefractionMode::Diffuse;
        p.reflection = ReflectionMode::Diffuse;
        p.maxDepthWhileMoving = p.maxDepthWhileMoving < 0 ? 1 : std::min(p.maxDepthWhileMoving, 1);
    }
    if (level >= 4) p.resolution = MovingResolution::Quarter;
    if (level >= 5) p.boxProxy = true;
    return p;
}

const char* Governor::levelName(int level) {
    static const char* const kNames[kLevels] = {"as set",           "deferred shadows",
                                                "half resolution",  "diffuse mirrors and glass",
                                                "quarter resolution", "box proxy"};
    return level >= 0 && level < kLevels ? kNames[level] : "off";
}

double Governor::tracedPixels(const InteractionPolicy& p, std::size_t stalePixels) {
    const double step = p.pixelStep();
    return double(stalePixels) / (step * step) / (p.interleaved ? 2.0 : 1.0);
}

double Governor::relativePixelCost(const InteractionPolicy& p) {
    // Thesis 4.2 (1280x720, depth 3): no shadows 90 ms vs 1 shadow ray 234 ms; depth 0-1
    // 72-81 ms vs 91 ms at depth 3 and more; a box instead of the moving object saves a
    // little more.
    double cost = 1.0;
    if (p.shadows == MovingShadows::Off || p.shadows == MovingShadows::Deferred) cost *= 0.45;
    if (p.reflection == ReflectionMode::Diffuse || p.refraction != RefractionMode::Full ||
        (p.maxDepthWhileMoving >= 0 && p.maxDepthWhileMoving <= 1))
        cost *= 0.78;
    if (p.boxProxy) cost *= 0.86;
    return cost;
}

double Governor::predictedMsPerPixel(const InteractionPolicy& base, int level) const {
    if (measured_[std::size_t(level)]) return msPerPixel_[std::size_t(level)];
    return msPerFullPixel_ * relativePixelCost(policyForLevel(base, level));
}

int Governor::choose(const InteractionPolicy& base, std::size_t stalePixels,
                     double targetMs) const {
    int cheapest = 0;
    InteractionPolicy previous;
    for (int level = 0; level < kLevels; ++level) {
        const InteractionPolicy p = policyForLevel(base, level);
        if (level > 0 && p == previous) continue;  // Nothing more turned down.
        previous = p;
        cheapest = level;
        if (tracedPixels(p, stalePixels) * predictedMsPerPixel(base, level) <= targetMs)
            return level;
    }
    return cheapest;
}

void Governor::record(int level, double ms, std::size_t tracedPixels) {
    if (level < 0 || level >= kLevels || tracedPixels < 64) return;
    const double sample = ms / double(tracedPixels);
    double& v = msPerPixel_[std::size_t(level)];
    v = measured_[std::size_t(level)] ? 0.7 * v + 0.3 * sample : sample;
    measured_[std::size_t(level)] = true;
}

double Governor::budgetMs(double targetMs, double updateMs, double planMs, double editIntervalMs,
                          double sinceEditMs) {
    (void)editIntervalMs, (void)sinceEditMs;
    return std::max(0.0, 0.9 * targetMs - updateMs - planMs);
}

void Governor::calibrate(double msPerFullQualityPixel) {
    msPerFullPixel_ = msPerFullQualityPixel;
}

}  // namespace rs
