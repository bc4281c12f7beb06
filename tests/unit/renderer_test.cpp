// Full renders: thread-count determinism, sampling patterns, adaptive supersampling, cancel.
#include "integrator/renderer.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <set>
#include <thread>

#include "test_scenes.h"

namespace rs {
namespace {

/// Renders `scene` on 1, 2 and 4 threads (the last with odd tiles) and expects one result.
void expectSameForAnyThreadCount(const CompiledScene& scene) {
    RenderOptions one, two, four;
    one.threads = 1;
    two.threads = 2;
    four.threads = 4;
    four.tileSize = 7;  // Different tiling must not matter either.
    const RenderResult a = renderImage(scene, one);
    const RenderResult b = renderImage(scene, two);
    const RenderResult c = renderImage(scene, four);
    EXPECT_EQ(a.image.pixels, b.image.pixels);
    EXPECT_EQ(a.image.pixels, c.image.pixels);
    EXPECT_EQ(a.ids, c.ids);
    EXPECT_EQ(a.rays, c.rays);
}

TEST(Renderer, SameImageForAnyThreadCount) {
    SceneDocument doc = test::smallRoom(80, 60);
    doc.render.supersampling = 2;
    doc.render.shadowSamples = 4;
    test::addSphereLight(doc, "area", Vec3(2, 3, -2), 0.5f);
    expectSameForAnyThreadCount(CompiledScene(doc));
}

TEST(Renderer, IdsBufferNamesTheObjectSeenThroughEachPixelCentre) {
    SceneDocument doc;
    doc.render.width = 9;
    doc.render.height = 9;
    const ObjectId ball = test::addSphere(doc, "ball", Vec3(0, 0, -5), 1.0f, "");
    const CompiledScene scene(doc);
    const RenderResult r = renderImage(scene);
    EXPECT_EQ(r.ids[4 * 9 + 4], ball);
    EXPECT_EQ(r.ids[0], kNoObject);
}

TEST(Sampling, PerfectSquareCounts_UseTheRegularSubGrid) {
    std::set<std::pair<float, float>> seen;
    for (int k = 0; k < 4; ++k) {
        Vec3 o = pixelSampleOffset(k, 4, 123u);
        seen.insert({o.x, o.y});
    }
    EXPECT_EQ(seen, (std::set<std::pair<float, float>>{
                        {0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}}));
    EXPECT_EQ(pixelSampleOffset(0, 1, 5u), Vec3(0.5f, 0.5f, 0.0f));
}

TEST(Sampling, OtherCounts_AreNRooksStratified) {
    for (int n : {2, 3, 8, 12}) {
        for (uint32_t seed : {1u, 99u, 12345u}) {
            std::set<int> cols, rows;
            for (int k = 0; k < n; ++k) {
                Vec3 o = pixelSampleOffset(k, n, seed);
                ASSERT_GE(o.x, 0.0f);
                ASSERT_LT(o.x, 1.0f);
                ASSERT_GE(o.y, 0.0f);
                ASSERT_LT(o.y, 1.0f);
                cols.insert(int(o.x * float(n)));
                rows.insert(int(o.y * float(n)));
            }
            EXPECT_EQ(int(cols.size()), n) << "n=" << n;
            EXPECT_EQ(int(rows.size()), n) << "n=" << n;
        }
    }
}

TEST(Sampling, DiskSamples_StayInsideTheUnitDiskAndCoverIt) {
    float sumX = 0.0f, sumY = 0.0f;
    for (int k = 0; k < 64; ++k) {
        Vec3 d = stratifiedDiskSample(k, 64, 77u);
        EXPECT_LE(glm::length(d), 1.0f + 1e-6f);
        sumX += d.x;
        sumY += d.y;
    }
    EXPECT_NEAR(sumX / 64.0f, 0.0f, 0.1f);
    EXPECT_NEAR(sumY / 64.0f, 0.0f, 0.1f);
}

TEST(Renderer, AdaptiveSupersampling_MatchesFullSupersamplingOnEdgesOnly) {
    SceneDocument doc = test::smallRoom(64, 48);
    doc.render.supersampling = 4;
    const RenderResult full = renderImage(CompiledScene(doc));
    doc.render.adaptiveSupersampling = true;
    const RenderResult adaptive = renderImage(CompiledScene(doc));
    doc.render.supersampling = 1;
    const RenderResult single = renderImage(CompiledScene(doc));
    int supersampled = 0, kept = 0;
    for (std::size_t i = 0; i < full.image.pixels.size(); ++i) {
        const Color a = adaptive.image.pixels[i];
        if (a == full.image.pixels[i] && a != single.image.pixels[i])
            ++supersampled;
        else if (a == single.image.pixels[i])
            ++kept;
        else
            ADD_FAILURE() << "pixel " << i << " is neither the 1-sample nor the 4-sample value";
    }
    EXPECT_GT(supersampled, 50);                         // Silhouettes were refined...
    EXPECT_GT(kept, int(full.image.pixels.size()) / 2);  // ...flat areas were not.
    EXPECT_LT(adaptive.rays, full.rays);
}

TEST(Renderer, CancelFlag_StopsTheRenderAndSaysSo) {
    // Point lights only (packet tracer where the CPU has it), then a sphere light (scalar).
    SceneDocument doc = test::smallRoom(64, 48);
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) {
            Light area;
            area.name = "area";
            area.type = LightType::Sphere;
            area.position = Vec3(2, 3, -2);
            doc.addLight(area);
        }
        const CompiledScene scene(doc);
        renderImage(scene);  // leaves a used image behind for the allocator to hand out again
        std::atomic<bool> cancel{true};
        RenderOptions options;
        options.cancel = &cancel;
        const RenderResult r = renderImage(scene, options);
        EXPECT_TRUE(r.cancelled);
        EXPECT_EQ(r.rays, 0u);
        // The buffers are not cleared up front: untraced tiles must still read as nothing.
        for (const Color& c : r.image.pixels) ASSERT_EQ(c, Color(0.0f)) << "pass " << pass;
        ASSERT_EQ(r.ids.size(), r.image.pixels.size());
        for (ObjectId id : r.ids) ASSERT_EQ(id, kNoObject) << "pass " << pass;
    }
}

TEST(Renderer, HoldFlag_NoTileStartsWhileHeld_ThenTheSameImage) {
    SceneDocument doc = test::smallRoom(64, 48);
    const CompiledScene scene(doc);
    const RenderResult free = renderImage(scene);
    std::atomic<bool> hold{true};
    std::atomic<int> tiles{0};
    RenderOptions options;
    options.threads = 2;
    options.hold = &hold;
    options.progress = [&](int done, int) { tiles = done; };
    RenderResult held;
    std::thread render([&] { held = renderImage(scene, options); });
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    EXPECT_EQ(tiles.load(), 0);  // Held from the start: not one tile traced.
    hold = false;
    render.join();
    EXPECT_FALSE(held.cancelled);
    EXPECT_EQ(tiles.load(), 4);  // 64 x 48 in 32-pixel tiles
    EXPECT_EQ(held.image.pixels, free.image.pixels);
    // Cancelled while held: it returns rather than waiting on.
    std::atomic<bool> cancel{false};
    hold = true;
    options.cancel = &cancel;
    std::thread cancelled([&] { held = renderImage(scene, options); });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    cancel = true;
    cancelled.join();
    EXPECT_TRUE(held.cancelled);
}

TEST(Renderer, SameImageForAnyThreadCount_PointLights) {
    // Centre samples and supersampled, with each engine.
    for (EngineKind engine : {EngineKind::Embree, EngineKind::Builtin}) {
        SCOPED_TRACE(engineName(engine));
        SceneDocument doc = test::smallRoom(83, 61);
        expectSameForAnyThreadCount(CompiledScene(doc, nullptr, engine));
        doc.render.supersampling = 3;
        expectSameForAnyThreadCount(CompiledScene(doc, nullptr, engine));
    }
}

TEST(Renderer, SameImageForAnyThreadCount_EachEngine_MeshesBoxesAndASphereLight) {
    for (EngineKind engine : {EngineKind::Embree, EngineKind::Builtin}) {
        SCOPED_TRACE(engineName(engine));
        SceneDocument doc = test::smallRoom(72, 54);
        doc.render.shadowSamples = 3;
        Light area;
        area.name = "area";
        area.type = LightType::Sphere;
        area.position = Vec3(-1.5f, 2.5f, -3.0f);
        area.radius = 0.4f;
        doc.addLight(area);
        Object box;
        box.name = "box";
        box.material = "mirror";
        box.geometry = BoxGeometry{Vec3(-0.4f), Vec3(0.4f)};
        box.transform.translate = Vec3(-0.6f, -1.4f, -3.6f);
        box.transform.rotate = Vec3(0, 30, 10);
        doc.addObject(box);
        Object mesh;
        mesh.name = "mesh";
        mesh.material = "glass";
        MeshGeometry g;
        g.file = "tetrahedron.obj";
        g.data = test::tetrahedron();
        mesh.geometry = g;
        mesh.transform.translate = Vec3(0.9f, -1.2f, -3.3f);
        mesh.transform.scale = Vec3(1.5f);
        doc.addObject(mesh);
        expectSameForAnyThreadCount(CompiledScene(doc, nullptr, engine));
    }
}

TEST(Renderer, EachPixelIsItsCentreRayTracedAloneWithItsSeed) {
    // A tile builds its centre rays from per-column and per-row terms and its seeds from a
    // key per row: each pixel must still be generateRay(x + 0.5, y + 0.5) traced alone with
    // pixelSeed(x, y, 0), bit for bit, for both projections, odd tiles and a band of rows.
    for (const Projection projection : {Projection::Perspective, Projection::Orthographic}) {
        SCOPED_TRACE(int(projection));
        SceneDocument doc = test::smallRoom(45, 29);
        doc.camera.projection = projection;
        doc.camera.orthoHeight = 6.0f;
        doc.render.shadowSamples = 4;  // the seed picks the sphere light's samples
        test::addSphereLight(doc, "area", Vec3(1.0f, 2.5f, -2.5f), 0.6f);
        const CompiledScene scene(doc);
        RenderOptions options;
        options.tileSize = 13;
        options.firstRow = 3;
        options.endRow = 27;
        const RenderResult r = renderImage(scene, options);
        const WhittedIntegrator integrator(scene);
        for (int y = options.firstRow; y < options.endRow; ++y) {
            for (int x = 0; x < 45; ++x) {
                TraceCounters counters;
                const Color c = integrator.traceCamera(
                    scene.camera().generateRay(float(x) + 0.5f, float(y) + 0.5f),
                    pixelSeed(x, y, 0), counters);
                ASSERT_EQ(r.image.at(x, y - options.firstRow), c) << x << ", " << y;
            }
        }
    }
}

TEST(Renderer, IdsOff_SameImageWithoutTheIdBuffer) {
    const CompiledScene scene(test::smallRoom(40, 30));
    RenderOptions withoutIds;
    withoutIds.ids = false;
    const RenderResult a = renderImage(scene);
    const RenderResult b = renderImage(scene, withoutIds);
    EXPECT_EQ(a.ids.size(), a.image.pixels.size());
    EXPECT_TRUE(b.ids.empty());
    EXPECT_EQ(a.image.pixels, b.image.pixels);
    EXPECT_EQ(a.rays, b.rays);
}

TEST(Renderer, ProgressReportsEveryTileOnce) {
    SceneDocument doc = test::smallRoom(100, 40);
    RenderOptions options;
    options.tileSize = 32;  // 4 x 2 tiles.
    int calls = 0, last = 0, total = 0;
    options.progress = [&](int done, int t) {
        ++calls;
        last = std::max(last, done);
        total = t;
    };
    renderImage(CompiledScene(doc), options);
    EXPECT_EQ(total, 8);
    EXPECT_EQ(calls, 8);
    EXPECT_EQ(last, 8);
}

TEST(Camera, PixelCentreOfTheImageLooksAtTheTarget) {
    Camera cam;
    cam.position = Vec3(1, 2, 3);
    cam.target = Vec3(4, 2, -1);
    const CameraModel model(cam, 100, 50);
    const Ray r = model.generateRay(50.0f, 25.0f);
    const Vec3 expected = glm::normalize(cam.target - cam.position);
    EXPECT_NEAR(glm::dot(r.dir, expected), 1.0f, 1e-6f);
}

TEST(Camera, ImageYGrowsDownwardsAndXToTheRight) {
    Camera cam;  // At the origin looking down -z with +y up.
    const CameraModel model(cam, 100, 100);
    const Ray topLeft = model.generateRay(0.5f, 0.5f);
    EXPECT_LT(topLeft.dir.x, 0.0f);
    EXPECT_GT(topLeft.dir.y, 0.0f);
    // fov_y 55: the top edge of the image is 27.5 degrees above the axis.
    const Ray top = model.generateRay(50.0f, 0.0f);
    EXPECT_NEAR(std::atan2(top.dir.y, -top.dir.z), glm::radians(27.5f), 1e-5f);
}

TEST(Camera, ProjectIsTheInverseOfGenerateRay) {
    Camera cam;
    cam.position = Vec3(0, 1, 5);
    cam.target = Vec3(0.5f, 0, 0);
    for (Projection p : {Projection::Perspective, Projection::Orthographic}) {
        cam.projection = p;
        const CameraModel model(cam, 320, 200);
        const Ray r = model.generateRay(37.25f, 150.5f);
        float px, py;
        ASSERT_TRUE(model.project(r.at(3.0f), px, py));
        EXPECT_NEAR(px, 37.25f, 1e-3f);
        EXPECT_NEAR(py, 150.5f, 1e-3f);
    }
}

TEST(Camera, OrthographicRaysAreParallelAndSpanOrthoHeight) {
    Camera cam;
    cam.projection = Projection::Orthographic;
    cam.orthoHeight = 4.0f;
    const CameraModel model(cam, 10, 10);
    const Ray top = model.generateRay(5.0f, 0.0f), bottom = model.generateRay(5.0f, 10.0f);
    EXPECT_EQ(top.dir, bottom.dir);
    EXPECT_NEAR(top.origin.y - bottom.origin.y, 4.0f, 1e-5f);
}

}  // namespace
}  // namespace rs

namespace rs {
namespace {

/// Two facing glass spheres between two parallel mirrors: every glass hit splits into a
/// reflected and a refracted ray and the mirrors send both back, so without min_weight the
/// tree doubles per glass hit (issue 12: depth 1000 exhausted 24 GB).
SceneDocument glassPair(int maxDepth, float minWeight) {
    SceneDocument doc;
    doc.render.width = 64;
    doc.render.height = 36;
    doc.render.maxDepth = maxDepth;
    doc.render.minWeight = minWeight;
    doc.render.background = Color(0.3f, 0.4f, 0.6f);
    doc.camera.position = Vec3(0, 0, 4);
    doc.camera.target = Vec3(0, 0, 0);
    test::addMaterial(doc, "glass", Color(1.0f), 0.0f, 0.5f, 0.0f, 1.0f, 1.5f);
    test::addMaterial(doc, "mirror", Color(0.9f), 0.1f, 0.0f, 0.9f);
    test::addSphere(doc, "left", Vec3(-0.6f, 0, 0), 0.55f, "glass");
    test::addSphere(doc, "right", Vec3(0.6f, 0, 0), 0.55f, "glass");
    test::addPlane(doc, "west", Vec3(-2, 0, 0), Vec3(1, 0, 0), "mirror");
    test::addPlane(doc, "east", Vec3(2, 0, 0), Vec3(-1, 0, 0), "mirror");
    test::addPointLight(doc, "light", Vec3(0, 3, 3), 1.0f);
    return doc;
}

TEST(Renderer, GlassPairAtDepth1000_MinWeightBoundsTheTree) {
    // The default min_weight (1/255) keeps at most 255 rays per level per camera ray; in
    // practice the trees die out within a few dozen levels.
    for (EngineKind engine : {EngineKind::Embree, EngineKind::Builtin}) {
        const RenderResult deep =
            renderImage(CompiledScene(glassPair(1000, 1.0f / 255.0f), nullptr, engine));
        EXPECT_FALSE(deep.cancelled);
        const uint64_t pixels = 64 * 36;
        EXPECT_LT(deep.rays, pixels * 20000) << engineName(engine);
        // And min_weight changes the picture only by what it cut: at depth 8 the cut rays
        // weigh less than 1/255 each.
        const RenderResult cut =
            renderImage(CompiledScene(glassPair(8, 1.0f / 255.0f), nullptr, engine));
        const RenderResult all = renderImage(CompiledScene(glassPair(8, 0.0f), nullptr, engine));
        EXPECT_LT(cut.rays, all.rays);
        float worst = 0.0f;
        for (std::size_t i = 0; i < all.image.pixels.size(); ++i) {
            const Color d = glm::abs(all.image.pixels[i] - cut.image.pixels[i]);
            worst = std::max(worst, std::max(d.x, std::max(d.y, d.z)));
        }
        EXPECT_GT(worst, 0.0f);
        EXPECT_LT(worst, 0.05f);
    }
}

TEST(Renderer, CancelStopsInsideADeepRayTree) {
    // With min_weight 0 the glass pair's trees grow about sevenfold every ten levels: at
    // depth 40 the whole 64x36 image takes ~0.2 s (so a cancel at 200 ms raced the finish
    // and CI once lost), at 60 ~8 s, at 80 several minutes on a 2-core machine. The render
    // returns at once only because cancellation is polled between the levels of a tree.
    std::atomic<bool> cancel{false};
    RenderOptions options;
    options.cancel = &cancel;
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        cancel = true;
    });
    const auto start = std::chrono::steady_clock::now();
    const RenderResult r = renderImage(CompiledScene(glassPair(80, 0.0f)), options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    canceller.join();
    EXPECT_TRUE(r.cancelled);
    EXPECT_EQ(r.image.pixels.size(), std::size_t(64 * 36));
    // Promptly: far below the minutes the uncancelled render takes, with room for TSan.
    EXPECT_LT(seconds, 20.0);
}

}  // namespace
}  // namespace rs
