// Automatic interaction quality: the least-reduced policy level that meets a frame-time target.
#pragma once

#include "session/interaction_policy.h"

#include <array>
#include <cstddef>

namespace rs {

/// Chooses among a ladder of ever cheaper policies from measured costs. Level 0 is the user's
/// policy as set; each further level turns down one more thing the thesis measured as costly:
/// 1 defers shadows, 2 shows mirrors and glass as diffuse with depth 1, 3 halves the
/// resolution, 4 quarters it and draws the moving object as its box.
class Governor {
public:
    static constexpr int kLevels = 5;

    /// The policy of `level`, derived from the user's `base` policy.
    static InteractionPolicy policyForLevel(const InteractionPolicy& base, int level);
    /// Pixels a level traces out of `stalePixels` (undersampling and interleaving divide).
    static double tracedPixels(const InteractionPolicy& p, std::size_t stalePixels);

    /// Picks the least-reduced level whose predicted frame time meets `targetMs`, or the
    /// cheapest level when none does.
    int choose(const InteractionPolicy& base, std::size_t stalePixels, double targetMs) const;
    /// Feeds back a measured interactive frame at `level`.
    void record(int level, double ms, std::size_t tracedPixels);
    /// Seeds every level from a full-quality pass (ms per pixel), scaled by the relative costs
    /// the thesis reports for the features each level removes.
    void calibrate(double msPerFullQualityPixel);
    double predictedMsPerPixel(int level) const { return msPerPixel_[std::size_t(level)]; }

private:
    std::array<double, kLevels> msPerPixel_{};
    std::array<bool, kLevels> measured_{};
};

}  // namespace rs
