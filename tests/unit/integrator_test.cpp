// The Whitted integrator against the illumination equation of scenes/FORMAT.md, term by term.
#include <gtest/gtest.h>

#include "integrator/whitted.h"
#include "test_scenes.h"

namespace rs {
namespace {

using test::addMaterial;
using test::addPlane;
using test::addPointLight;
using test::addSphere;

void expectColorNear(const Color& a, const Color& b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

/// Traces one ray straight down onto a floor at y = 0 from above.
Color traceDown(const SceneDocument& doc, Vec3 from = Vec3(0, 2, 0), int* shadowRays = nullptr) {
    const CompiledScene scene(doc);
    const WhittedIntegrator integrator(scene);
    TraceCounters counters;
    Color c = integrator.traceCamera(Ray::make(from, Vec3(0, -1, 0)), 7u, counters);
    if (shadowRays) *shadowRays = int(counters.shadowRays);
    return c;
}

SceneDocument floorScene(const Material& floor) {
    SceneDocument doc;
    doc.materials.push_back(floor);
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), floor.name);
    return doc;
}

// Schlick's approximation against its closed form, at normal incidence (R0), near grazing
// (89 degrees) and between, where a wrong exponent shows: analytic_test.cpp.

TEST(Refraction, SnellsLaw_HoldsForTheRefractedDirection) {
    const Vec3 n(0, 1, 0);
    const Vec3 d = glm::normalize(Vec3(1, -1, 0));  // 45 degrees incidence.
    Vec3 t;
    ASSERT_TRUE(refractDir(d, n, 1.0f / 1.5f, t));
    const float sinI = std::sqrt(1.0f - glm::dot(d, n) * glm::dot(d, n));
    const float sinT = std::sqrt(1.0f - glm::dot(t, n) * glm::dot(t, n));
    EXPECT_NEAR(sinI / sinT, 1.5f, 1e-5f);
    EXPECT_LT(t.y, 0.0f);
}

TEST(Refraction, BeyondCriticalAngle_IsTotalInternalReflection) {
    const Vec3 n(0, 1, 0);  // Facing the incident side, inside glass going out: eta = 1.5.
    const float critical = std::asin(1.0f / 1.5f);
    const float below = critical - 0.01f, above = critical + 0.01f;
    Vec3 t;
    EXPECT_TRUE(refractDir(Vec3(std::sin(below), -std::cos(below), 0), n, 1.5f, t));
    EXPECT_FALSE(refractDir(Vec3(std::sin(above), -std::cos(above), 0), n, 1.5f, t));
}

TEST(Whitted, NoLights_DiffuseSurfaceShowsAmbientTimesColorTimesKd) {
    Material m;
    m.name = "m";
    m.color = Color(0.5f, 0.25f, 1.0f);
    m.diffuse = 0.8f;
    SceneDocument doc = floorScene(m);
    doc.render.ambient = Color(0.1f, 0.2f, 0.3f);
    expectColorNear(traceDown(doc), doc.render.ambient * m.color * m.diffuse);
}

TEST(Whitted, PointLight_AddsLambertTermWithoutFalloff) {
    Material m;
    m.name = "m";
    m.color = Color(0.5f, 0.6f, 0.7f);
    m.diffuse = 0.9f;
    SceneDocument doc = floorScene(m);
    Light l;
    l.name = "l";
    l.position = Vec3(3, 4, 0);  // Distance 5: N.L = 0.8; no fall-off by the format.
    l.color = Color(1.0f, 0.5f, 0.25f);
    l.intensity = 2.0f;
    doc.addLight(l);
    const Color expected = doc.render.ambient * m.color * m.diffuse +
                           l.intensity * l.color * (m.diffuse * m.color * 0.8f);
    expectColorNear(traceDown(doc), expected);
}

TEST(Whitted, PhongHighlight_UsesReflectedLightDotViewToTheShininess) {
    Material m;
    m.name = "m";
    m.diffuse = 0.0f;
    m.specular = 0.5f;
    m.shininess = 10.0f;
    SceneDocument doc = floorScene(m);
    doc.render.ambient = Color(0.0f);
    addPointLight(doc, "l", Vec3(1, 1, 0));  // L at 45 degrees; R.V = cos 45.
    const float rv = std::sqrt(0.5f);
    expectColorNear(traceDown(doc), Color(0.5f * std::pow(rv, 10.0f)));
}

TEST(Whitted, OccludedPoint_GetsOnlyAmbient) {
    Material m;
    m.name = "m";
    SceneDocument doc = floorScene(m);
    addPointLight(doc, "l", Vec3(0, 5, 0));
    addSphere(doc, "blocker", Vec3(0, 3, 0), 0.5f, "m");
    // Trace from between floor and blocker so the camera ray does not hit the blocker.
    expectColorNear(traceDown(doc, Vec3(0, 1, 0)), doc.render.ambient * m.color * m.diffuse);
}

TEST(Whitted, ZeroShadowSamples_TracesNoShadowRaysAndIgnoresOccluders) {
    Material m;
    m.name = "m";
    SceneDocument doc = floorScene(m);
    doc.render.shadowSamples = 0;
    addPointLight(doc, "l", Vec3(0, 5, 0));
    addSphere(doc, "blocker", Vec3(0, 3, 0), 0.5f, "m");
    int shadowRays = -1;
    const Color c = traceDown(doc, Vec3(0, 1, 0), &shadowRays);
    EXPECT_EQ(shadowRays, 0);
    expectColorNear(c, doc.render.ambient * m.color + m.color);
}

TEST(Whitted, SphereLightHalfBlocked_GivesPenumbraBetweenLitAndShadowed) {
    Material m;
    m.name = "m";
    SceneDocument doc = floorScene(m);
    doc.render.ambient = Color(0.0f);
    doc.render.shadowSamples = 64;
    Light l;
    l.name = "area";
    l.type = LightType::Sphere;
    l.position = Vec3(0, 4, 0);
    l.radius = 1.0f;
    doc.addLight(l);
    // A wall edge right under the light's centre hides about half of its disk.
    Object wall;
    wall.name = "wall";
    wall.material = "m";
    wall.geometry = BoxGeometry{Vec3(0, 2, -5), Vec3(5, 2.1f, 5)};
    doc.addObject(wall);
    const float lit = traceDown(doc, Vec3(0.0f, 1.0f, 0.0f)).x;
    EXPECT_GT(lit, 0.3f * m.color.x);
    EXPECT_LT(lit, 0.7f * m.color.x);
}

TEST(Whitted, MirrorAtMaxDepthZero_ShowsOnlyItsLocalShare) {
    Material mirror;
    mirror.name = "mirror";
    mirror.reflectivity = 0.9f;
    SceneDocument doc = floorScene(mirror);
    doc.render.background = Color(1.0f);
    doc.render.maxDepth = 0;
    const Color local = doc.render.ambient * mirror.color * mirror.diffuse;
    expectColorNear(traceDown(doc), 0.1f * local);
    doc.render.maxDepth = 1;  // Now the reflected ray sees the white background.
    expectColorNear(traceDown(doc), 0.1f * local + Color(0.9f));
}

// Glass's Fresnel split, with different colours behind the two branches, and total internal
// reflection at the critical angle: analytic_test.cpp.

TEST(Whitted, InsideGlassBeyondCriticalAngle_SendsAllEnergyToReflection) {
    // A camera inside a glass ball: a ray meeting the surface beyond the critical angle is
    // totally reflected and, at depth 1, ends black; a steeper ray leaves and sees the sky.
    Material glass;
    glass.name = "glass";
    glass.diffuse = 0.0f;
    glass.transparency = 1.0f;
    SceneDocument doc;
    doc.materials.push_back(glass);
    addSphere(doc, "ball", Vec3(0), 1.0f, "glass");
    doc.render.background = Color(1.0f);
    doc.render.maxDepth = 1;
    const CompiledScene scene(doc);
    const WhittedIntegrator integrator(scene);
    TraceCounters counters;
    // From (0, 0.9, 0) along +x the ray meets the sphere where cos(incidence) = 0.436, i.e.
    // 64 degrees, beyond the critical 41.8 degrees for ior 1.5.
    const Color tir =
        integrator.traceCamera(Ray::make(Vec3(0, 0.9f, 0), Vec3(1, 0, 0)), 1u, counters);
    expectColorNear(tir, Color(0.0f));
    // From the centre the ray leaves at normal incidence: transmitted share 1 - R0.
    const Color out = integrator.traceCamera(Ray::make(Vec3(0), Vec3(1, 0, 0)), 1u, counters);
    expectColorNear(out, Color(1.0f - 0.04f));
}

TEST(Whitted, MissedRay_ReturnsBackground) {
    SceneDocument doc;
    doc.render.background = Color(0.1f, 0.2f, 0.3f);
    const CompiledScene scene(doc);
    const WhittedIntegrator integrator(scene);
    TraceCounters counters;
    expectColorNear(integrator.traceCamera(Ray::make(Vec3(0), Vec3(0, 0, -1)), 1u, counters),
                    doc.render.background);
    EXPECT_EQ(counters.rays, 1u);
}

}  // namespace
}  // namespace rs
