// The flat set answers with the bits of the scalar shape tests, in both its machine codes,
// for every batch length; and camera-tile culling only narrows, never changes, answers.
#include "accel/flat_set.h"

#include <gtest/gtest.h>

#include <bit>
#include <random>

#include "accel/bvh_engine.h"
#include "snapshot/compiled_scene.h"
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

/// A box, a rotated rectangle and a stretched sphere: primitives the flat set tests one ray
/// at a time with intersectPrimitive.
void addOthers(SceneDocument& doc) {
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
    rect.geometry =
        RectangleGeometry{Vec3(1.0f, 0.5f, -2.0f), Vec3(0.8f, 0, 0), Vec3(0, 0.6f, 0.3f)};
    doc.addObject(rect);
    Object egg;
    egg.name = "egg";
    egg.material = "m";
    egg.geometry = SphereGeometry{Vec3(0.0f), 0.5f};
    egg.transform.scale = Vec3(1.0f, 2.0f, 1.0f);
    egg.transform.translate = Vec3(0.5f, 0.0f, 1.0f);
    doc.addObject(egg);
}

bool worldSphere(const Primitive& p) {
    return !p.hasFrame && std::holds_alternative<SphereShape>(p.shape);
}

/// The scalar answer the flat set must reproduce: planes in order with intersect(PlaneShape),
/// then world spheres in order with intersect(SphereShape), then the other primitives in
/// order with intersectPrimitive, each taken when strictly nearer.
EngineHit scalarClosest(const CompiledScene& scene, const Ray& ray, float tmax) {
    EngineHit best;
    best.t = tmax;
    ShapeHit sh;
    for (std::size_t j = 0; j < scene.planes().size(); ++j)
        if (intersect(scene.planes()[j].shape, ray, 0.0f, best.t, sh))
            best = {sh.t, sh.n, kPlaneSlot | uint32_t(j)};
    const auto& prims = scene.primitives();
    for (std::size_t s = 0; s < prims.size(); ++s)
        if (worldSphere(prims[s]) &&
            intersect(std::get<SphereShape>(prims[s].shape), ray, 0.0f, best.t, sh))
            best = {sh.t, sh.n, uint32_t(s)};
    for (std::size_t s = 0; s < prims.size(); ++s)
        if (!worldSphere(prims[s]) && intersectPrimitive(prims[s], ray, 0.0f, best.t, sh))
            best = {sh.t, sh.n, uint32_t(s)};
    if (best.slot == kNoSlot) best = EngineHit{};
    return best;
}

bool scalarAny(const CompiledScene& scene, const Ray& ray, float tmax) {
    ShapeHit sh;
    for (const PlanePrimitive& p : scene.planes())
        if (intersect(p.shape, ray, 0.0f, tmax, sh)) return true;
    for (const Primitive& p : scene.primitives())
        if (intersectPrimitive(p, ray, 0.0f, tmax, sh)) return true;
    return false;
}

/// Rays as the kernel casts them: camera rays, shadow rays leaving surfaces toward (a point
/// of) the light, and rays from random points (inside spheres too) in random directions.
struct Rays {
    std::vector<float> ox, oy, oz, dx, dy, dz, tmax;
    void add(const Ray& r, float t) {
        ox.push_back(r.origin.x), oy.push_back(r.origin.y), oz.push_back(r.origin.z);
        dx.push_back(r.dir.x), dy.push_back(r.dir.y), dz.push_back(r.dir.z);
        tmax.push_back(t);
    }
    Ray at(std::size_t i) const {
        return Ray::make(Vec3(ox[i], oy[i], oz[i]), Vec3(dx[i], dy[i], dz[i]));
    }
    RayBatch batch(std::size_t first, std::size_t count) const {
        return {ox.data() + first, oy.data() + first, oz.data() + first,   dx.data() + first,
                dy.data() + first, dz.data() + first, tmax.data() + first, count};
    }
};

Rays someRays(const CompiledScene& scene, std::mt19937& rng, int n) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), u01(0.0f, 1.0f);
    Rays rays;
    const Vec3 light = scene.lights()[0].position;
    for (int k = 0; k < n; ++k) {
        const Ray view = scene.camera().generateRay(u01(rng) * float(scene.camera().width()),
                                                    u01(rng) * float(scene.camera().height()));
        switch (k % 3) {
            case 0:
                rays.add(view, kInfinity);
                break;
            case 1: {
                SurfaceHit hit;
                if (!scene.intersect(view, kInfinity, hit)) break;
                const Vec3 n = glm::dot(hit.n, view.dir) > 0.0f ? -hit.n : hit.n;
                const Vec3 p = view.at(hit.t) + n * scene.epsilon();
                const Vec3 q = light + 0.4f * Vec3(u(rng), u(rng), u(rng));
                const float dist = glm::length(q - p);
                rays.add(Ray::make(p, (q - p) / dist), dist - scene.epsilon());
                break;
            }
            default:
                rays.add(Ray::make(Vec3(3.0f * u(rng), 2.5f * u(rng), 3.0f * u(rng)),
                                   Vec3(u(rng), u(rng), u(rng))),
                         k % 2 ? kInfinity : 4.0f * u01(rng));
        }
    }
    return rays;
}

/// Both machine codes, over batches of every length from 1 to 19 (short last groups).
void expectScalarAnswers(const CompiledScene& scene, const FlatSet& flat, const Rays& rays,
                         int& hits, int& blocked) {
    const std::size_t n = rays.ox.size();
    for (FlatSet::Lanes lanes : {FlatSet::Lanes::Best, FlatSet::Lanes::Baseline}) {
        std::vector<float> t(n), nx(n), ny(n), nz(n);
        std::vector<uint32_t> slot(n);
        std::vector<uint8_t> occluded(n);
        for (std::size_t first = 0, len = 1; first < n; first += len, len = len % 19 + 1) {
            const std::size_t count = std::min(len, n - first);
            flat.closestHit(rays.batch(first, count),
                            {t.data() + first, nx.data() + first, ny.data() + first,
                             nz.data() + first, slot.data() + first},
                            lanes);
            flat.anyHit(rays.batch(first, count), occluded.data() + first, false, lanes);
        }
        for (std::size_t i = 0; i < n; ++i) {
            const EngineHit e = scalarClosest(scene, rays.at(i), rays.tmax[i]);
            ASSERT_EQ(slot[i], e.slot) << "ray " << i;
            ASSERT_EQ(std::bit_cast<uint32_t>(t[i]), std::bit_cast<uint32_t>(e.t)) << "ray " << i;
            ASSERT_EQ(std::bit_cast<uint32_t>(nx[i]), std::bit_cast<uint32_t>(e.n.x))
                << "ray " << i;
            ASSERT_EQ(std::bit_cast<uint32_t>(ny[i]), std::bit_cast<uint32_t>(e.n.y))
                << "ray " << i;
            ASSERT_EQ(std::bit_cast<uint32_t>(nz[i]), std::bit_cast<uint32_t>(e.n.z))
                << "ray " << i;
            ASSERT_EQ(occluded[i] != 0, scalarAny(scene, rays.at(i), rays.tmax[i])) << "ray " << i;
            hits += e.slot != kNoSlot && !(e.slot & kPlaneSlot);
            blocked += occluded[i] != 0;
        }
    }
}

TEST(FlatSet, AnswersAreTheScalarTestsBits_BothMachineCodes_EveryBatchLength) {
    std::mt19937 rng(7);
    int sphereHits = 0, blocked = 0, total = 0;
    for (int s = 0; s < 30; ++s) {
        SceneDocument doc = randomRoom(rng, 1 + s % int(FlatSet::kMaxShapes - 3), 0.0f);
        if (s % 3 == 0) addOthers(doc);
        const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
        ASSERT_TRUE(FlatSet::suits(scene.primitives()));
        const FlatSet flat(scene.planes(), &scene.primitives());
        const Rays rays = someRays(scene, rng, 1500);
        expectScalarAnswers(scene, flat, rays, sphereHits, blocked);
        total += 2 * int(rays.ox.size());
    }
    // Spheres win often and shadow answers go both ways, so the comparison means something.
    EXPECT_GT(sphereHits, total / 10);
    EXPECT_GT(blocked, total / 10);
    EXPECT_LT(blocked, total - total / 10);
}

TEST(FlatSet, RaysGrazingASphereGetTheScalarAnswer) {
    // Rays built tangent to a ball, a hair inside or outside it: where a lane's root choice or
    // a NaN would differ from the scalar test first.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int hits = 0, blocked = 0;
    for (int c = 0; c < 200; ++c) {
        SceneDocument doc;
        addMaterial(doc, "m", Color(0.8f), 0.9f);
        addPlane(doc, "floor", Vec3(0, -5, 0), Vec3(0, 1, 0), "m");
        const Vec3 centre(u(rng), u(rng), u(rng));
        const float radius = 0.3f + 0.5f * std::abs(u(rng));
        addSphere(doc, "ball", centre, radius, "m");
        Light l;
        l.name = "light";
        l.position = Vec3(0, 4, 0);
        doc.addLight(l);
        const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
        const FlatSet flat(scene.planes(), &scene.primitives());
        Rays rays;
        for (int k = 0; k < 40; ++k) {
            const Vec3 normal = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(0, 0, 1e-3f));
            const Vec3 tangent = glm::normalize(
                glm::cross(normal, Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-3f, 0, 0)));
            const Vec3 touch = centre + radius * (1.0f + 1e-4f * u(rng)) * normal;
            const Vec3 from = touch - (0.5f + 2.0f * std::abs(u(rng))) * tangent;
            rays.add(Ray::make(from, tangent), k % 2 ? kInfinity : 3.0f);
        }
        int unused = 0;
        expectScalarAnswers(scene, flat, rays, hits, unused);
        blocked += unused;
    }
    EXPECT_GT(hits, 200);
    EXPECT_GT(blocked, 200);
}

TEST(FlatSet, CoherentGroupsGrazingOneOfManySpheresGetTheScalarAnswer) {
    // Groups of nearly parallel rays from nearby origins, each tangent to one of several balls
    // a hair inside or outside it, ending just short of, at or past the touching point: the
    // box around such a group lies close to the ball it grazes and away from most others, so
    // the per-group cull drops spheres, and a margin too small would drop the grazed one.
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int hits = 0, blocked = 0;
    for (int c = 0; c < 120; ++c) {
        SceneDocument doc = randomRoom(rng, 4 + c % 9, 0.0f);
        const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
        const FlatSet flat(scene.planes(), &scene.primitives());
        std::vector<SphereShape> balls;
        for (const Primitive& p : scene.primitives())
            balls.push_back(std::get<SphereShape>(p.shape));
        Rays rays;
        for (int group = 0; group < 6; ++group) {
            const SphereShape& ball = balls[std::size_t(group) % balls.size()];
            Vec3 normal = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(0, 0, 1e-3f));
            Vec3 tangent = glm::normalize(
                glm::cross(normal, Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-3f, 0, 0)));
            float spread = 1e-3f;
            if (group % 2 == 0) {
                // Along an axis, side by side: the box is then as thin as the segments, and
                // touches the ball as closely as they do.
                const int axis = int(std::abs(u(rng)) * 2.99f),
                          off = (axis + 1 + group / 2 % 2) % 3;
                tangent = normal = Vec3(0.0f);
                tangent[axis] = u(rng) < 0.0f ? -1.0f : 1.0f;
                normal[off] = u(rng) < 0.0f ? -1.0f : 1.0f;
                spread = 0.0f;
            }
            const Vec3 side = glm::cross(normal, tangent);
            const float back = 0.3f + std::abs(u(rng));
            for (int k = 0; k < 8; ++k) {
                const float inside = 1.0f + 2e-5f * float(k - 4) + 1e-6f * u(rng);
                const Vec3 touch =
                    ball.center + ball.radius * inside * normal + spread * float(k) * side;
                const Vec3 dir = glm::normalize(tangent + 0.1f * spread * u(rng) * side);
                const float length =
                    k % 4 == 0 ? kInfinity : back * (1.0f + 0.5f * float(k % 4 - 2));
                rays.add(Ray::make(touch - back * dir, dir), length);
            }
        }
        int unused = 0;
        expectScalarAnswers(scene, flat, rays, hits, unused);
        blocked += unused;
    }
    EXPECT_GT(hits, 300);
    EXPECT_GT(blocked, 300);
}

TEST(FlatSet, ShadowGroupsEndingAHairFromAPlaneGetTheScalarAnswer) {
    // Groups of eight rays from one point (as a shading point's samples of a sphere light),
    // starting or ending a hair before, on or past one of the room's planes, so the box
    // around the group lies a hair from that plane: the per-group plane cull must drop only
    // planes every lane misses (a margin too small would drop the one they end at).
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), u01(0.0f, 1.0f);
    const float hairs[] = {-1e-4f, -1e-5f, -1e-6f, -1e-7f, 0.0f, 1e-7f, 1e-6f, 1e-5f, 1e-4f};
    int blocked = 0, open = 0;
    for (int c = 0; c < 60; ++c) {
        SceneDocument doc = randomRoom(rng, c % 6, 0.0f);
        const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
        const FlatSet flat(scene.planes(), &scene.primitives());
        Rays rays;
        for (int group = 0; group < 24; ++group) {
            const PlaneShape& plane =
                scene.planes()[std::size_t(group) % scene.planes().size()].shape;
            const Vec3 n = glm::normalize(plane.normal);
            const Vec3 o = Vec3(2.0f * u(rng), 1.5f * u(rng), 2.0f * u(rng));
            // A point on the plane near o, and the group's directions around o toward it.
            const Vec3 target =
                o - glm::dot(o - plane.point, n) * n + 0.5f * Vec3(u(rng), u(rng), u(rng));
            const bool fromPlane = group % 3 == 0;  // leaving the plane instead of reaching it
            for (int k = 0; k < 8; ++k) {
                const float hair = hairs[std::size_t(k + group) % std::size(hairs)];
                const Vec3 q = target + 0.05f * Vec3(u(rng), u(rng), u(rng));
                const Vec3 onPlane = q - glm::dot(q - plane.point, n) * n;
                if (fromPlane) {
                    const Vec3 from = onPlane + hair * (1.0f + glm::length(onPlane)) * n;
                    const Vec3 d = glm::normalize(o - from);
                    rays.add(Ray::make(from, d), glm::length(o - from));
                } else {
                    const float dist = glm::length(onPlane - o);
                    const Vec3 d = (onPlane - o) / dist;
                    rays.add(Ray::make(o, d), dist * (1.0f + hair));
                }
            }
        }
        for (FlatSet::Lanes lanes : {FlatSet::Lanes::Best, FlatSet::Lanes::Baseline}) {
            std::vector<uint8_t> occluded(rays.ox.size());
            flat.anyHit(rays.batch(0, rays.ox.size()), occluded.data(), false, lanes);
            for (std::size_t i = 0; i < rays.ox.size(); ++i) {
                ASSERT_EQ(occluded[i] != 0, scalarAny(scene, rays.at(i), rays.tmax[i]))
                    << "ray " << i;
                (occluded[i] ? blocked : open) += 1;
            }
        }
    }
    EXPECT_GT(blocked, 1000);
    EXPECT_GT(open, 1000);
}

TEST(FlatSet, OnlyAFewObjectsAndNoMeshAreFlat) {
    std::mt19937 rng(3);
    SceneDocument doc = randomRoom(rng, int(FlatSet::kMaxShapes) - 3, 0.0f);
    addOthers(doc);
    EXPECT_TRUE(
        dynamic_cast<const BvhEngine&>(CompiledScene(doc, nullptr, EngineKind::Builtin).engine())
            .testsFlat());
    addSphere(doc, "one more", Vec3(0.0f), 0.1f, "m");
    EXPECT_FALSE(
        dynamic_cast<const BvhEngine&>(CompiledScene(doc, nullptr, EngineKind::Builtin).engine())
            .testsFlat());
    SceneDocument withMesh = randomRoom(rng, 2, 0.0f);
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh->indices = {0, 1, 2};
    Object o;
    o.name = "triangle";
    o.material = "m";
    MeshGeometry g;
    g.file = "triangle.obj";
    g.data = mesh;
    o.geometry = g;
    withMesh.addObject(o);
    EXPECT_FALSE(FlatSet::suits(CompiledScene(withMesh).primitives()));
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
