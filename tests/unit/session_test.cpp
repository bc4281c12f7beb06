// The interactive session's invariant: after any edits and refinement, frame == full render.
#include <gtest/gtest.h>

#include <random>

#include "session_test_support.h"

namespace rs {
namespace {

using namespace std::chrono_literals;
using test::firstDragStep;
using test::maxDiffToFullRender;
using test::mixedRoom;
using test::testRoom;

Object* randomObject(SceneDocument& doc, std::mt19937& rng) {
    std::vector<Object*> bounded;
    for (Object& o : doc.objects.editable())
        if (!std::holds_alternative<PlaneGeometry>(o.geometry)) bounded.push_back(&o);
    return bounded.empty() ? nullptr : bounded[rng() % bounded.size()];
}

/// One random edit of the kinds the designer makes.
void randomEdit(SceneDocument& doc, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    switch (rng() % 10) {
        case 0:
        case 1:
        case 2:  // Move (the common case: refit + dirty regions).
            if (Object* o = randomObject(doc, rng))
                o->transform.translate += Vec3(0.4f * u(rng), 0.3f * u(rng), 0.4f * u(rng));
            break;
        case 3:  // Rotate or scale (uniformly or not): frames change, spheres may leave world
                 // space.
            if (Object* o = randomObject(doc, rng)) {
                if (rng() % 2)
                    o->transform.rotate += Vec3(20.0f * u(rng), 30.0f * u(rng), 0.0f);
                else
                    o->transform.scale *= rng() % 2 ? Vec3(1.0f + 0.2f * u(rng))
                                                    : Vec3(1.0f, 1.0f + 0.3f * u(rng), 1.0f);
            }
            break;
        case 4:  // Material edit.
            doc.materials[rng() % doc.materials.size()].color =
                Color(0.5f + 0.4f * u(rng), 0.5f, 0.6f);
            break;
        case 5:  // Object switches material (diffuse <-> mirror <-> glass).
            if (Object* o = randomObject(doc, rng))
                o->material = doc.materials[rng() % doc.materials.size()].name;
            break;
        case 6:  // Light edits: move, brightness, add, remove.
            switch (rng() % 4) {
                case 0:
                    doc.lights[rng() % doc.lights.size()].position +=
                        Vec3(0.3f * u(rng), 0.0f, 0.3f * u(rng));
                    break;
                case 1:
                    doc.lights[rng() % doc.lights.size()].intensity *=
                        1.0f + 0.5f * u(rng) * u(rng);
                    break;
                case 2:
                    test::addPointLight(doc, "fill " + std::to_string(doc.nextId),
                                        Vec3(2.0f * u(rng), 1.0f + u(rng), -3.0f + u(rng)), 0.3f);
                    break;
                default:
                    if (doc.lights.size() > 1)
                        doc.lights.erase(doc.lights.begin() + long(rng() % doc.lights.size()));
                    break;
            }
            break;
        case 7:  // Add or remove an object.
            if (rng() % 2 && doc.objects.size() > 3) {
                doc.objects.erase(doc.objects.begin() + long(2 + rng() % (doc.objects.size() - 2)));
            } else {
                test::addSphere(doc, "added " + std::to_string(doc.nextId),
                                Vec3(u(rng), -1.5f, -4.5f + u(rng)), 0.3f,
                                doc.materials[rng() % doc.materials.size()].name);
            }
            break;
        case 8:  // Visibility toggle.
            if (Object* o = randomObject(doc, rng)) o->visible = !o->visible;
            break;
        default:  // Camera nudge (re-renders everything).
            doc.camera.target.x += 0.05f * u(rng);
            break;
    }
}

void runRandomEdits(const InteractionPolicy& policy, uint32_t seed, bool adaptive,
                    SceneDocument doc = testRoom(), EngineKind engine = EngineKind::Embree) {
    doc.render.supersampling = 4;
    doc.render.adaptiveSupersampling = adaptive;
    RenderSession session(2);
    session.setPolicy(policy);
    session.setEngine(engine);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    ASSERT_LE(maxDiffToFullRender(session, doc), 1e-5f);
    std::mt19937 rng(seed);
    for (int round = 0; round < 6; ++round) {
        const bool drag = rng() % 2;
        if (drag) session.beginInteraction(doc.objects[2].id);
        const int edits = 1 + int(rng() % 5);
        for (int e = 0; e < edits; ++e) {
            randomEdit(doc, rng);
            const uint64_t gen = session.update(doc);
            // Sometimes let a frame finish, sometimes pile edits on a running pass.
            if (rng() % 2) session.waitForPass(gen, 30s);
        }
        if (drag) session.endInteraction();
        ASSERT_TRUE(session.waitUntilComplete(60s));
        EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f)
            << "seed " << seed << " round " << round;
    }
}

TEST(RenderSession, FirstUpdate_RefinesToExactlyTheFullRender) {
    SceneDocument doc = testRoom();
    doc.render.supersampling = 4;
    doc.render.adaptiveSupersampling = true;
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

TEST(RenderSession, RandomEdits_DefaultPolicy_FrameEqualsFullRender) {
    for (uint32_t seed : {1u, 2u, 3u, 8u, 9u, 10u}) runRandomEdits(InteractionPolicy{}, seed, true);
}

TEST(RenderSession, RandomEdits_DeferredShadowsWithoutGovernor_FrameEqualsFullRender) {
    InteractionPolicy p;
    p.governorTargetMs = 0.0;
    for (uint32_t seed : {11u, 12u}) runRandomEdits(p, seed, true);
}

TEST(RenderSession, RandomEdits_EveryShortcutOn_FrameEqualsFullRender) {
    InteractionPolicy p;
    p.governorTargetMs = 0.0;
    p.resolution = MovingResolution::Half;
    p.interleaved = true;
    p.boxProxy = true;
    p.refraction = RefractionMode::DiffuseExceptSelected;
    p.reflection = ReflectionMode::Diffuse;
    p.maxDepthWhileMoving = 1;
    p.shadows = MovingShadows::Off;
    for (uint32_t seed : {4u, 5u}) runRandomEdits(p, seed, false);
}

TEST(RenderSession, RandomEdits_HardShadowsAndGovernor_FrameEqualsFullRender) {
    InteractionPolicy p;
    p.shadows = MovingShadows::HardOnly;
    p.governorTargetMs = 0.5;
    runRandomEdits(p, 6u, true);
}

TEST(RenderSession, RandomEdits_BoxesRectanglesMeshes_FrameEqualsFullRender) {
    // Rotated boxes and meshes are traced in their own frame and refit as instances.
    for (uint32_t seed : {21u, 22u})
        runRandomEdits(InteractionPolicy{}, seed, true, mixedRoom(false));
    InteractionPolicy shortcuts;
    shortcuts.governorTargetMs = 0.0;
    shortcuts.boxProxy = true;
    shortcuts.resolution = MovingResolution::Half;
    runRandomEdits(shortcuts, 23u, false, mixedRoom(false));
}

/// mixedRoom with a sampled sphere light: every shape kind, frames, instances, soft shadows.
SceneDocument everyKindRoom() {
    SceneDocument doc = mixedRoom(false);
    Light area;
    area.name = "area";
    area.type = LightType::Sphere;
    area.position = Vec3(1.5f, 2.0f, -3.5f);
    area.radius = 0.3f;
    area.intensity = 0.6f;
    doc.addLight(area);
    test::addSphere(doc, "scaled", Vec3(1.2f, -1.6f, -4.0f), 0.3f, "glass");
    doc.objects.back().transform.scale = Vec3(1.0f, 1.6f, 1.0f);
    return doc;
}

TEST(RenderSession, RandomEdits_EachEngine_EveryShapeKindAndSphereLight_FrameEqualsFullRender) {
    for (EngineKind engine : {EngineKind::Embree, EngineKind::Builtin}) {
        SCOPED_TRACE(engineName(engine));
        runRandomEdits(InteractionPolicy{}, 41u, true, everyKindRoom(), engine);
        InteractionPolicy shortcuts;
        shortcuts.governorTargetMs = 0.0;
        shortcuts.boxProxy = true;
        shortcuts.refraction = RefractionMode::Diffuse;
        runRandomEdits(shortcuts, 42u, false, everyKindRoom(), engine);
    }
}

TEST(RenderSession, SwitchingEngines_RebuildsAndEndsExact) {
    SceneDocument doc = everyKindRoom();
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    session.setEngine(EngineKind::Builtin);
    doc.objects[2].transform.translate.x += 0.1f;
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_EQ(session.snapshot()->engineKind(), EngineKind::Builtin);
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

TEST(RenderSession, RandomEdits_OrthographicCamera_FrameEqualsFullRender) {
    runRandomEdits(InteractionPolicy{}, 31u, true, mixedRoom(true));
}

TEST(RenderSession, RandomEdits_NoPolicy_FrameEqualsFullRender) {
    runRandomEdits(InteractionPolicy::none(), 7u, true);
}

TEST(RenderSession, MovingADiffuseBall_RefitsAndTracesOnlyItsRegion) {
    SceneDocument doc = testRoom();
    doc.render.width = 128;
    doc.render.height = 96;
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    Object* ball = doc.findObject(doc.objects[2].id);  // The diffuse ball.
    ASSERT_EQ(ball->name, "diffuse ball");
    ball->transform.translate.x += 0.2f;
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
    const SessionStats stats = session.stats();
    EXPECT_TRUE(stats.lastEditRefitted);
    EXPECT_GT(stats.lastDirtyPixels, 0u);
    EXPECT_LT(stats.lastDirtyPixels, std::size_t(128 * 96) / 2);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

TEST(RenderSession, QuarterResolution_EachTracedRayFillsItsBlock) {
    // An undersampled pass commits one entry per 4x4 block; every pixel of the block must get
    // the block's sample, and refinement must still end at the full render.
    SceneDocument doc = testRoom();
    doc.render.width = 70;  // not a multiple of 4 or of the tile size: partial blocks
    doc.render.height = 45;
    RenderSession session(2);
    InteractionPolicy p;
    p.resolution = MovingResolution::Quarter;
    PassInfo info;
    ASSERT_TRUE(firstDragStep(session, doc, p, info));
    std::size_t interactive = 0, differing = 0;
    session.withFrame([&](const DeepFrame& f, const auto&) {
        for (int y = 0; y < f.height(); ++y) {
            for (int x = 0; x < f.width(); ++x) {
                const std::size_t i = f.index(x, y);
                // The block's sample sits at its top-left pixel; blocks never cross tiles.
                const std::size_t corner = f.index(x / 4 * 4, y / 4 * 4);
                if (f.state()[i] != kInteractive) continue;
                ++interactive;
                differing += f.color()[i] != f.color()[corner] || f.id()[i] != f.id()[corner] ||
                             f.state()[corner] != kInteractive;
            }
        }
    });
    EXPECT_EQ(interactive, std::size_t(70 * 45));
    EXPECT_EQ(differing, 0u);
    EXPECT_EQ(info.tracedPixels, std::size_t(18 * 12));  // ceil(70 / 4) x ceil(45 / 4) rays
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

TEST(RenderSession, DeferredShadows_RecordsWhileMovingAndResolvesExactlyAfterRelease) {
    SceneDocument doc = testRoom();
    RenderSession session(2);
    InteractionPolicy p;
    p.shadows = MovingShadows::Deferred;
    PassInfo info;
    ASSERT_TRUE(firstDragStep(session, doc, p, info));
    std::size_t deferred = 0, interactive = 0;
    session.withFrame([&](const DeepFrame& f, const auto&) {
        for (std::size_t i = 0; i < f.pixelCount(); ++i) {
            deferred += (f.flags()[i] & kDeferredValid) != 0;
            interactive += f.state()[i] == kInteractive;
        }
    });
    EXPECT_EQ(interactive, doc.render.width * std::size_t(doc.render.height));
    EXPECT_GT(deferred, interactive * 9 / 10);
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

TEST(RenderSession, DeferredShadows_MarkTheMovedShadowOnceOnRelease) {
    // While dragging with deferred shadows, pixels that only the ball's shadow changes are
    // not shown differently, so steps do not mark them; release marks them and the frame
    // ends exact. With full shadows while moving, every step marks them.
    auto stepMarks = [](MovingShadows shadows, float& diff) {
        SceneDocument doc = testRoom();
        RenderSession session(2);
        InteractionPolicy p;
        p.shadows = shadows;
        p.governorTargetMs = 0.0;
        session.setPolicy(p);
        session.update(doc);
        EXPECT_TRUE(session.waitUntilComplete(60s));
        session.beginInteraction(doc.objects[2].id);
        std::size_t marked = 0;
        for (int step = 0; step < 4; ++step) {
            doc.objects[2].transform.translate.x += 0.1f;
            EXPECT_TRUE(session.waitForPass(session.update(doc), 30s));
            marked += session.stats().lastDirtyPixels;
        }
        session.endInteraction();
        EXPECT_TRUE(session.waitUntilComplete(60s));
        diff = maxDiffToFullRender(session, doc);
        return marked;
    };
    float deferredDiff = 1.0f, fullDiff = 1.0f;
    const std::size_t deferred = stepMarks(MovingShadows::Deferred, deferredDiff);
    const std::size_t full = stepMarks(MovingShadows::Full, fullDiff);
    EXPECT_LT(deferred, full);
    EXPECT_LE(deferredDiff, 1e-5f);
    EXPECT_LE(fullDiff, 1e-5f);
}

TEST(RenderSession, LightEdits_RetraceOnlyPixelsTheLightCanReach) {
    // A second light below the floor and behind the back wall: neither faces it, so moving
    // or dimming it re-traces the balls (and what sees them), not the floor or the wall.
    SceneDocument doc = test::smallRoom(64, 48);
    const ObjectId under = test::addPointLight(doc, "under", Vec3(0.5f, -3.0f, -9.0f), 0.5f);
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const std::size_t total = std::size_t(doc.render.width) * std::size_t(doc.render.height);
    for (int k = 0; k < 2; ++k) {
        Light* l = nullptr;
        for (Light& candidate : doc.lights)
            if (candidate.id == under) l = &candidate;
        ASSERT_NE(l, nullptr);
        if (k == 0)
            l->position.x += 0.4f;
        else
            l->intensity = 0.8f;
        ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
        const std::size_t marked = session.stats().lastDirtyPixels;
        EXPECT_GT(marked, 0u);
        EXPECT_LT(marked, total / 2) << "edit " << k;
        ASSERT_TRUE(session.waitUntilComplete(60s));
        EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f) << "edit " << k;
    }
    // The key light above faces nearly everything.
    doc.lights[0].position.x += 0.3f;
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
    EXPECT_GT(session.stats().lastDirtyPixels, total / 2);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

TEST(RenderSession, HalfResolutionWhileMoving_TracesAQuarterOfTheDirtyPixels) {
    SceneDocument doc = testRoom();
    RenderSession session(2);
    InteractionPolicy p;
    p.resolution = MovingResolution::Half;
    p.dirtyRegions = false;
    p.governorTargetMs = 0.0;
    session.setPolicy(p);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    session.beginInteraction(doc.objects[2].id);
    doc.objects[2].transform.translate.x += 0.3f;
    PassInfo info;
    ASSERT_TRUE(session.waitForPass(session.update(doc), 30s, &info));
    EXPECT_EQ(info.tracedPixels, std::size_t(64 / 2) * std::size_t(48 / 2));
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
}

/// Holds the workers in tileDone once a tile of `from` (or later) commits, until released.
class TileGate : public SessionObserver {
public:
    void tileDone(int, int, int, int, uint64_t generation) override {
        std::unique_lock lock(m_);
        if (from_ == 0 || generation < from_) return;
        held_ = true;
        cv_.notify_all();
        cv_.wait(lock, [&] { return !from_; });
    }
    void close(uint64_t from) {
        std::lock_guard lock(m_);
        from_ = from;
    }
    bool waitHeld() {
        std::unique_lock lock(m_);
        return cv_.wait_for(lock, 30s, [&] { return held_; });
    }
    void open() {
        std::lock_guard lock(m_);
        from_ = 0;
        cv_.notify_all();
    }

private:
    std::mutex m_;
    std::condition_variable cv_;
    uint64_t from_ = 0;
    bool held_ = false;
};

TEST(RenderSession, WholeFrames_APassOverStalePixelsTearsTheFrameUntilOneLeavesNoneStale) {
    SceneDocument doc = testRoom();
    TileGate gate;
    RenderSession session(2);
    session.setObserver(&gate);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const uint64_t opened = session.wholeMark();
    bool whole = false;
    session.withFrame([&](const DeepFrame&, const auto&) { whole = session.wholeSince(opened); });
    EXPECT_TRUE(whole);
    // An edit that traces nothing marks nothing: still the same whole frame.
    doc.objects[2].name += " renamed";
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_EQ(session.wholeMark(), opened);
    // An orbit step marks every pixel: with its first tiles committed and the pass not
    // done, the frame is torn (pixels of two cameras), and whole again after the pass.
    // (Marked alone, before its pass, it still shows one camera: marking keeps colours.)
    session.beginInteraction(kNoObject);
    doc.camera.position.x += 0.2f;
    const uint64_t orbit = session.generation() + 1;
    gate.close(orbit);
    ASSERT_EQ(session.update(doc), orbit);
    ASSERT_TRUE(gate.waitHeld());
    session.withFrame([&](const DeepFrame& f, const auto&) {
        EXPECT_GT(f.countBelow(kInteractive), 0u);
        EXPECT_FALSE(session.wholeSince(session.wholeMark()));
    });
    EXPECT_EQ(session.wholeMark(), opened);
    gate.open();
    ASSERT_TRUE(session.waitForPass(orbit, 30s));
    EXPECT_GT(session.wholeMark(), opened);
    session.withFrame(
        [&](const DeepFrame&, const auto&) { whole = session.wholeSince(session.wholeMark()); });
    EXPECT_TRUE(whole);
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
    session.setObserver(nullptr);
}

/// Sets a policy of `targetMs` governor target (and whole frames while moving or not) on
/// `session` and traces `doc` to completion.
static void governedAndComplete(RenderSession& session, const SceneDocument& doc, double targetMs,
                                bool wholeFrames = true) {
    InteractionPolicy p;
    p.governorTargetMs = targetMs;
    p.wholeFramesWhileMoving = wholeFrames;
    session.setPolicy(p);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
}

/// Ends the interaction, waits for the refined frame and checks it against a full render.
static void releasedEndsExact(RenderSession& session, const SceneDocument& doc) {
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
    session.setObserver(nullptr);
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

/// Starts a governed orbit step of `doc` whose workers `gate` holds mid-pass; returns its
/// generation.
static uint64_t orbitStepHeldMidPass(RenderSession& session, TileGate& gate, SceneDocument& doc) {
    session.setObserver(&gate);
    session.beginInteraction(kNoObject);
    doc.camera.position.x += 0.2f;
    gate.close(session.generation() + 1);
    const uint64_t step = session.update(doc);
    EXPECT_TRUE(gate.waitHeld());
    return step;
}

/// Holds a governed orbit step mid-pass, posts another move, and checks that the move cuts
/// the pass and ends exact after release. The caller declares `gate` before `session`, so the
/// session's workers (joined by its destructor) never call a gate that is gone.
static void heldPassIsCutByTheNextEdit(RenderSession& session, TileGate& gate, SceneDocument& doc) {
    const uint64_t step = orbitStepHeldMidPass(session, gate, doc);
    doc.camera.position.x += 0.1f;
    const uint64_t next = session.update(doc);
    gate.open();
    EXPECT_FALSE(session.waitForPass(step, 30s));  // Cut: the next edit is traced instead.
    ASSERT_TRUE(session.waitForPass(next, 30s));
    releasedEndsExact(session, doc);
}

TEST(RenderSession, WhileMoving_AGovernedPassWithinItsTimeFinishes_TheEditsWaitForIt) {
    SceneDocument doc = testRoom();
    TileGate gate;  // Outlives the session, whose workers may still call it.
    RenderSession session(2);
    // However long the test holds the pass, it is in time.
    governedAndComplete(session, doc, 60000.0);
    const uint64_t step = orbitStepHeldMidPass(session, gate, doc);
    // Two more mouse moves while the pass runs: they coalesce and wait for it.
    uint64_t last = 0;
    for (int k = 0; k < 2; ++k) {
        doc.camera.position.x += 0.1f;
        last = session.update(doc);
    }
    EXPECT_EQ(last, step + 2);
    gate.open();
    PassInfo info;
    ASSERT_TRUE(session.waitForPass(step, 30s, &info));  // Ended whole, not cut.
    EXPECT_FALSE(info.cancelled);
    EXPECT_EQ(info.tracedPixels, info.totalPixels);
    // Then the latest edit is applied and traced; released, the frame is exact.
    ASSERT_TRUE(session.waitForPass(last, 30s));
    releasedEndsExact(session, doc);
}

TEST(RenderSession, WhileMoving_WithWholeFramesOff_EveryEditCutsThePass) {
    SceneDocument doc = testRoom();
    TileGate gate;
    RenderSession session(2);
    // However long the test holds the pass, it is in time: only the policy lets it be cut.
    governedAndComplete(session, doc, 60000.0, /*wholeFrames=*/false);
    heldPassIsCutByTheNextEdit(session, gate, doc);
}

TEST(RenderSession, WhileMoving_APassOverItsTimeIsCutByTheNextEdit) {
    SceneDocument doc = testRoom();
    TileGate gate;
    RenderSession session(2);
    governedAndComplete(session, doc, 1e-3);  // Any pass held mid-way is long over its time.
    heldPassIsCutByTheNextEdit(session, gate, doc);
}

TEST(RenderSession, EditsFromAnotherThreadWhileRendering_EndExact) {
    // Stress: edits arrive from a second thread as fast as it can make them; the TSan preset
    // runs this too.
    SceneDocument doc = testRoom();
    doc.render.width = 96;
    doc.render.height = 72;
    RenderSession session(2);
    session.update(doc);
    std::thread editor([&] {
        std::mt19937 rng(42);
        session.beginInteraction(doc.objects[3].id);
        for (int i = 0; i < 60; ++i) {
            randomEdit(doc, rng);
            session.update(doc);
        }
        session.endInteraction();
    });
    editor.join();
    ASSERT_TRUE(session.waitUntilComplete(120s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
    EXPECT_GT(session.stats().passes, 0u);
}

TEST(RenderSession, FramesSizedByTheViewport_OddSizesResizedMidDrag_EndExact) {
    // The designer's viewport traces its own size: any odd size, and a new one whenever the
    // window edge comes to rest, even during a drag. A target no level meets walks the
    // governor down to quarter resolution and the box proxy, whose blocks do not divide 333.
    SceneDocument doc = testRoom();
    doc.render.width = 333;
    doc.render.height = 187;
    InteractionPolicy p;
    p.governorTargetMs = 0.01;
    RenderSession session(2);
    session.setPolicy(p);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    ASSERT_LE(maxDiffToFullRender(session, doc), 1e-5f);
    std::mt19937 rng(21);
    session.beginInteraction(doc.objects[2].id);
    for (int e = 0; e < 3; ++e) {
        randomEdit(doc, rng);
        session.waitForPass(session.update(doc), 30s);
    }
    doc.render.width = 187;
    doc.render.height = 333;
    for (int e = 0; e < 3; ++e) {
        randomEdit(doc, rng);
        session.waitForPass(session.update(doc), 30s);
    }
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
    session.withFrame([](const DeepFrame& f, const auto&) {
        EXPECT_EQ(f.width(), 187);
        EXPECT_EQ(f.height(), 333);
    });
}

}  // namespace
}  // namespace rs
