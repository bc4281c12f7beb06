// The interaction policy's file form and the governor's choice of levels.
#include "session_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace rs {
namespace {

TEST(InteractionPolicy, JsonRoundTripAndErrorsNameTheKey) {
    InteractionPolicy p;
    p.resolution = MovingResolution::Quarter;
    p.refraction = RefractionMode::DiffuseExceptSelected;
    p.shadows = MovingShadows::HardOnly;
    p.maxDepthWhileMoving = 2;
    p.governorTargetMs = 12.5;
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

/// Edits the document from inside a pass, as mouse events arriving mid-pass do: on a tile
/// of each of `rounds` passes it posts `perRound` camera nudges (they coalesce), and tiles of
/// the generations before the last one posted cost `tileCost` more (as on a loaded machine).
class EditingObserver : public SessionObserver {
public:
    EditingObserver(SceneDocument doc, int rounds, int perRound, std::chrono::milliseconds tileCost)
        : rounds_(rounds), perRound_(perRound), tileCost_(tileCost), doc_(std::move(doc)) {}
    RenderSession* session = nullptr;
    std::atomic<bool> armed{false};

    void tileDone(int, int, int, int, uint64_t generation) override {
        if (!armed.load()) return;
        {
            std::lock_guard lock(mutex_);
            if (generation == postedFrom_) ++tilesAfterPost_;
            if (rounds_ > 0 && generation != postedFrom_) {
                for (int k = 0; k < perRound_; ++k) {
                    doc_.camera.target.x += 0.01f;  // An orbit step: every pixel goes stale.
                    last_ = session->update(doc_);
                    posted_.push_back(last_);
                }
                postedFrom_ = generation;
                --rounds_;
            }
        }
        if (generation < lastPosted()) std::this_thread::sleep_for(tileCost_);
    }
    void passDone(const PassInfo& info) override {
        {
            std::lock_guard lock(mutex_);
            if (info.kind == PassKind::Interactive) interactive_.push_back(info);
        }
        seen_.notify_all();
    }
    /// Waits until passDone has reported an uncut interactive pass of `generation`.
    bool waitForPassReported(uint64_t generation) {
        std::unique_lock lock(mutex_);
        return seen_.wait_for(lock, std::chrono::seconds(60), [&] {
            return std::any_of(interactive_.begin(), interactive_.end(), [&](const PassInfo& p) {
                return p.generation == generation && !p.cancelled;
            });
        });
    }
    bool done() {
        std::lock_guard lock(mutex_);
        return rounds_ == 0;
    }
    uint64_t lastPosted() {
        std::lock_guard lock(mutex_);
        return last_;
    }
    SceneDocument document() {
        std::lock_guard lock(mutex_);
        return doc_;
    }
    std::vector<uint64_t> posted() {
        std::lock_guard lock(mutex_);
        return posted_;
    }
    std::vector<PassInfo> interactivePasses() {
        std::lock_guard lock(mutex_);
        return interactive_;
    }
    /// Tiles the last pass an edit was posted from committed after that.
    int tilesAfterPost() {
        std::lock_guard lock(mutex_);
        return tilesAfterPost_;
    }

private:
    std::mutex mutex_;
    std::condition_variable seen_;
    int rounds_, perRound_;
    std::chrono::milliseconds tileCost_;
    SceneDocument doc_;
    uint64_t last_ = 0, postedFrom_ = 0;
    int tilesAfterPost_ = 0;
    std::vector<uint64_t> posted_;
    std::vector<PassInfo> interactive_;
};

/// testRoom at 128x96 (12 tiles) under InteractionPolicy::none() and a governor aiming at
/// `targetMs`, rendered complete; then an orbit begins and `observer` edits from inside the
/// passes that follow the first camera move. Returns that move's generation.
uint64_t orbitWhileObserved(RenderSession& session, EditingObserver& observer, double targetMs) {
    using namespace std::chrono_literals;
    InteractionPolicy policy = InteractionPolicy::none();
    policy.governorTargetMs = targetMs;
    session.setPolicy(policy);
    observer.session = &session;
    session.setObserver(&observer);
    SceneDocument doc = observer.document();
    session.update(doc);
    EXPECT_TRUE(session.waitUntilComplete(60s));  // Its base pass calibrates the governor.
    session.beginInteraction(kNoObject);
    doc.camera.target.x -= 0.01f;
    observer.armed = true;
    const uint64_t first = session.update(doc);
    for (int i = 0; i < 60000 && !observer.done(); ++i) std::this_thread::sleep_for(1ms);
    EXPECT_TRUE(observer.done());
    EXPECT_TRUE(session.waitForPass(observer.lastPosted(), 60s));
    EXPECT_TRUE(observer.waitForPassReported(observer.lastPosted()));
    return first;
}

/// Ends the orbit; the frame must equal a full render of the last document posted.
void endOrbitExact(RenderSession& session, EditingObserver& observer) {
    using namespace std::chrono_literals;
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
    session.setObserver(nullptr);
    EXPECT_LE(test::maxDiffToFullRender(session, observer.document()), 1e-5f);
}

SceneDocument orbitRoom() {
    SceneDocument doc = test::testRoom();
    doc.render.width = 128;
    doc.render.height = 96;
    return doc;
}

TEST(Governor, StepsDownAfterCutPassesThatWereTooSlow_AndTheFrameEndsExact) {
    // Every pass gets the next move at its first tile and then costs 100 ms a tile: past its
    // 45 ms budget, at whose end the move cuts it. The governor must learn from passes that
    // never finish.
    constexpr int kCuts = 8;
    EditingObserver observer(orbitRoom(), kCuts, 1, std::chrono::milliseconds(100));
    RenderSession session(2);
    orbitWhileObserved(session, observer, 50.0);
    const std::vector<PassInfo> passes = observer.interactivePasses();
    ASSERT_GE(passes.size(), 4u);
    int highest = 0;
    for (const PassInfo& p : passes) {
        // The levels predicted from the quick base pass are tried, cut and dropped one after
        // the other (once every level is measured too slow, the cheapest may finish).
        if (highest < 3) {
            EXPECT_TRUE(p.cancelled) << "level " << p.governorLevel;
        }
        highest = std::max(highest, p.governorLevel);
    }
    EXPECT_GT(highest, passes.front().governorLevel);
    EXPECT_GE(highest, 3);
    // The uncut pass after the last move is the one that shows; it is governed as well.
    EXPECT_FALSE(passes.back().cancelled);
    EXPECT_GE(passes.back().governorLevel, 3);
    endOrbitExact(session, observer);
}

TEST(RenderSession, EditsDuringAGovernedPassWithinItsBudget_LetItFinish_TheLatestWins_EndExact) {
    // A budget of a minute: the pass the first move started finishes although two more moves
    // arrive at its first tile; they coalesce into one pass after it.
    EditingObserver observer(orbitRoom(), 1, 2, std::chrono::milliseconds(0));
    RenderSession session(2);
    const uint64_t appliedBefore = session.stats().appliedUpdates;
    const uint64_t first = orbitWhileObserved(session, observer, 60000.0);
    const std::vector<uint64_t> posted = observer.posted();
    ASSERT_EQ(posted.size(), 2u);
    const std::vector<PassInfo> passes = observer.interactivePasses();
    ASSERT_GE(passes.size(), 2u);
    EXPECT_EQ(passes.front().generation, first);
    EXPECT_FALSE(passes.front().cancelled);
    EXPECT_EQ(passes.front().tracedPixels, passes.front().totalPixels);  // The whole view.
    for (const PassInfo& p : passes) EXPECT_NE(p.generation, posted[0]);  // Coalesced away.
    EXPECT_EQ(passes.back().generation, posted[1]);
    EXPECT_FALSE(passes.back().cancelled);
    // The opening document, the first move and the latest of the two: three applied.
    EXPECT_EQ(session.stats().appliedUpdates - appliedBefore, 3u);
    endOrbitExact(session, observer);
}

TEST(RenderSession, AnEditHeldBackByAGovernedPass_CutsItAtTheEndOfItsBudget_EndExact) {
    // A 900 ms budget, a move at the first tile, then 250 ms a tile: the pass keeps going
    // after the move (it is within its budget) and is cut at the budget's end, with tiles of
    // its 12 still to do.
    EditingObserver observer(orbitRoom(), 1, 1, std::chrono::milliseconds(250));
    RenderSession session(2);
    const uint64_t first = orbitWhileObserved(session, observer, 1000.0);
    const std::vector<PassInfo> passes = observer.interactivePasses();
    ASSERT_GE(passes.size(), 2u);
    EXPECT_EQ(passes.front().generation, first);
    EXPECT_TRUE(passes.front().cancelled);
    EXPECT_GE(observer.tilesAfterPost(), 1);  // Held back: the pass went on.
    EXPECT_EQ(passes.back().generation, observer.lastPosted());
    EXPECT_FALSE(passes.back().cancelled);
    endOrbitExact(session, observer);
}

}  // namespace
}  // namespace rs
