// The shading rules of scene/shading_rules.h against the code that applies them: the
// snapshot's highlight cut-off is where the shading's highlight becomes negligible, and the
// shading leaves it out exactly below that cut-off; the ray tree's depth rules agree with
// each other. (The cost estimate against the rays really traced: cost_bound_test.cpp.)
#include "scene/shading_rules.h"

#include <gtest/gtest.h>

#include <cmath>

#include "integrator/light_sampling.h"
#include "snapshot/compiled_scene.h"
#include "test_scenes.h"

namespace rs {
namespace {

const float kSpeculars[] = {0.02f, 0.3f, 1.0f};
const float kShininesses[] = {1.0f, 8.0f, 50.0f, 1000.0f, 10000.0f};

TEST(ShadingRules, HighlightCutoff_IsWhereTheHighlightBecomesNegligible) {
    for (float specular : kSpeculars) {
        for (float shininess : kShininesses) {
            const float cutoff = highlightCutoff(specular, shininess);
            ASSERT_GT(cutoff, 0.0f);
            ASSERT_LE(cutoff, 1.0f);
            if (cutoff == 1.0f) continue;  // negligible everywhere
            // In double, so that the check does not share the float pow's rounding: the
            // highlight at the cut-off is the negligible one (to the float R.V's rounding).
            const double at = double(specular) * std::pow(double(cutoff), double(shininess));
            EXPECT_NEAR(at / double(kNegligibleHighlight), 1.0, 1e-6 * double(shininess) + 1e-5)
                << "specular " << specular << ", shininess " << shininess;
        }
    }
    EXPECT_EQ(highlightCutoff(0.0f, 50.0f), 0.0f);
    EXPECT_EQ(highlightCutoff(0.5f, 0.0f), 0.0f);
}

TEST(ShadingRules, Snapshot_TakesTheRulesCutoff) {
    SceneDocument doc;
    for (float specular : kSpeculars) {
        for (float shininess : kShininesses) {
            std::string name = "m";  // appended piecewise: GCC 12's false -Wrestrict
            name += std::to_string(doc.materials.size());
            test::addMaterial(doc, name, Color(0.5f), 0.5f, specular);
            doc.materials.back().shininess = shininess;
            test::addSphere(doc, name, Vec3(0.0f, 0.0f, -3.0f), 1.0f, name);
        }
    }
    const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
    int checked = 0;
    for (const CompiledMaterial& m : scene.materials()) {
        if (!(m.specular > 0.0f)) continue;  // the built-in default
        EXPECT_EQ(m.specularCutoff, highlightCutoff(m.specular, m.shininess));
        ++checked;
    }
    EXPECT_EQ(checked, int(std::size(kSpeculars) * std::size(kShininesses)));
}

/// The highlight that shading adds for one unshadowed sample straight along the normal, seen
/// from a direction whose R.V is `rv` (no diffuse part, a white light of power 1).
float shadedHighlight(const CompiledMaterial& m, float rv) {
    CompiledMaterial highlightOnly = m;
    highlightOnly.diffuse = 0.0f;
    CompiledLight light{};
    light.power = Color(1.0f);
    const Vec3 n(0.0f, 0.0f, 1.0f);
    // R = 2 (n.l) n - l = n for l = n, so R.V is the viewer direction's z, exactly.
    const LightSample s{n, 1.0f, 1.0f};
    return sampleShare(light, surfaceTerms(highlightOnly), n, Vec3(0.0f, 0.0f, rv), s, 1.0f).x;
}

TEST(ShadingRules, Shading_LeavesTheHighlightOutExactlyBelowTheCutoff) {
    for (float specular : kSpeculars) {
        for (float shininess : kShininesses) {
            CompiledMaterial m{};
            m.color = Color(1.0f);
            m.specular = specular;
            m.shininess = shininess;
            m.specularCutoff = highlightCutoff(specular, shininess);
            if (m.specularCutoff >= 1.0f) continue;
            const float below = std::nextafter(m.specularCutoff, 0.0f);
            const float above = std::nextafter(m.specularCutoff, 1.0f);
            EXPECT_EQ(shadedHighlight(m, below), 0.0f)
                << "specular " << specular << ", shininess " << shininess;
            const float kept = shadedHighlight(m, above);
            EXPECT_GT(kept, 0.0f) << "specular " << specular << ", shininess " << shininess;
            // What is left out is no more than what the rule calls negligible.
            EXPECT_LT(kept, 1.01f * kNegligibleHighlight);
        }
    }
}

TEST(ShadingRules, TreeLevels_AreTheDepthsSpawnsChildrenReaches) {
    for (int maxDepth = 0; maxDepth <= 12; ++maxDepth) {
        int levels = 1;  // the camera ray's
        while (spawnsChildren(levels - 1, maxDepth)) ++levels;
        EXPECT_EQ(levels, treeLevels(maxDepth)) << "max_depth " << maxDepth;
    }
}

TEST(ShadingRules, ShadowRays_NoneWithoutSamples_OneAtACentre_TheSamplesOverADisk) {
    EXPECT_EQ(shadowRaysTowardLight(false, 0), 0);
    EXPECT_EQ(shadowRaysTowardLight(true, 0), 0);
    EXPECT_EQ(shadowRaysTowardLight(false, 16), 1);
    EXPECT_EQ(shadowRaysTowardLight(true, 16), 16);
}

}  // namespace
}  // namespace rs
