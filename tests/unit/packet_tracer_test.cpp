// The packet tracer against the scalar integrator: the same bits for every colour, id, normal
// and ray count, on fixed and random flat scenes.
#include "integrator/packet_tracer.h"
#include "integrator/renderer.h"
#include "io/scene_io.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <sstream>
#include <string>

namespace rs {
namespace {

bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Traces `scene` tile by tile with PacketTracer and pixel by pixel with traceCamera (the
/// path renderImage takes without packets) and expects identical results. Tiles of 13 pixels
/// leave partial eight-ray batches at every row's end.
void expectSameAsScalar(const CompiledScene& scene, const std::string& what,
                        PacketTracer::Kernel kernel) {
    ASSERT_TRUE(PacketTracer::supports(scene)) << what;
    const int w = scene.settings().width, h = scene.settings().height;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    std::vector<Color> colors(n, Color(-1.0f));
    std::vector<ObjectId> ids(n, 12345u);
    std::vector<Vec3> normals(n, Vec3(-7.0f));
    const PacketTracer tracer(scene, kernel);
    const WhittedIntegrator integrator(scene);
    TraceCounters packetCounters, scalarCounters;
    int colorMismatches = 0, idMismatches = 0, normalMismatches = 0;
    std::ostringstream first;
    constexpr int kTile = 13;
    for (int y0 = 0; y0 < h; y0 += kTile) {
        for (int x0 = 0; x0 < w; x0 += kTile) {
            const int x1 = std::min(w, x0 + kTile), y1 = std::min(h, y0 + kTile);
            RaySubset subset;
            cullTile(scene, x0, y0, x1, y1, subset);
            tracer.traceTile(x0, y0, x1, y1, subset, std::size_t(w), colors.data(), ids.data(),
                             normals.data(), packetCounters);
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    PrimaryInfo info;
                    const Color c = integrator.traceCamera(
                        scene.camera().generateRay(float(x) + 0.5f, float(y) + 0.5f),
                        pixelSeed(x, y, 0), scalarCounters, &info, nullptr, nullptr, &subset);
                    const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                    if (!sameBits(c, colors[i]) && colorMismatches++ == 0)
                        first << "pixel (" << x << ", " << y << "): scalar " << c.x << " " << c.y
                              << " " << c.z << ", packet " << colors[i].x << " " << colors[i].y
                              << " " << colors[i].z;
                    idMismatches += info.id != ids[i];
                    normalMismatches += !sameBits(info.normal, normals[i]);
                }
            }
        }
    }
    EXPECT_EQ(colorMismatches, 0) << what << ", first at " << first.str();
    EXPECT_EQ(idMismatches, 0) << what;
    EXPECT_EQ(normalMismatches, 0) << what;
    EXPECT_EQ(packetCounters.rays, scalarCounters.rays) << what;
    EXPECT_EQ(packetCounters.shadowRays, scalarCounters.shadowRays) << what;
}

/// The fastest kernel this CPU runs (AVX2 where it has it) and the baseline build.
void expectBothKernelsSameAsScalar(const CompiledScene& scene, const std::string& what) {
    expectSameAsScalar(scene, what + ", fastest kernel", PacketTracer::Kernel::Fastest);
    expectSameAsScalar(scene, what + ", baseline kernel", PacketTracer::Kernel::Baseline);
}

TEST(PacketTracer, SmallRoom_SameBitsAsTheIntegrator) {
    for (int depth : {0, 1, 3, 8}) {
        SceneDocument doc = test::smallRoom(61, 37);
        doc.render.maxDepth = depth;
        doc.render.background = Color(0.2f, 0.3f, 0.4f);
        expectBothKernelsSameAsScalar(CompiledScene(doc), "depth " + std::to_string(depth));
    }
}

TEST(PacketTracer, ReferenceRoom_SameBitsAsTheIntegrator) {
    SceneLoadResult loaded = loadScene(RAYSTUDIO_SCENES_DIR "/reference-room.scene.json");
    ASSERT_TRUE(loaded.ok());
    loaded.document.render.width = 160;
    loaded.document.render.height = 90;
    expectBothKernelsSameAsScalar(CompiledScene(loaded.document), "reference room");
}

/// A random scene of planes and up to 16 spheres: overlapping glass, mirrors, Phong and
/// Lambert materials, lights inside and outside spheres, the camera sometimes inside glass.
SceneDocument randomFlatScene(uint32_t seed) {
    std::mt19937 rng(seed);
    auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    auto chance = [&](float p) { return uniform(0.0f, 1.0f) < p; };
    SceneDocument doc;
    doc.render.width = 45;
    doc.render.height = 29;
    doc.render.maxDepth = int(rng() % 7);
    doc.render.shadowSamples = chance(0.2f) ? 0 : 1 + int(rng() % 3);
    doc.render.background = Color(uniform(0, 0.5f), uniform(0, 0.5f), uniform(0, 0.5f));
    doc.render.ambient = Color(uniform(0, 0.2f));
    doc.camera.position = Vec3(uniform(-1, 1), uniform(-1, 1), uniform(2, 4));
    doc.camera.target = Vec3(uniform(-0.5f, 0.5f), uniform(-0.5f, 0.5f), 0.0f);
    if (chance(0.25f)) {
        doc.camera.projection = Projection::Orthographic;
        doc.camera.orthoHeight = uniform(3, 8);
    }
    const int materials = 6;
    for (int m = 0; m < materials; ++m) {
        float reflectivity = 0, transparency = 0;
        switch (rng() % 4) {
            case 0: break;
            case 1: reflectivity = uniform(0.1f, 0.9f); break;
            case 2: transparency = uniform(0.5f, 1.0f); break;
            default:
                reflectivity = uniform(0, 0.4f);
                transparency = uniform(0, 0.5f);
        }
        test::addMaterial(doc, "m" + std::to_string(m),
                          Color(uniform(0, 1), uniform(0, 1), uniform(0, 1)), uniform(0, 1),
                          chance(0.6f) ? uniform(0, 1) : 0.0f, reflectivity, transparency,
                          uniform(1.0f, 2.4f));
        doc.materials.back().shininess = uniform(1, 300);
    }
    auto material = [&] { return "m" + std::to_string(rng() % materials); };
    const int planes = int(rng() % 5);
    for (int p = 0; p < planes; ++p) {
        Vec3 normal = glm::normalize(Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
        if (chance(0.5f)) normal = Vec3(0, 1, 0);  // axis-aligned floors tie exactly
        test::addPlane(doc, "plane " + std::to_string(p),
                       Vec3(uniform(-4, 4), uniform(-4, 0), uniform(-8, 0)), normal, material());
    }
    const int spheres = 1 + int(rng() % 16);
    for (int s = 0; s < spheres; ++s) {
        const Vec3 c = s == 0 && chance(0.2f) ? doc.camera.position  // camera inside
                                              : Vec3(uniform(-3, 3), uniform(-2, 2), uniform(-6, 1));
        test::addSphere(doc, "sphere " + std::to_string(s), c, uniform(0.2f, 1.5f), material());
    }
    const int lights = 1 + int(rng() % 3);
    for (int l = 0; l < lights; ++l) {
        test::addPointLight(doc, "light " + std::to_string(l),
                            Vec3(uniform(-4, 4), uniform(-1, 5), uniform(-6, 3)),
                            uniform(0.3f, 1.5f));
        doc.lights.back().type = LightType::Point;
    }
    return doc;
}

TEST(PacketTracer, RandomFlatScenes_SameBitsAsTheIntegrator) {
    for (uint32_t seed = 1; seed <= 60; ++seed) {
        const SceneDocument doc = randomFlatScene(seed);
        expectBothKernelsSameAsScalar(CompiledScene(doc), "seed " + std::to_string(seed));
    }
}

/// tracePixels on every `step`-th pixel against traceCamera with a PrimaryInfo and a
/// SegmentSink of `capacity`: colour, first hit and its point, touched-specular flag, rays
/// and segments.
void expectPixelsSameAsScalar(const CompiledScene& scene, const std::string& what, int step,
                              int capacity, PacketTracer::Kernel kernel) {
    const int w = scene.settings().width, h = scene.settings().height;
    std::vector<int32_t> xs, ys;
    for (int i = 0; i < w * h; i += step) xs.push_back(i % w), ys.push_back(i / w);
    std::vector<PacketPixel> out(xs.size());
    std::vector<TreeSegment> segments;
    TraceCounters packetCounters, scalarCounters;
    const PacketTracer tracer(scene, kernel);
    tracer.tracePixels(xs.data(), ys.data(), xs.size(), RaySubset{}, capacity, out.data(),
                       segments, packetCounters);
    const WhittedIntegrator integrator(scene);
    int mismatches = 0;
    std::ostringstream first;
    std::vector<TreeSegment> buffer(std::size_t(capacity) + 1);
    for (std::size_t i = 0; i < xs.size(); ++i) {
        PrimaryInfo info;
        TraceCounters tc;
        SegmentSink sink{buffer.data(), capacity, 0, false};
        const Ray ray = scene.camera().generateRay(float(xs[i]) + 0.5f, float(ys[i]) + 0.5f);
        const Color c =
            integrator.traceCamera(ray, pixelSeed(xs[i], ys[i], 0), tc, &info, nullptr, &sink);
        scalarCounters.rays += tc.rays;
        scalarCounters.shadowRays += tc.shadowRays;
        const PacketPixel& p = out[i];
        bool same = sameBits(c, p.color) && info.id == p.info.id &&
                    std::memcmp(&info.depth, &p.info.depth, sizeof(float)) == 0 &&
                    sameBits(info.normal, p.info.normal) &&
                    info.touchedSpecular == p.info.touchedSpecular && tc.total() == p.rays &&
                    uint32_t(sink.count) == p.segmentCount && sink.overflow == p.segmentOverflow &&
                    (info.id == kNoObject || sameBits(ray.at(info.depth), p.hitPoint));
        for (int k = 0; same && k < sink.count; ++k) {
            const TreeSegment& a = buffer[std::size_t(k)];
            const TreeSegment& b = segments[p.segmentOffset + std::size_t(k)];
            same = sameBits(a.a, b.a) && sameBits(a.b, b.b) && a.escapes == b.escapes;
        }
        if (!same && mismatches++ == 0)
            first << "pixel (" << xs[i] << ", " << ys[i] << "): rays " << tc.total() << " vs "
                  << p.rays << ", segments " << sink.count << " vs " << p.segmentCount;
    }
    EXPECT_EQ(mismatches, 0) << what << ", first at " << first.str();
    EXPECT_EQ(packetCounters.rays, scalarCounters.rays) << what;
    EXPECT_EQ(packetCounters.shadowRays, scalarCounters.shadowRays) << what;
}

TEST(PacketTracer, PixelLists_SameOutputsAsTheIntegrator) {
    for (const auto kernel : {PacketTracer::Kernel::Fastest, PacketTracer::Kernel::Baseline}) {
        SceneDocument room = test::smallRoom(61, 37);
        room.render.maxDepth = 6;
        expectPixelsSameAsScalar(CompiledScene(room), "small room", 3, 24, kernel);
        expectPixelsSameAsScalar(CompiledScene(room), "small room, 2 segments", 1, 2, kernel);
        for (uint32_t seed = 100; seed < 120; ++seed)
            expectPixelsSameAsScalar(CompiledScene(randomFlatScene(seed)),
                                     "seed " + std::to_string(seed), 2, 5, kernel);
    }
}

TEST(PacketTracer, Supersamples_SameBitsAsRenderPixel) {
    for (const auto kernel : {PacketTracer::Kernel::Fastest, PacketTracer::Kernel::Baseline}) {
        for (uint32_t seed = 200; seed < 206; ++seed) {
            const CompiledScene scene(randomFlatScene(seed));
            const PacketTracer tracer(scene, kernel);
            const WhittedIntegrator integrator(scene);
            const int w = scene.settings().width, h = scene.settings().height;
            std::vector<int32_t> xs, ys;
            for (int i = 0; i < w * h; i += 3) xs.push_back(i % w), ys.push_back(i / w);
            for (int spp : {2, 3, 4, 5}) {  // regular grids and n-rooks patterns
                std::vector<Color> colors(xs.size());
                std::vector<ObjectId> ids(xs.size());
                TraceCounters packetCounters, scalarCounters;
                tracer.traceSamples(xs.data(), ys.data(), xs.size(), spp, RaySubset{},
                                    colors.data(), packetCounters);
                tracer.firstHits(xs.data(), ys.data(), xs.size(), RaySubset{}, ids.data());
                int mismatches = 0;
                for (std::size_t i = 0; i < xs.size(); ++i) {
                    const Color c =
                        renderPixel(integrator, scene.camera(), xs[i], ys[i], spp, scalarCounters);
                    SurfaceHit hit;
                    const Ray centre =
                        scene.camera().generateRay(float(xs[i]) + 0.5f, float(ys[i]) + 0.5f);
                    const ObjectId id =
                        scene.intersect(centre, 0.0f, kInfinity, hit) ? hit.id : kNoObject;
                    mismatches += !sameBits(c, colors[i]) || id != ids[i];
                }
                EXPECT_EQ(mismatches, 0) << "seed " << seed << ", spp " << spp;
                EXPECT_EQ(packetCounters.total(), scalarCounters.total())
                    << "seed " << seed << ", spp " << spp;
            }
        }
    }
}

TEST(PacketTracer, RenderImage_PacketsOnOrOff_SameResult) {
    // Every path of renderImage: centre samples, full and adaptive supersampling.
    for (int spp : {1, 3, 4}) {  // 3: n-rooks, and a division that is not exact
        for (bool adaptive : {false, true}) {
            SceneDocument doc = test::smallRoom(67, 41);
            doc.render.supersampling = spp;
            doc.render.adaptiveSupersampling = adaptive;
            const CompiledScene scene(doc);
            RenderOptions on, off;
            on.threads = off.threads = 2;
            off.packets = false;
            const RenderResult a = renderImage(scene, on);
            const RenderResult b = renderImage(scene, off);
            EXPECT_EQ(a.image.pixels, b.image.pixels) << "spp " << spp << " adaptive " << adaptive;
            EXPECT_EQ(a.ids, b.ids) << "spp " << spp << " adaptive " << adaptive;
            EXPECT_EQ(a.rays, b.rays) << "spp " << spp << " adaptive " << adaptive;
        }
    }
}

TEST(PacketTracer, RenderImage_GivesTheScalarPixels) {
    // Whichever path renderImage takes on this machine, its image and ids are traceCamera's.
    SceneDocument doc = test::smallRoom(50, 30);
    const CompiledScene scene(doc);
    RenderOptions options;
    options.threads = 2;
    const RenderResult result = renderImage(scene, options);
    const WhittedIntegrator integrator(scene);
    TraceCounters counters;
    int mismatches = 0;
    for (int y = 0; y < 30; ++y) {
        for (int x = 0; x < 50; ++x) {
            PrimaryInfo info;
            const Color c = integrator.traceCamera(
                scene.camera().generateRay(float(x) + 0.5f, float(y) + 0.5f), pixelSeed(x, y, 0),
                counters, &info);
            mismatches += !sameBits(c, result.image.at(x, y)) ||
                          info.id != result.ids[std::size_t(y) * 50 + std::size_t(x)];
        }
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_EQ(result.rays, counters.total());
}

TEST(PacketTracer, Supports_OnlyFlatScenesWithoutSampledSphereLights) {
    SceneDocument doc = test::smallRoom();
    EXPECT_TRUE(PacketTracer::supports(CompiledScene(doc)));

    SceneDocument soft = doc;
    Light sphereLight;
    sphereLight.name = "soft";
    sphereLight.type = LightType::Sphere;
    sphereLight.position = Vec3(1, 3, -4);
    sphereLight.radius = 0.5f;
    soft.addLight(sphereLight);
    EXPECT_FALSE(PacketTracer::supports(CompiledScene(soft)));
    soft.render.shadowSamples = 0;  // no samples: the light is its centre, as a point light
    EXPECT_TRUE(PacketTracer::supports(CompiledScene(soft)));

    SceneDocument boxed = doc;
    Object box;
    box.name = "box";
    box.material = "red";
    box.geometry = BoxGeometry{Vec3(-0.5f), Vec3(0.5f)};
    boxed.addObject(box);
    EXPECT_FALSE(PacketTracer::supports(CompiledScene(boxed)));
}

}  // namespace
}  // namespace rs
