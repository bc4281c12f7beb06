// Closed forms against the renderer: where a term of the illumination equation has an exact
// value (scene-format.md), the picture must show it. Different colours sit behind every branch,
// so a term given the wrong weight, or sent down the wrong branch, changes the value.
#include <gtest/gtest.h>

#include <cmath>

#include "integrator/renderer.h"
#include "integrator/whitted.h"
#include "test_scenes.h"

namespace rs {
namespace {

using test::addMaterial;
using test::addPlane;
using test::addPointLight;
using test::addSphere;

void expectColorNear(const Color& actual, const Color& expected, float tol,
                     const std::string& what) {
    EXPECT_NEAR(actual.x, expected.x, tol) << what;
    EXPECT_NEAR(actual.y, expected.y, tol) << what;
    EXPECT_NEAR(actual.z, expected.z, tol) << what;
}

Color traceOne(const SceneDocument& doc, const Ray& ray) {
    const CompiledScene scene(doc);
    const WhittedIntegrator integrator(scene);
    TraceCounters counters;
    return integrator.traceCamera(ray, 11u, counters);
}

// A unit sphere seen by an orthographic camera down -z, lit by one point light: every pixel
// that sees it is ambient * color * kd + I * C * kd * color * max(0, N.L) at the point its
// centre's ray hits, and every other pixel the background.
TEST(Analytic, LambertSphereUnderPointLight_EveryPixelIsTheClosedForm) {
    SceneDocument doc;
    doc.render.width = 96;
    doc.render.height = 64;
    doc.render.ambient = Color(0.05f, 0.1f, 0.15f);
    doc.render.background = Color(0.2f, 0.0f, 0.3f);
    doc.camera.projection = Projection::Orthographic;
    doc.camera.position = Vec3(0, 0, 5);
    doc.camera.target = Vec3(0, 0, 0);
    doc.camera.orthoHeight = 2.5f;
    const Color albedo(0.9f, 0.5f, 0.2f);
    const float kd = 0.8f;
    addMaterial(doc, "clay", albedo, kd);
    addSphere(doc, "ball", Vec3(0), 1.0f, "clay");
    Light light;
    light.name = "key";
    light.position = Vec3(3, 4, 6);
    light.color = Color(1.0f, 0.9f, 0.7f);
    light.intensity = 1.5f;
    doc.addLight(light);

    const CompiledScene scene(doc);
    const RenderResult render = renderImage(scene);
    int onSphere = 0, lit = 0;
    for (int y = 0; y < doc.render.height; ++y)
        for (int x = 0; x < doc.render.width; ++x) {
            const Ray ray = scene.camera().generateRay(float(x) + 0.5f, float(y) + 0.5f);
            // Ray-sphere by hand: origin o, direction d, |o + t d| = 1.
            const float b = glm::dot(ray.origin, ray.dir);
            const float disc = b * b - (glm::dot(ray.origin, ray.origin) - 1.0f);
            const Color got = render.image.at(x, y);
            const std::string where = "pixel " + std::to_string(x) + ", " + std::to_string(y);
            if (std::abs(disc) < 1e-3f) continue;  // a silhouette pixel: either answer is right
            if (disc < 0.0f) {
                expectColorNear(got, doc.render.background, 1e-6f, where);
                continue;
            }
            ++onSphere;
            const Vec3 p = ray.origin + (-b - std::sqrt(disc)) * ray.dir;
            const Vec3 n = glm::normalize(p);
            const float nl = std::max(0.0f, glm::dot(n, glm::normalize(light.position - p)));
            if (nl > 0.0f) ++lit;
            const Color expected = doc.render.ambient * albedo * kd +
                                   light.intensity * light.color * (kd * albedo * nl);
            expectColorNear(got, expected, 2e-4f, where);
        }
    EXPECT_GT(onSphere, 1500);  // the sphere covers about 2,000 of the 6,144 pixels
    EXPECT_GT(lit, onSphere / 3);
    EXPECT_LT(lit, onSphere);  // and its terminator is in view
}

/// A glass plane at y = 0 with a blue ceiling above (seen only by the reflected ray) and a red
/// floor below (seen only by the refracted ray); no lights, ambient 1, so each shows its
/// colour exactly. The camera ray comes from (0, 2, 0) at `degrees` from the normal.
struct SplitScene {
    SceneDocument doc;
    Color reflected{0.1f, 0.2f, 0.9f};
    Color refracted{0.9f, 0.15f, 0.05f};
    explicit SplitScene(float reflectivity, float transparency) {
        doc.render.ambient = Color(1.0f);
        doc.render.background = Color(0.0f, 1.0f, 0.0f);  // seen by neither branch
        doc.render.maxDepth = 2;
        doc.render.minWeight = 0.0f;
        addMaterial(doc, "ceiling", reflected, 1.0f);
        addMaterial(doc, "floor", refracted, 1.0f);
        addMaterial(doc, "glass", Color(1.0f), 0.0f, 0.0f, reflectivity, transparency, 1.5f);
        addPlane(doc, "ceiling", Vec3(0, 3, 0), Vec3(0, -1, 0), "ceiling");
        addPlane(doc, "glass", Vec3(0), Vec3(0, 1, 0), "glass");
        addPlane(doc, "floor", Vec3(0, -1, 0), Vec3(0, 1, 0), "floor");
    }
    Color trace(float degrees) const {
        const float a = glm::radians(degrees);
        return traceOne(doc, Ray::make(Vec3(0, 2, 0), Vec3(std::sin(a), -std::cos(a), 0)));
    }
};

TEST(Analytic, Schlick_SplitsReflectedAndRefractedColoursByF) {
    const SplitScene s(0.0f, 1.0f);
    for (float degrees : {0.0f, 30.0f, 60.0f, 80.0f}) {
        const float f = schlick(std::cos(glm::radians(degrees)), 1.5f);
        const Color expected = f * s.reflected + (1.0f - f) * s.refracted;
        expectColorNear(s.trace(degrees), expected, 1e-5f,
                        "at " + std::to_string(degrees) + " degrees, F = " + std::to_string(f));
    }
    // The numbers themselves, so a wrong R0 in schlick() cannot cancel out: R0 = 0.04.
    expectColorNear(s.trace(0.0f), 0.04f * s.reflected + 0.96f * s.refracted, 1e-5f, "R0");
}

TEST(Analytic, MirrorPlusGlass_WeightsEachBranchAsTheEquation) {
    // kr = 0.25, kt = 0.6, kd = 0: 0.25 * reflected + 0.6 * (F * reflected + (1 - F) * refracted).
    const SplitScene s(0.25f, 0.6f);
    const float f = schlick(std::cos(glm::radians(45.0f)), 1.5f);
    expectColorNear(s.trace(45.0f),
                    0.25f * s.reflected + 0.6f * (f * s.reflected + (1.0f - f) * s.refracted),
                    1e-5f, "kr 0.25, kt 0.6 at 45 degrees");
}

/// A camera inside a glass slab looks up at its top face at `degrees` from the normal: the
/// refracted ray leaves into the blue background, the reflected one falls on a red plane
/// inside the glass.
Color insideSlab(float degrees) {
    SceneDocument doc;
    doc.render.ambient = Color(1.0f);
    doc.render.background = Color(0.1f, 0.2f, 0.9f);
    doc.render.maxDepth = 1;
    doc.render.minWeight = 0.0f;
    addMaterial(doc, "glass", Color(1.0f), 0.0f, 0.0f, 0.0f, 1.0f, 1.5f);
    addMaterial(doc, "red", Color(0.9f, 0.15f, 0.05f), 1.0f);
    Object slab;
    slab.name = "slab";
    slab.material = "glass";
    slab.geometry = BoxGeometry{Vec3(-50, -1, -50), Vec3(50, 1, 50)};
    doc.addObject(slab);
    addPlane(doc, "red", Vec3(0, -0.5f, 0), Vec3(0, 1, 0), "red");
    const float a = glm::radians(degrees);
    return traceOne(doc, Ray::make(Vec3(0), Vec3(std::sin(a), std::cos(a), 0)));
}

TEST(Analytic, TotalInternalReflection_AtTheCriticalAngleSwitchesAllToReflection) {
    const Color sky(0.1f, 0.2f, 0.9f), red(0.9f, 0.15f, 0.05f);
    const float critical = glm::degrees(std::asin(1.0f / 1.5f));  // 41.81 degrees
    const float eps = 0.05f;
    // Just below: the ray leaves; F is Schlick's with the cosine on the inside.
    const float fBelow = schlick(std::cos(glm::radians(critical - eps)), 1.5f);
    expectColorNear(insideSlab(critical - eps), fBelow * red + (1.0f - fBelow) * sky, 1e-4f,
                    "critical - eps");
    EXPECT_LT(fBelow, 0.05f);
    // Just above: no refracted ray; the whole refractive part goes to the reflected one.
    expectColorNear(insideSlab(critical + eps), red, 1e-5f, "critical + eps");
    // Far from it on either side the same two answers.
    const float fSteep = schlick(std::cos(glm::radians(20.0f)), 1.5f);
    expectColorNear(insideSlab(20.0f), fSteep * red + (1.0f - fSteep) * sky, 1e-4f, "20 degrees");
    expectColorNear(insideSlab(60.0f), red, 1e-5f, "60 degrees");
}

// A sphere light of radius R at height H above the floor, a straight occluder edge at height h
// right below its centre: the floor sees the light partly hidden for |x| < R h / (H - h) (the
// edge's shadow of the light's disc), fully lit beyond on one side, fully dark on the other.
TEST(Analytic, SoftShadowPenumbra_HasTheGeometricWidth) {
    const float R = 0.5f, H = 4.0f, h = 2.0f;
    const float halfWidth = R * h / (H - h);  // 0.5
    auto floorScene = [&](bool occluder) {
        SceneDocument doc;
        doc.render.ambient = Color(0.0f);
        doc.render.shadowSamples = 1024;
        addMaterial(doc, "m", Color(1.0f), 1.0f);
        addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "m");
        Light l;
        l.name = "area";
        l.type = LightType::Sphere;
        l.position = Vec3(0, H, 0);
        l.radius = R;
        doc.addLight(l);
        if (occluder) {
            Object wall;  // covers x < 0 at height h
            wall.name = "wall";
            wall.material = "m";
            wall.geometry = BoxGeometry{Vec3(-20, h, -20), Vec3(0, h + 0.01f, 20)};
            doc.addObject(wall);
        }
        return doc;
    };
    const SceneDocument shadowed = floorScene(true), open = floorScene(false);
    auto visible = [&](float x) {
        const Ray down = Ray::make(Vec3(x, 1.0f, 0), Vec3(0, -1, 0));
        return traceOne(shadowed, down).x / traceOne(open, down).x;
    };
    // Outside the penumbra: all or nothing.
    EXPECT_NEAR(visible(-halfWidth - 0.05f), 0.0f, 1e-6f);
    EXPECT_NEAR(visible(halfWidth + 0.05f), 1.0f, 1e-6f);
    // Half the disc hidden right under the edge.
    EXPECT_NEAR(visible(0.0f), 0.5f, 0.03f);
    // The measured penumbra: from the last fully dark to the first fully lit point.
    float darkEnd = -1.0f, litStart = 1.0f;
    float previous = -1.0f;
    for (float x = -1.0f; x <= 1.0f; x += 0.01f) {
        const float v = visible(x);
        EXPECT_GE(v, previous - 0.03f) << "visibility falls at x = " << x;
        previous = v;
        if (v < 0.005f) darkEnd = x;
        if (v > 0.995f && litStart > x) litStart = x;
    }
    EXPECT_NEAR(litStart - darkEnd, 2.0f * halfWidth, 0.06f)
        << "penumbra from " << darkEnd << " to " << litStart;
    EXPECT_NEAR(0.5f * (litStart + darkEnd), 0.0f, 0.03f);
}

}  // namespace
}  // namespace rs
