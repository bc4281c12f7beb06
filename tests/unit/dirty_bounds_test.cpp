// The dirty region's bounds of the shading path (session/dirty_bounds.h) against the shading
// path itself: the integrator's face-forward turn (faceHits), which light samples it lists
// (LightSampler: horizon and spot cone) and where its shadow rays go (to those samples). A
// change of either side that makes them disagree fails here.
#include "session/dirty_bounds.h"

#include <gtest/gtest.h>

#include <random>

#include "integrator/face_hits.h"
#include "integrator/light_sampling.h"
#include "snapshot/compiled_scene.h"
#include "test_scenes.h"

namespace rs {
namespace {

/// Point, sphere, spot and directional lights around the origin; 16 shadow samples.
SceneDocument mixedLights(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    SceneDocument doc;
    doc.render.shadowSamples = 16;
    test::addMaterial(doc, "m", Color(0.8f), 0.9f);
    test::addPlane(doc, "floor", Vec3(0, -4, 0), Vec3(0, 1, 0), "m");
    test::addPointLight(doc, "point", Vec3(u(rng), u(rng), u(rng)));
    for (int i = 0; i < 3; ++i)
        test::addSphereLight(doc, "sphere " + std::to_string(i), Vec3(u(rng), u(rng), u(rng)),
                             0.05f + 0.5f * std::abs(u(rng)) / 3.0f);
    for (int i = 0; i < 2; ++i) {
        Light l;
        l.name = "spot " + std::to_string(i);
        l.type = LightType::Spot;
        l.position = Vec3(u(rng), u(rng), u(rng));
        l.target = Vec3(u(rng), u(rng), u(rng));
        l.coneRadius = 10.0f + 5.0f * std::abs(u(rng));
        l.coneFalloff = l.coneRadius + 10.0f * std::abs(u(rng));
        doc.addLight(l);
    }
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(Vec3(u(rng), -3.5f, u(rng)));
    doc.addLight(sun);
    return doc;
}

/// The light as the dirty region gets it from a scene edit (scene_update.cpp's sphereOf).
LightSphere sphereOf(const CompiledLight& c) {
    return {c.position, c.radius, c.spot, c.axis, c.cosFalloff};
}

Vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        const Vec3 v(g(rng), g(rng), g(rng));
        if (glm::length(v) > 1e-3f) return glm::normalize(v);
    }
}

/// The integrator's shading point of a ray from `origin` along unit `dir` hitting at t with
/// geometric normal `h`: its point and normal turned toward the ray.
void integratorShadingPoint(const Vec3& origin, const Vec3& dir, float t, const Vec3& h, Vec3& p,
                            Vec3& n) {
    float ox[4] = {origin.x}, oy[4] = {origin.y}, oz[4] = {origin.z};
    float dx[4] = {dir.x}, dy[4] = {dir.y}, dz[4] = {dir.z};
    float ts[4] = {t}, hx[4] = {h.x}, hy[4] = {h.y}, hz[4] = {h.z};
    uint32_t slots[4] = {0};
    uint8_t inside[4] = {0};
    const HitBatch hits{ts, hx, hy, hz, slots};
    ShadingPoints sp;
    sp.resize(1);
    faceHits(ox, oy, oz, dx, dy, dz, hits, 1, sp, inside);
    p = Vec3(sp.px[0], sp.py[0], sp.pz[0]);
    n = Vec3(sp.nx[0], sp.ny[0], sp.nz[0]);
}

TEST(DirtyBounds, FaceViewerTurnsTheNormalAsTheIntegratorDoes) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f), dist(0.5f, 20.0f);
    int told = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        const Vec3 eye(u(rng), u(rng), u(rng)), dir = randomUnit(rng), h = randomUnit(rng);
        Vec3 p, n;
        integratorShadingPoint(eye, dir, dist(rng), h, p, n);
        Vec3 ns;
        if (!faceViewer(h, eye - p, ns)) continue;  // Too close to grazing to tell.
        ++told;
        ASSERT_EQ(ns, n) << "trial " << trial;
    }
    EXPECT_GT(told, 190000);
}

TEST(DirtyBounds, NoLightTheIntegratorListsIsLeftOut) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f), dist(0.5f, 20.0f);
    std::size_t leftOut = 0, listed = 0;
    for (int sceneIndex = 0; sceneIndex < 20; ++sceneIndex) {
        const SceneDocument doc = mixedLights(rng);
        const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
        const LightSampler sampler(scene);
        const float slack = 1e-4f;  // As marking takes it for a scene of this size.
        for (int trial = 0; trial < 4000; ++trial) {
            const Vec3 eye(u(rng), u(rng), u(rng)), dir = randomUnit(rng), h = randomUnit(rng);
            Vec3 p, n;
            integratorShadingPoint(eye, dir, dist(rng), h, p, n);
            Vec3 ns;
            if (!faceViewer(h, eye - p, ns)) continue;
            for (std::size_t li = 0; li < scene.lights().size(); ++li) {
                if (lightMayReach(p, ns, sphereOf(scene.lights()[li]), slack)) continue;
                ++leftOut;
                LightSamples samples;
                LightSpans spans;
                sampler.sampleLight(li, p, n, uint32_t(rng()), true, samples, spans);
                listed += samples.size();
                ASSERT_TRUE(spans.empty()) << "light " << li << " is listed at a point the "
                                           << "dirty region says it cannot reach";
            }
        }
    }
    // Below the horizon and outside spot cones both happened often.
    EXPECT_GT(leftOut, 100000u);
    EXPECT_EQ(listed, 0u);
}

TEST(DirtyBounds, ShadowRaysFromOutsideTheConeMissTheRegion) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f), side(0.05f, 1.5f), reach(0.0f, 8.0f);
    std::size_t outside = 0, rays = 0;
    for (int sceneIndex = 0; sceneIndex < 20; ++sceneIndex) {
        const SceneDocument doc = mixedLights(rng);
        const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
        const LightSampler sampler(scene);
        for (int trial = 0; trial < 3000; ++trial) {
            const Vec3 centre(u(rng), u(rng), u(rng));
            const Vec3 half(side(rng), side(rng), side(rng));
            const Aabb region{centre - half, centre + half};
            // Points near the region, many of them just outside the cones.
            const Vec3 p = centre + randomUnit(rng) * reach(rng);
            for (std::size_t li = 0; li < scene.lights().size(); ++li) {
                const CompiledLight& light = scene.lights()[li];
                if (makeCone(light, region).mayContain(p, 0.0f)) continue;
                ++outside;
                // A normal toward the light, so that its samples are listed.
                const Vec3 toLight = light.position - p;
                if (!(glm::length(toLight) > 0.0f)) continue;
                LightSamples samples;
                LightSpans spans;
                sampler.sampleLight(li, p, glm::normalize(toLight), uint32_t(rng()), true, samples,
                                    spans);
                for (const LightSample& s : samples) {
                    ++rays;
                    ASSERT_FALSE(intersectSlabs(region, Ray::make(p, s.dir * s.dist), 0.0f, 1.0f))
                        << "a shadow ray to light " << li << " crosses the region from a point "
                        << "outside its cone";
                }
            }
        }
    }
    EXPECT_GT(outside, 100000u);
    EXPECT_GT(rays, 100000u);
}

}  // namespace
}  // namespace rs
