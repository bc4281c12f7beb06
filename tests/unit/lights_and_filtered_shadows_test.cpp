// Sun and spot lights and shadows through glass against closed forms (scenes/FORMAT.md
// "lights" and "Shadows"): each value below is worked out here from the format's equations.
#include <gtest/gtest.h>

#include <cmath>

#include "closed_form_support.h"
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

constexpr float kPi = 3.14159265358979f;

/// A grey floor at y = 0 (diffuse 1, colour c) and the ambient term, no light yet.
SceneDocument floorScene(const Color& c, const Color& ambient) {
    SceneDocument doc;
    doc.render.ambient = ambient;
    addMaterial(doc, "floor", c, 1.0f);
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "floor");
    return doc;
}

/// The floor's colour at (x, 0, z), seen straight down from just above it (below the balls).
Color floorAt(const SceneDocument& doc, float x, float z) {
    return traceOne(doc, Ray::make(Vec3(x, 0.1f, z), Vec3(0, -1, 0)));
}

TEST(SunLight, LightsEveryPointAlike_AsParallelLightOfItsDirection) {
    const Color c(0.8f, 0.6f, 0.4f), ambient(0.05f, 0.05f, 0.1f);
    SceneDocument doc = floorScene(c, ambient);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = Vec3(1.0f, -2.0f, 0.5f);
    sun.color = Color(1.0f, 0.9f, 0.8f);
    sun.intensity = 1.5f;
    doc.addLight(sun);
    // n . l with l the unit vector against the direction of travel.
    const float nl = 2.0f / std::sqrt(1.0f + 4.0f + 0.25f);
    const Color expected = ambient * c + sun.intensity * sun.color * c * nl;
    for (float x : {-500.0f, 0.0f, 3.0f, 700.0f})
        expectColorNear(floorAt(doc, x, -x * 0.5f), expected, 2e-5f, "x = " + std::to_string(x));
}

TEST(SunLight, ABlockerCastsItsShadowAlongTheDirection) {
    const Color c(0.7f), ambient(0.1f);
    SceneDocument doc = floorScene(c, ambient);
    addMaterial(doc, "stone", Color(0.5f), 1.0f);
    addSphere(doc, "blocker", Vec3(0, 2, 0), 0.5f, "stone");
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = Vec3(1.0f, -1.0f, 0.0f);  // 45 degrees: the shadow lands at x = +2.
    doc.addLight(sun);
    const Color lit = ambient * c + c * (1.0f / std::sqrt(2.0f));
    expectColorNear(floorAt(doc, 2.0f, 0.0f), ambient * c, 1e-6f, "in the shadow");
    expectColorNear(floorAt(doc, 0.0f, 0.0f), lit, 2e-5f, "under the blocker, lit sideways");
    expectColorNear(floorAt(doc, -2.0f, 0.0f), lit, 2e-5f, "away from it");
}

/// POV-Ray's spotlight fall-off (tightness 0), written out here independently.
float spotFalloff(float angleDeg, float radiusDeg, float falloffDeg) {
    const float c = std::cos(angleDeg * kPi / 180.0f);
    const float hi = std::cos(radiusDeg * kPi / 180.0f), lo = std::cos(falloffDeg * kPi / 180.0f);
    if (c >= hi) return 1.0f;
    if (c <= lo) return 0.0f;
    const float t = (c - lo) / (hi - lo);
    return t * t * (3.0f - 2.0f * t);
}

TEST(SpotLight, FullInsideItsRadius_NothingBeyondItsFalloff_TheCubicBetween) {
    const Color c(0.9f), ambient(0.05f);
    SceneDocument doc = floorScene(c, ambient);
    Light spot;
    spot.type = LightType::Spot;
    spot.position = Vec3(0, 4, 0);
    spot.target = Vec3(0, 0, 0);
    spot.coneRadius = 20.0f;
    spot.coneFalloff = 40.0f;
    spot.intensity = 2.0f;
    doc.addLight(spot);
    for (float angle : {0.0f, 10.0f, 19.0f, 25.0f, 30.0f, 35.0f, 39.0f, 45.0f, 60.0f}) {
        const float x = 4.0f * std::tan(angle * kPi / 180.0f);
        const float nl = std::cos(angle * kPi / 180.0f);  // the light is straight above the axis
        const Color expected =
            ambient * c + spot.intensity * c * nl * spotFalloff(angle, 20.0f, 40.0f);
        expectColorNear(floorAt(doc, x, 0.0f), expected, 3e-5f, "angle " + std::to_string(angle));
    }
    // Aimed elsewhere, the same light leaves this point dark.
    doc.lights[0].target = Vec3(10, 0, 0);
    expectColorNear(floorAt(doc, 0.0f, 0.0f), ambient * c, 1e-6f, "aimed away");
}

TEST(FilteredShadows, AGlassBallTintsItsShadowByTransparencyTimesColourPerCrossing) {
    const Color c(0.8f), ambient(0.05f);
    SceneDocument doc = floorScene(c, ambient);
    const Color glass(0.9f, 0.5f, 0.2f);
    const float transparency = 0.8f;
    addMaterial(doc, "glass", glass, 0.0f, 0.0f, 0.1f, transparency, 1.5f);
    addSphere(doc, "ball", Vec3(0, 2, 0), 0.5f, "glass");
    addPointLight(doc, "key", Vec3(0, 6, 0));
    // Straight below the ball the shadow ray crosses its surface twice.
    const Color kept = (transparency * glass) * (transparency * glass);
    expectColorNear(floorAt(doc, 0.0f, 0.0f), ambient * c + c * kept, 2e-5f, "under the ball");
    // Beside the ball, lit as if it were not there.
    const Vec3 p(3.0f, 0.0f, 0.0f), l = glm::normalize(Vec3(0, 6, 0) - p);
    expectColorNear(floorAt(doc, p.x, p.z), ambient * c + c * l.y, 2e-5f, "beside it");
    // Version 1's shadows on request: the glass blocks all of it.
    doc.render.opaqueShadows = true;
    expectColorNear(floorAt(doc, 0.0f, 0.0f), ambient * c, 1e-6f, "opaque_shadows");
}

TEST(FilteredShadows, AnOpaqueSurfaceBehindTheGlassStillBlocks) {
    const Color c(0.8f), ambient(0.05f);
    SceneDocument doc = floorScene(c, ambient);
    addMaterial(doc, "glass", Color(1.0f), 0.0f, 0.0f, 0.0f, 1.0f, 1.5f);
    addMaterial(doc, "stone", Color(0.5f), 1.0f);
    addSphere(doc, "glass ball", Vec3(0, 2, 0), 0.5f, "glass");
    addSphere(doc, "stone ball", Vec3(0, 4, 0), 0.5f, "stone");
    addPointLight(doc, "key", Vec3(0, 6, 0));
    expectColorNear(floorAt(doc, 0.0f, 0.0f), ambient * c, 1e-6f, "glass then stone");
    // Clear glass alone passes all of it.
    doc.objects.pop_back();
    expectColorNear(floorAt(doc, 0.0f, 0.0f), ambient * c + c, 2e-5f, "clear glass alone");
}

}  // namespace
}  // namespace rs
