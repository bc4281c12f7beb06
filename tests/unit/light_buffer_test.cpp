// Light buffer and camera-tile culling: both only narrow which shapes a ray tests, so the
// answers must equal the plain queries' exactly, also for rays that graze an object.
#include "accel/bvh_engine.h"
#include "snapshot/compiled_scene.h"

#include <gtest/gtest.h>

#include <random>

#include "test_scenes.h"

namespace rs {
namespace {

using test::addMaterial;
using test::addPlane;
using test::addSphere;

/// A closed room of six planes with `spheres` random balls, a box, a rotated rectangle and a
/// light of radius `lightRadius` somewhere inside.
SceneDocument randomRoom(std::mt19937& rng, int spheres, float lightRadius) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    SceneDocument doc;
    doc.render.width = 96;
    doc.render.height = 64;
    addMaterial(doc, "m", Color(0.8f), 0.9f);
    addPlane(doc, "floor", Vec3(0, -3, 0), Vec3(0, 1, 0), "m");
    addPlane(doc, "ceiling", Vec3(0, 3, 0), Vec3(0, -1, 0), "m");
    addPlane(doc, "left", Vec3(-4, 0, 0), Vec3(1, 0, 0), "m");
    addPlane(doc, "right", Vec3(4, 0, 0), Vec3(-1, 0, 0), "m");
    addPlane(doc, "back", Vec3(0, 0, -4), Vec3(0, 0, 1), "m");
    addPlane(doc, "front", Vec3(0, 0, 4), glm::normalize(Vec3(0.1f, 0.05f, -1)), "m");
    for (int i = 0; i < spheres; ++i)
        addSphere(doc, "s" + std::to_string(i), Vec3(3.0f * u(rng), 2.0f * u(rng), 3.0f * u(rng)),
                  0.2f + 0.6f * (0.5f + 0.5f * u(rng)), "m");
    Light l;
    l.name = "light";
    l.position = Vec3(2.5f * u(rng), 2.0f * u(rng), 2.5f * u(rng));
    l.type = lightRadius > 0.0f ? LightType::Sphere : LightType::Point;
    l.radius = lightRadius > 0.0f ? lightRadius : 0.5f;
    doc.addLight(l);
    doc.camera.position = Vec3(2.0f * u(rng), 1.5f * u(rng), 3.0f);
    doc.camera.target = Vec3(u(rng), u(rng), -3.0f);
    return doc;
}

void addBoxAndRectangle(SceneDocument& doc) {
    Object box;
    box.name = "box";
    box.material = "m";
    box.geometry = BoxGeometry{Vec3(-0.5f), Vec3(0.5f)};
    box.transform.rotate = Vec3(20, 35, 0);
    box.transform.translate = Vec3(-1.5f, -2.0f, -1.0f);
    doc.addObject(box);
    Object rect;
    rect.name = "rect";
    rect.material = "m";
    rect.geometry = RectangleGeometry{Vec3(1.0f, 0.5f, -2.0f), Vec3(0.8f, 0, 0), Vec3(0, 0.6f, 0.3f)};
    doc.addObject(rect);
}

/// A shadow ray as WhittedIntegrator::directLight casts it, from surface point p with facing
/// normal n toward light sample q.
bool shadowRay(const CompiledScene& scene, const Vec3& p, const Vec3& n, const Vec3& q, Ray& ray,
               float& tmax) {
    Vec3 toLight = q - p;
    const float dist = glm::length(toLight);
    if (dist <= 0.0f) return false;
    toLight = divide(toLight, dist);
    if (glm::dot(n, toLight) <= 0.0f) return false;
    ray = Ray::make(p + n * scene.epsilon(), toLight);
    tmax = dist - scene.epsilon();
    return true;
}

/// The built-in engine's any-hit answer with the light buffer (a ray toward light 0) and
/// without it (testing everything).
struct ShadowAnswers {
    bool buffered, everything;
};
ShadowAnswers shadowAnswers(const CompiledScene& scene, const Ray& ray, float tmax) {
    const RayEngine& engine = scene.engine();
    EXPECT_EQ(engine.kind(), EngineKind::Builtin);
    const uint32_t light = 0;
    RayBatch batch{&ray.origin.x, &ray.origin.y, &ray.origin.z, &ray.dir.x, &ray.dir.y,
                   &ray.dir.z,    &tmax,         1};
    uint8_t plain = 0, buffered = 0;
    engine.anyHit(batch, &plain);
    batch.light = &light;
    engine.anyHit(batch, &buffered);
    return {buffered != 0, plain != 0};
}

Vec3 randomInBall(std::mt19937& rng, float radius) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Vec3 v;
    do v = Vec3(u(rng), u(rng), u(rng));
    while (glm::dot(v, v) > 1.0f);
    return radius * v;
}

void expectSameShadowAnswers(const CompiledScene& scene, std::mt19937& rng, int cameraRays,
                             int& occludedCount, int& total) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const CompiledLight& light = scene.lights()[0];
    for (int k = 0; k < cameraRays; ++k) {
        const Ray view = scene.camera().generateRay(u01(rng) * float(scene.camera().width()),
                                                    u01(rng) * float(scene.camera().height()));
        SurfaceHit hit;
        if (!scene.intersect(view, kInfinity, hit)) continue;
        const Vec3 p = view.at(hit.t);
        const Vec3 n = glm::dot(hit.n, view.dir) > 0.0f ? -hit.n : hit.n;
        Ray ray;
        float tmax;
        if (!shadowRay(scene, p, n, light.position + randomInBall(rng, light.radius), ray, tmax))
            continue;
        const ShadowAnswers a = shadowAnswers(scene, ray, tmax);
        const bool expected = a.everything;
        ASSERT_EQ(a.buffered, expected)
            << "camera ray " << k << " from (" << p.x << ", " << p.y << ", " << p.z << ")";
        occludedCount += expected;
        ++total;
    }
}

TEST(LightBuffer, ShadowAnswersEqualTestingEverything_PointAndSphereLights) {
    std::mt19937 rng(7);
    int occluded = 0, total = 0;
    for (int scene = 0; scene < 40; ++scene) {
        SceneDocument doc = randomRoom(rng, 3 + scene % 12, scene % 2 ? 0.4f : 0.0f);
        if (scene % 3 == 0) addBoxAndRectangle(doc);  // not flat: boxes and frames too
        const CompiledScene compiled(doc, nullptr, EngineKind::Builtin);
        expectSameShadowAnswers(compiled, rng, 4000, occluded, total);
    }
    // Both answers occur often, so the comparison means something.
    EXPECT_GT(occluded, total / 20);
    EXPECT_LT(occluded, total - total / 20);
}

TEST(LightBuffer, RaysGrazingASphereGetTheSameAnswer) {
    // Shadow rays built tangent to a ball (a hair inside or outside it): the cases where a
    // too-tight cone in the buffer would drop the ball while the exact test still hits it.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int hits = 0, total = 0;
    for (int c = 0; c < 300; ++c) {
        SceneDocument doc;
        addMaterial(doc, "m", Color(0.8f), 0.9f);
        addPlane(doc, "floor", Vec3(0, -5, 0), Vec3(0, 1, 0), "m");
        const Vec3 centre(u(rng), u(rng), u(rng));
        const float radius = 0.3f + 0.5f * std::abs(u(rng));
        addSphere(doc, "ball", centre, radius, "m");
        const Vec3 normal = glm::normalize(randomInBall(rng, 1.0f) + Vec3(0, 0, 1e-3f));
        const Vec3 touch = centre + radius * normal;
        Vec3 tangent = glm::normalize(glm::cross(normal, randomInBall(rng, 1.0f) + Vec3(1e-3f, 0, 0)));
        Light l;
        l.name = "light";
        l.position = touch + (1.0f + 3.0f * std::abs(u(rng))) * tangent;
        doc.addLight(l);
        const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
        for (int k = 0; k < 50; ++k) {
            // Shading points on the far side of the tangent point, nudged across the surface.
            const float nudge = 1e-3f * u(rng) * radius;
            const Vec3 p = touch - (0.5f + 2.0f * std::abs(u(rng))) * tangent + nudge * normal;
            const Vec3 n = glm::normalize(tangent + 0.1f * normal);
            Ray ray;
            float tmax;
            if (!shadowRay(scene, p, n, l.position, ray, tmax)) continue;
            const ShadowAnswers a = shadowAnswers(scene, ray, tmax);
            const bool expected = a.everything;
            ASSERT_EQ(a.buffered, expected) << "case " << c;
            hits += expected;
            ++total;
        }
    }
    EXPECT_GT(hits, total / 10);
    EXPECT_LT(hits, total - total / 10);
}

TEST(LightBuffer, ListsOnlyWhatADirectionCanMeet) {
    std::mt19937 rng(3);
    SceneDocument doc = randomRoom(rng, 8, 0.0f);
    const CompiledScene scene(doc);
    std::vector<BoundingSphere> spheres;
    for (const Primitive& p : scene.primitives()) {
        const auto& s = std::get<SphereShape>(p.shape);
        spheres.push_back({s.center, s.radius});
    }
    std::vector<BufferPlane> planes;
    for (const PlanePrimitive& p : scene.planes()) planes.push_back({p.shape.point, p.shape.normal});
    const LightBuffer buffer(scene.lights()[0].position, 4.0f * scene.epsilon(), spheres, planes);
    // 8 balls and 6 walls: a cell sees a few of them, not all 14.
    EXPECT_GT(buffer.averageCandidates(), 0.5f);
    EXPECT_LT(buffer.averageCandidates(), 7.0f);
    // The light itself has no direction: the caller must test everything.
    EXPECT_EQ(buffer.anyHit(scene.lights()[0].position, [](uint32_t) { return false; }), -1);
}

TEST(TileCulling, OrthographicCamerasTestEverything) {
    std::mt19937 rng(9);
    SceneDocument doc = randomRoom(rng, 4, 0.0f);
    doc.camera.projection = Projection::Orthographic;
    const CompiledScene scene(doc);
    Vec3 axis;
    float halfAngle;
    EXPECT_FALSE(scene.camera().tileCone(0, 0, 16, 16, axis, halfAngle));
}

}  // namespace
}  // namespace rs
