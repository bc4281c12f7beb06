// Schlick's approximation between its end points, against the closed form written out here:
// F(cos) = R0 + (1 - R0) (1 - cos)^5 with R0 = ((1 - n) / (1 + n))^2. The end points alone
// (R0 at normal incidence, 1 at grazing) let a wrong exponent through.
#include <gtest/gtest.h>

#include <cmath>

#include "integrator/whitted.h"

namespace rs {
namespace {

TEST(SchlickClosedForm, BetweenNormalAndGrazing_IsR0PlusTheFifthPower) {
    for (const double ior : {1.33, 1.5, 2.4}) {
        const double r0 = ((1.0 - ior) / (1.0 + ior)) * ((1.0 - ior) / (1.0 + ior));
        for (const double cosine : {0.9, 0.7, 0.5, 0.3, 0.1}) {
            const double expected = r0 + (1.0 - r0) * std::pow(1.0 - cosine, 5.0);
            EXPECT_NEAR(schlick(float(cosine), float(ior)), expected, 1e-6)
                << "ior " << ior << ", cos " << cosine;
        }
    }
    // One value by hand: glass (R0 = 0.04) at 60 degrees, (1/2)^5 = 1/32.
    EXPECT_NEAR(schlick(0.5f, 1.5f), 0.04 + 0.96 / 32.0, 1e-6);
}

}  // namespace
}  // namespace rs
