// What the closed-form tests share: one camera ray through the renderer, and a colour
// compared channel by channel.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "integrator/whitted.h"
#include "scene/document.h"

namespace rs::test {

/// The colour a full-quality trace of `ray` gives in `doc`.
inline Color traceOne(const SceneDocument& doc, const Ray& ray, uint32_t seed = 11u) {
    const CompiledScene scene(doc);
    const WhittedIntegrator integrator(scene);
    TraceCounters counters;
    return integrator.traceCamera(ray, seed, counters);
}

inline void expectColorNear(const Color& actual, const Color& expected, float tol,
                            const std::string& what) {
    EXPECT_NEAR(actual.x, expected.x, tol) << what;
    EXPECT_NEAR(actual.y, expected.y, tol) << what;
    EXPECT_NEAR(actual.z, expected.z, tol) << what;
}

}  // namespace rs::test
