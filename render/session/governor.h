// Automatic interaction quality: the least-reduced policy level that meets a frame-time target.
#pragma once

#include <array>
#include <cstddef>

#include "session/interaction_policy.h"

namespace rs {

/// Chooses among a ladder of ever cheaper policies from measured costs. Level 0 is the user's
/// policy as set; each further level turns down one more thing, those that change what the
/// picture shows last: 1 defers shadows, 2 halves the resolution, 3 shows mirrors and glass
/// as diffuse with depth 1, 4 quarters the resolution, 5 draws the moving object as its box.
/// A level that changes nothing over the one before it (the user already chose that) is
/// skipped.
class Governor {
public:
    static constexpr int kLevels = 6;

    /// The policy of `level`, derived from the user's `base` policy.
    static InteractionPolicy policyForLevel(const InteractionPolicy& base, int level);
    /// What `level` turns down, for the status bar ("half resolution").
    static const char* levelName(int level);
    /// Pixels a level traces out of `stalePixels` (undersampling and interleaving divide).
    static double tracedPixels(const InteractionPolicy& p, std::size_t stalePixels);
    /// Cost of a traced pixel under `p` relative to a full-quality one, from the thesis's
    /// measurements (4.2), for levels not measured yet.
    static double relativePixelCost(const InteractionPolicy& p);

    /// Picks the least-reduced level whose predicted frame time meets `targetMs`; when none
    /// does, the level predicted fastest (a deeper level that measured no faster, because
    /// it still fills and commits every pixel, is not taken for nothing). When the level
    /// that meets the target was measured and a less-reduced one was not, but is predicted
    /// within twice the target, that one is taken instead, to be measured: quality comes
    /// back as soon as the machine allows (a level measured too slow is tried again only
    /// once forgotten, kForgetAfter passes later).
    int choose(const InteractionPolicy& base, std::size_t stalePixels, double targetMs) const;
    /// Feeds back an interactive pass at `level`: `ms` to its end, or to the edit that cut it,
    /// and the pixels it traced by then (a cut pass costs what it traced before the cut).
    void record(int level, double ms, std::size_t tracedPixels);
    /// Sets the cost of a full-quality pixel (ms), which predicts the levels not measured yet.
    void calibrate(double msPerFullQualityPixel);
    /// Predicted ms per traced pixel of `level` under `base`: measured; else scaled from the
    /// nearest measured level (the machine's load as it is now), else calibrated.
    double predictedMsPerPixel(const InteractionPolicy& base, int level) const;
    /// Milliseconds an interactive pass planned now may take: `targetMs` less the edit's own
    /// cost (diff, refit, marking) and the planning, less a tenth kept for scheduling jitter,
    /// so that frames meet the target, not just average it.
    static double budgetMs(double targetMs, double updateMs, double planMs);
    /// Passes measured at other levels after which a level's own measurement is forgotten
    /// (predicted again): a level measured while the machine was busy gets another try.
    static constexpr int kForgetAfter = 60;

private:
    double msPerFullPixel_ = 0.0;
    std::array<double, kLevels> msPerPixel_{};
    std::array<bool, kLevels> measured_{};
    std::array<int, kLevels> age_{};  ///< Passes recorded at other levels since measured.
};

}  // namespace rs
