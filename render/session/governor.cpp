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
    static const char* const kNames[kLevels] = {"as set",
                                                "deferred shadows",
                                                "half resolution",
                                                "diffuse mirrors and glass",
                                                "quarter resolution",
                                                "box proxy"};
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
    const double relative = relativePixelCost(policyForLevel(base, level));
    for (int d = 1; d < kLevels; ++d) {
        for (const int m : {level - d, level + d}) {
            if (m < 0 || m >= kLevels || !measured_[std::size_t(m)]) continue;
            return msPerPixel_[std::size_t(m)] * relative /
                   relativePixelCost(policyForLevel(base, m));
        }
    }
    return msPerFullPixel_ * relative;
}

namespace {
/// When no level meets the target, a deeper measured one is taken over the fastest so far
/// only if it is this much faster (not the blocks or the box for a few percent).
constexpr double kClearlyFaster = 0.8;
/// A less-reduced level not measured yet is tried when predicted within this many targets.
constexpr double kProbeReach = 2.0;
}  // namespace

int Governor::choose(const InteractionPolicy& base, std::size_t stalePixels,
                     double targetMs) const {
    int fastest = 0;
    double fastestMs = 0.0;
    InteractionPolicy previous;
    // The nearest less-reduced level not measured yet, and its prediction.
    int unmeasured = -1;
    double unmeasuredMs = 0.0;
    for (int level = 0; level < kLevels; ++level) {
        const InteractionPolicy p = policyForLevel(base, level);
        if (level > 0 && p == previous) continue;  // Nothing more turned down.
        previous = p;
        const double ms = tracedPixels(p, stalePixels) * predictedMsPerPixel(base, level);
        if (ms <= targetMs) {
            // Predictions of a level from another's measurement scale by pixel counts and
            // the thesis's ratios, which overstate what a finer level costs (every pass
            // also fills and commits its pixels): a less-reduced level predicted within
            // reach is tried, and its own measurement decides from then on.
            if (unmeasured >= 0 && measured_[std::size_t(level)] &&
                unmeasuredMs <= kProbeReach * targetMs)
                return unmeasured;
            return level;
        }
        if (!measured_[std::size_t(level)]) unmeasured = level, unmeasuredMs = ms;
        // A level measured to change the picture more must be clearly faster to be worth it
        // (one only predicted is tried when faster at all: then it is measured).
        const double margin = measured_[std::size_t(level)] ? kClearlyFaster : 1.0;
        if (level == 0 || ms < margin * fastestMs) fastest = level, fastestMs = ms;
    }
    return fastest;
}

void Governor::record(int level, double ms, std::size_t tracedPixels) {
    if (level < 0 || level >= kLevels || tracedPixels < 64) return;
    const double sample = ms / double(tracedPixels);
    double& v = msPerPixel_[std::size_t(level)];
    v = measured_[std::size_t(level)] ? 0.7 * v + 0.3 * sample : sample;
    measured_[std::size_t(level)] = true;
    age_[std::size_t(level)] = 0;
    for (int other = 0; other < kLevels; ++other)
        if (other != level && measured_[std::size_t(other)] &&
            ++age_[std::size_t(other)] > kForgetAfter)
            measured_[std::size_t(other)] = false;
}

double Governor::budgetMs(double targetMs, double updateMs, double planMs) {
    return std::max(0.0, 0.9 * targetMs - updateMs - planMs);
}

void Governor::calibrate(double msPerFullQualityPixel) {
    msPerFullPixel_ = msPerFullQualityPixel;
}

}  // namespace rs
