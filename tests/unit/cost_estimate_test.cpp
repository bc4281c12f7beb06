// The render cost budget: the estimate's factors, the glass tree bound and the budget message.
// Whether the estimate bounds the rays a render really traces: cost_bound_test.cpp.
#include "integrator/cost_estimate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "io/scene_io.h"
#include "test_scenes.h"

namespace rs {
namespace {

SceneDocument room() {
    SceneLoadResult r = loadScene(RAYSTUDIO_SCENES_DIR "/reference-room.scene.json");
    EXPECT_TRUE(r.ok()) << r.errorText();
    return r.document;
}

TEST(CostEstimate, ReferenceRoom_IsWithinTheDefaultBudget) {
    const CostEstimate e = estimateCost(room());
    EXPECT_EQ(e.pixels, 1280.0 * 720.0);
    EXPECT_EQ(e.samplesPerPixel, 1.0);
    EXPECT_EQ(e.shadowRaysPerHit, 1.0);  // One point light.
    // Glass at depth 3: a full binary tree (15 rays) is below the min_weight bound.
    EXPECT_EQ(e.treeRays, 15.0);
    EXPECT_EQ(e.rays, 1280.0 * 720.0 * 15.0 * 2.0);
    EXPECT_TRUE(budgetExceeded(e).empty());
}

TEST(CostEstimate, GlassTree_GrowsLikeMinOfPowerOfTwoAndDepthOverMinWeight) {
    SceneDocument doc = room();
    doc.render.maxDepth = 44;
    doc.render.minWeight = 1.0f / 255.0f;
    EXPECT_NEAR(estimateCost(doc).treeRays, 1.0 + 44.0 * 255.0, 1e-3);
    doc.render.minWeight = 0.0f;  // No bail-out: the whole tree.
    EXPECT_EQ(estimateCost(doc).treeRays, std::exp2(45.0) - 1.0);
    doc.render.maxDepth = kMaxDepthLimit;
    EXPECT_TRUE(std::isfinite(estimateCost(doc).rays));
    EXPECT_FALSE(budgetExceeded(estimateCost(doc)).empty());
}

TEST(CostEstimate, MirrorsAloneGiveAChain_DiffuseOneRay) {
    SceneDocument doc;
    test::addMaterial(doc, "mirror", Color(0.9f), 0.0f, 0.0f, 0.9f);
    test::addSphere(doc, "ball", Vec3(0, 0, -3), 1.0f, "mirror");
    doc.render.maxDepth = 5;
    EXPECT_EQ(estimateCost(doc).treeRays, 6.0);
    doc.objects[0].material.clear();
    EXPECT_EQ(estimateCost(doc).treeRays, 1.0);
}

TEST(CostEstimate, SphereLightsCountTheirShadowSamples_PointLightsOne) {
    SceneDocument doc;
    test::addPointLight(doc, "key", Vec3(0, 5, 0));
    Light soft;
    soft.type = LightType::Sphere;
    doc.addLight(soft);
    doc.render.shadowSamples = 16;
    EXPECT_EQ(estimateCost(doc).shadowRaysPerHit, 17.0);
    doc.render.shadowSamples = 0;
    EXPECT_EQ(estimateCost(doc).shadowRaysPerHit, 0.0);
}

TEST(CostEstimate, OverBudget_MessageNamesTheBudget) {
    SceneDocument doc = room();
    doc.render.supersampling = 4096;
    const std::string message = budgetExceeded(estimateCost(doc));
    EXPECT_NE(message.find("ray budget of 1e+11 rays"), std::string::npos) << message;
    EXPECT_NE(message.find("4096 samples"), std::string::npos) << message;
    CostBudget tight;
    tight.bytes = 1024;
    EXPECT_NE(budgetExceeded(estimateCost(room()), tight).find("memory budget"), std::string::npos);
}

}  // namespace
}  // namespace rs
