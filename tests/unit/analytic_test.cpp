// Closed forms against the renderer: where a term of the illumination equation has an exact
// value (scenes/FORMAT.md), the picture must show it. Different colours sit behind every branch,
// so a term given the wrong weight, or sent down the wrong branch, changes the value.
#include <gtest/gtest.h>

#include <cmath>

#include "closed_form_support.h"
#include "integrator/renderer.h"
#include "integrator/whitted.h"
#include "test_scenes.h"

namespace rs {
namespace {

using test::addMaterial;
using test::addPlane;
using test::addPointLight;
using test::addSphere;
using test::expectColorNear;
using test::traceOne;

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

/// Schlick's Fresnel reflectance written out here, never through the product's schlick():
/// R0 = ((n1 - n2) / (n1 + n2))^2 and F = R0 + (1 - R0) (1 - cos)^5, with `cosIncident` the
/// cosine on the side the ray comes from (scenes/FORMAT.md: "evaluated with the cosine on the
/// incident side", the ratio inverted inside a glass body).
double fresnelSchlick(double cosIncident, double n1, double n2) {
    const double r0 = ((n1 - n2) / (n1 + n2)) * ((n1 - n2) / (n1 + n2));
    return r0 + (1.0 - r0) * std::pow(1.0 - cosIncident, 5.0);
}

double cosDegrees(double degrees) {
    return std::cos(degrees * 3.14159265358979323846 / 180.0);
}

// The approximation itself between its end points, where a wrong exponent shows: at 60
// degrees (1 - cos)^5 = 1/32 but (1 - cos)^4 = 1/16, F = 0.07 against 0.1.
TEST(Analytic, Schlick_BetweenItsEndPoints_IsTheFifthPowerClosedForm) {
    EXPECT_NEAR(fresnelSchlick(0.5, 1.0, 1.5), 0.04 + 0.96 / 32.0, 1e-12);  // the helper itself
    for (float ior : {1.33f, 1.5f, 2.4f})
        for (double degrees : {0.0, 15.0, 30.0, 45.0, 60.0, 70.0, 80.0, 89.0}) {
            const double c = cosDegrees(degrees);
            // From air into the body and, with the ratio inverted, from inside it out.
            EXPECT_NEAR(schlick(float(c), ior), fresnelSchlick(c, 1.0, ior), 2e-6)
                << "ior " << ior << " at " << degrees << " degrees";
            EXPECT_NEAR(fresnelSchlick(c, ior, 1.0), fresnelSchlick(c, 1.0, ior), 1e-12);
        }
}

TEST(Analytic, Schlick_SplitsReflectedAndRefractedColoursByF) {
    const SplitScene s(0.0f, 1.0f);
    for (double degrees : {0.0, 15.0, 30.0, 45.0, 60.0, 70.0, 80.0}) {
        const float f = float(fresnelSchlick(cosDegrees(degrees), 1.0, 1.5));
        const Color expected = f * s.reflected + (1.0f - f) * s.refracted;
        expectColorNear(s.trace(float(degrees)), expected, 1e-5f,
                        "at " + std::to_string(degrees) + " degrees, F = " + std::to_string(f));
    }
    // The numbers themselves: R0 = 0.04 at normal incidence, 0.04 + 0.96 / 32 = 0.07 at 60.
    expectColorNear(s.trace(0.0f), 0.04f * s.reflected + 0.96f * s.refracted, 1e-5f, "R0");
    expectColorNear(s.trace(60.0f), 0.07f * s.reflected + 0.93f * s.refracted, 1e-5f, "60 degrees");
}

TEST(Analytic, MirrorPlusGlass_WeightsEachBranchAsTheEquation) {
    // kr = 0.25, kt = 0.6, kd = 0: 0.25 * reflected + 0.6 * (F * reflected + (1 - F) * refracted).
    const SplitScene s(0.25f, 0.6f);
    for (double degrees : {45.0, 65.0}) {
        const float f = float(fresnelSchlick(cosDegrees(degrees), 1.0, 1.5));
        expectColorNear(s.trace(float(degrees)),
                        0.25f * s.reflected + 0.6f * (f * s.reflected + (1.0f - f) * s.refracted),
                        1e-5f, "kr 0.25, kt 0.6 at " + std::to_string(degrees) + " degrees");
    }
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
    // Leaving glass (n1 = 1.5) into air (n2 = 1): the ratio inverted, the cosine inside.
    auto leaving = [&](double degrees) {
        const float f = float(fresnelSchlick(cosDegrees(degrees), 1.5, 1.0));
        return f * red + (1.0f - f) * sky;
    };
    const double critical = std::asin(1.0 / 1.5) * 180.0 / 3.14159265358979323846;  // 41.81
    const double eps = 0.05;
    // Below it the ray leaves, F of the inside cosine: at 0 degrees R0 = 0.04.
    expectColorNear(insideSlab(0.0f), 0.04f * red + 0.96f * sky, 1e-4f, "0 degrees");
    for (double degrees : {10.0, 20.0, 30.0, 35.0, 40.0, critical - eps})
        expectColorNear(insideSlab(float(degrees)), leaving(degrees), 1e-4f,
                        std::to_string(degrees) + " degrees inside");
    EXPECT_LT(fresnelSchlick(cosDegrees(critical - eps), 1.5, 1.0), 0.05);
    // Just above: no refracted ray; the whole refractive part goes to the reflected one.
    for (double degrees : {critical + eps, 45.0, 60.0, 80.0})
        expectColorNear(insideSlab(float(degrees)), red, 1e-5f,
                        std::to_string(degrees) + " degrees inside, past the critical angle");
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
