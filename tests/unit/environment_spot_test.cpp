// Where rays look in a latitude-longitude environment: the map, and many at once as one alone.
#include "texture/environment_spot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "core/math.h"

namespace rs {
namespace {

EnvironmentSpot spotOf(const Vec3& d, float rotationDegrees = 0.0f, float cone = 0.0f) {
    EnvironmentSpot spot;
    environmentSpots(1, {&d.x, &d.y, &d.z}, rotationDegrees, cone, &spot);
    return spot;
}

TEST(EnvironmentSpot, FollowsTheLatitudeLongitudeMap) {
    // u = phi / (2 pi) from +X toward +Z, the top row straight up (scenes/FORMAT.md).
    EXPECT_NEAR(spotOf(Vec3(1, 0, 0)).s, 0.0f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(0, 0, 1)).s, 0.25f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(-1, 0, 0)).s, 0.5f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(0, 0, -1)).s, 0.75f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(1, 0, 0)).t, 0.5f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(0, 1, 0)).t, 0.0f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(0, -1, 0)).t, 1.0f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(1, 1, 0)).t, 0.25f, 1e-6f);
    // Length does not matter; a zero or NaN direction looks straight up.
    EXPECT_NEAR(spotOf(Vec3(0, 0, 7)).s, 0.25f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(0.0f)).t, 0.0f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(NAN, 0, 0)).t, 0.0f, 1e-6f);
    // Rotation adds a turn's share to s, wrapped into [0, 1).
    EXPECT_NEAR(spotOf(Vec3(0, 0, 1), 90.0f).s, 0.5f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(0, 0, -1), 90.0f).s, 0.0f, 1e-6f);
    EXPECT_NEAR(spotOf(Vec3(0, 0, 1), -450.0f).s, 0.0f, 1e-6f);
    // A cone of angle a spans a / pi in t and a / (2 pi cos(latitude)) in s, at most a turn.
    const EnvironmentSpot equator = spotOf(Vec3(1, 0, 0), 0.0f, 0.01f);
    EXPECT_NEAR(equator.dt, 0.01f / kPi, 1e-9f);
    EXPECT_NEAR(equator.ds, 0.01f / kTwoPi, 1e-9f);
    EXPECT_NEAR(spotOf(Vec3(1, std::sqrt(3.0f), 0), 0.0f, 0.01f).ds, 0.02f / kTwoPi, 1e-8f);
    EXPECT_EQ(spotOf(Vec3(0, 1, 0), 0.0f, 0.01f).ds, 1.0f);
    EXPECT_EQ(spotOf(Vec3(1, 0, 0), 0.0f, -1.0f).ds, 0.0f);
}

TEST(EnvironmentSpot, ManyDirectionsAtOnce_GiveEachTheBitsItGetsAlone) {
    // The renderer looks a level's escaped rays up four at a time; the designer's strip and
    // single rays one at a time: the same direction must land on the same texel weights.
    std::mt19937 rng(61);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const float specials[] = {0.0f,   -0.0f, 1e-39f, -1e-39f, 1.0f,     -1.0f,
                              1e-20f, 1e20f, 0.5f,   -0.5f,   INFINITY, NAN};
    const auto value = [&]() -> float {
        switch (rng() % 4) {
            case 0:
                return specials[rng() % std::size(specials)];
            case 1:
                return unit(rng);
            case 2:
                return std::ldexp(unit(rng), int(rng() % 80) - 40);
            default:
                return float(int(rng() % 3) - 1);
        }
    };
    for (std::size_t count : {1u, 2u, 3u, 4u, 5u, 7u, 9u, 4099u}) {
        const float rotation = unit(rng) * 720.0f, cone = std::abs(unit(rng)) * 0.01f;
        std::vector<float> x(count), y(count), z(count);
        for (std::size_t i = 0; i < count; ++i) x[i] = value(), y[i] = value(), z[i] = value();
        std::vector<EnvironmentSpot> spots(count);
        environmentSpots(count, {x.data(), y.data(), z.data()}, rotation, cone, spots.data());
        for (std::size_t i = 0; i < count; ++i) {
            const EnvironmentSpot alone = spotOf(Vec3(x[i], y[i], z[i]), rotation, cone);
            ASSERT_EQ(std::memcmp(&alone, &spots[i], sizeof alone), 0)
                << "direction " << i << " of " << count << ": (" << x[i] << ", " << y[i] << ", "
                << z[i] << "): alone s " << alone.s << " t " << alone.t << " ds " << alone.ds
                << ", with others s " << spots[i].s << " t " << spots[i].t << " ds " << spots[i].ds;
        }
    }
}

}  // namespace
}  // namespace rs
