// The interaction policy's file form and the governor's choice of levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "session_test_support.h"

namespace rs {
namespace {

TEST(InteractionPolicy, JsonRoundTripAndErrorsNameTheKey) {
    InteractionPolicy p;
    p.resolution = MovingResolution::Quarter;
    p.refraction = RefractionMode::DiffuseExceptSelected;
    p.shadows = MovingShadows::HardOnly;
    p.maxDepthWhileMoving = 2;
    p.governorTargetMs = 12.5;
    p.wholeFramesWhileMoving = false;
    InteractionPolicy back = InteractionPolicy::none();
    std::string error;
    ASSERT_TRUE(policyFromJson(policyToJson(p), back, error)) << error;
    EXPECT_EQ(back, p);
    EXPECT_FALSE(policyFromJson(R"({"shadow": "off"})", back, error));
    EXPECT_NE(error.find("shadow"), std::string::npos);
    EXPECT_FALSE(policyFromJson(R"({"shadows": "sometimes"})", back, error));
    EXPECT_NE(error.find("sometimes"), std::string::npos);
}

TEST(Governor, LowerTargetsPickCheaperLevels) {
    Governor g;
    g.calibrate(0.001);  // 1 microsecond per full-quality pixel.
    const InteractionPolicy base = InteractionPolicy::none();
    const int generous = g.choose(base, 100000, 1000.0);
    const int tight = g.choose(base, 100000, 10.0);
    const int impossible = g.choose(base, 100000, 0.001);
    EXPECT_EQ(generous, 0);
    EXPECT_GT(tight, generous);
    EXPECT_EQ(impossible, Governor::kLevels - 1);
    // Feedback moves predictions: a level measured slow is skipped.
    g.record(1, 1000.0, 100000);
    EXPECT_GT(g.choose(base, 100000, 60.0), 1);
}

TEST(Governor, LevelsThatChangeThePictureComeLast) {
    // The default aims at what a 30 Hz display shows.
    EXPECT_DOUBLE_EQ(InteractionPolicy{}.governorTargetMs, 1000.0 / 30.0);
    InteractionPolicy full = InteractionPolicy::none();
    full.governorTargetMs = InteractionPolicy::kDefaultGovernorTargetMs;
    auto keepsMaterials = [](const InteractionPolicy& p) {
        return p.reflection == ReflectionMode::Full && p.refraction == RefractionMode::Full &&
               p.maxDepthWhileMoving < 0 && !p.boxProxy;
    };
    // First what the picture gets back after release or shows a little softer...
    EXPECT_EQ(Governor::policyForLevel(full, 0), full);
    EXPECT_EQ(Governor::policyForLevel(full, 1).shadows, MovingShadows::Deferred);
    EXPECT_EQ(Governor::policyForLevel(full, 1).resolution, MovingResolution::Full);
    EXPECT_EQ(Governor::policyForLevel(full, 2).resolution, MovingResolution::Half);
    for (int level : {0, 1, 2}) EXPECT_TRUE(keepsMaterials(Governor::policyForLevel(full, level)));
    // ...then white glass and mirrors, blocks, a box, in that order.
    const InteractionPolicy diffuse = Governor::policyForLevel(full, 3);
    EXPECT_EQ(diffuse.refraction, RefractionMode::Diffuse);
    EXPECT_EQ(diffuse.reflection, ReflectionMode::Diffuse);
    EXPECT_EQ(diffuse.resolution, MovingResolution::Half);
    EXPECT_FALSE(diffuse.boxProxy);
    EXPECT_EQ(Governor::policyForLevel(full, 4).resolution, MovingResolution::Quarter);
    EXPECT_FALSE(Governor::policyForLevel(full, 4).boxProxy);
    EXPECT_TRUE(Governor::policyForLevel(full, 5).boxProxy);
    // Each level predicts a cheaper frame than the one before.
    Governor g;
    g.calibrate(1e-4);
    for (int level = 1; level < Governor::kLevels; ++level)
        EXPECT_LT(Governor::tracedPixels(Governor::policyForLevel(full, level), 100000) *
                      g.predictedMsPerPixel(full, level),
                  Governor::tracedPixels(Governor::policyForLevel(full, level - 1), 100000) *
                      g.predictedMsPerPixel(full, level - 1))
            << level;
    EXPECT_STREQ(Governor::levelName(2), "half resolution");
}

TEST(Governor, AtTheDefaultTarget_ADragStaysFullQuality_AWholeFrameOnlyHalvesTheResolution) {
    // A room pixel at 1e-4 ms (a 1 Mpixel full frame in 100 ms, this machine's viewport).
    Governor g;
    g.calibrate(1e-4);
    const InteractionPolicy defaults;  // Deferred shadows, 33 ms.
    // A ball's drag step re-traces about 1.5 % of the frame: nothing is turned down.
    EXPECT_EQ(g.choose(defaults, 15000, defaults.governorTargetMs), 0);
    // An orbit re-traces everything: deferred shadows alone (45 ms) miss the target, half
    // resolution meets it; mirrors and glass stay. Level 1 is the user's own setting (shadows
    // already deferred), so it is skipped.
    EXPECT_EQ(g.choose(defaults, 1000000, defaults.governorTargetMs), 2);
    // Only a measured cost that really forces it goes further.
    g.record(2, 60.0, 250000);
    EXPECT_GE(g.choose(defaults, 1000000, defaults.governorTargetMs), 3);
}

TEST(Governor, CutPassesTeachTheCostAndLevelsNotMeasuredFollowTheirLoad) {
    Governor g;
    g.calibrate(1e-4);  // An idle Base pass: 0.1 microseconds a full-quality pixel.
    const InteractionPolicy defaults;
    // An orbit step of a 1 Mpixel frame with 15 ms to the next edit: half resolution fits.
    EXPECT_EQ(g.choose(defaults, 1000000, 15.0), 2);
    // Each such pass was cut after 16 ms with 100,000 of its 250,000 pixels traced: the
    // machine is busier than the idle calibration said. Diffuse glass at half resolution,
    // predicted from that load (not from the idle calibration, 8.8 ms), misses too.
    for (int i = 0; i < 3; ++i) g.record(2, 16.0, 100000);
    EXPECT_EQ(g.choose(defaults, 1000000, 15.0), 4);
}

TEST(Governor, NoLevelMeetsTheTarget_TheFastestMeasuredIsTaken) {
    Governor g;
    g.calibrate(1e-4);
    const InteractionPolicy defaults;
    // Measured: deeper levels hardly cheaper, as they still fill and commit every pixel.
    g.record(2, 20.0, 250000);
    g.record(3, 22.0, 250000);
    g.record(4, 25.0, 62500);
    g.record(5, 30.0, 62500);
    EXPECT_EQ(g.choose(defaults, 1000000, 5.0), 2);  // No box proxy for nothing.
    g.record(4, 10.0, 62500);
    g.record(4, 10.0, 62500);
    g.record(4, 10.0, 62500);
    EXPECT_EQ(g.choose(defaults, 1000000, 5.0), 4);
}

TEST(Governor, ALevelMeasuredSlowIsTriedAgainOnceOthersHaveRunForAWhile) {
    Governor g;
    g.calibrate(1e-4);
    const InteractionPolicy defaults;
    g.record(0, 150.0, 15000);  // A drag step at full resolution, while the machine was busy.
    EXPECT_GT(g.choose(defaults, 15000, 100.0), 0);
    for (int i = 0; i < Governor::kForgetAfter; ++i) g.record(2, 0.375, 3750);
    EXPECT_GT(g.choose(defaults, 15000, 100.0), 0);
    g.record(2, 0.375, 3750);  // Level 0 forgotten: predicted from level 2's load now.
    EXPECT_EQ(g.choose(defaults, 15000, 100.0), 0);
}

/// Passes of a machine where a pass costs `fixedMs` plus `msPerPixel` a traced pixel at
/// every level, `passes` times over a frame of `pixels`; returns the level of each pass.
std::vector<int> drive(Governor& g, double fixedMs, double msPerPixel, std::size_t pixels,
                       double targetMs, int passes) {
    const InteractionPolicy defaults;
    std::vector<int> levels;
    for (int i = 0; i < passes; ++i) {
        const int level = g.choose(defaults, pixels, targetMs);
        const double traced =
            Governor::tracedPixels(Governor::policyForLevel(defaults, level), pixels);
        g.record(level, fixedMs + msPerPixel * traced, std::size_t(traced));
        levels.push_back(level);
    }
    return levels;
}

TEST(Governor, ADragThatFitsTheBudgetAtFullQualityGetsFullQualityBack) {
    // A 1 Mpixel step costs 4 ms plus 16 ms of pixels at full quality: well within 30 ms.
    // The calibration (a still pass with its supersamples) predicts 45 ms, so the first
    // pass is turned down; measuring the finer level then brings it back for good.
    Governor g;
    g.calibrate(1e-4);
    const std::vector<int> levels = drive(g, 4.0, 1.6e-5, 1000000, 30.0, 40);
    EXPECT_GT(levels.front(), 0);
    const auto firstFull = std::find(levels.begin(), levels.end(), 0);
    ASSERT_NE(firstFull, levels.end());
    EXPECT_LE(firstFull - levels.begin(), 3);
    EXPECT_TRUE(std::all_of(firstFull, levels.end(), [](int l) { return l == 0; }));
}

TEST(Governor, ALevelTooSlowIsProbedOnlyOnceItIsForgotten) {
    // Full quality really costs 56 ms: half resolution measures 14 ms, which predicts 56
    // within reach, so full quality is tried; after that probe half resolution stays, and
    // full quality is tried again only every kForgetAfter passes.
    Governor g;
    g.calibrate(1e-4);
    const std::vector<int> levels = drive(g, 0.0, 5.6e-5, 1000000, 30.0, 200);
    const long full = std::count(levels.begin(), levels.end(), 0);
    EXPECT_GE(full, 1);
    EXPECT_LE(full, 200 / Governor::kForgetAfter + 1);
    EXPECT_EQ(levels.back() == 0 ? levels[levels.size() - 2] : levels.back(), 2);
}

}  // namespace
}  // namespace rs
