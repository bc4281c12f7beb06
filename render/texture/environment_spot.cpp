// The latitude-longitude map, four directions in the lanes of an SSE vector.
#include "texture/environment_spot.h"

#include <algorithm>

#include "core/fast_angles.h"
#include "core/floor_lanes.h"
#include "core/lanes.h"
#include "core/math.h"

namespace rs {

namespace {

constexpr int kWidth = kLaneWidth;
using F = FloatLanes;

}  // namespace

void environmentSpots(std::size_t count, const Directions& d, float rotationDegrees,
                      float coneAngle, EnvironmentSpot* out) {
    // Both angles are atan2s, which need no unit vector: |d| enters only the cone's width in s.
    constexpr float kInverseTwoPi = 1.0f / kTwoPi, kInversePi = 1.0f / kPi;
    const float turn = rotationDegrees * (1.0f / 360.0f);
    const float cone = std::max(coneAngle, 0.0f);
    const float dt = cone * kInversePi;
    for (std::size_t first = 0; first < count; first += kWidth) {
        F x = gatherLanes(d.x, first, count), y = gatherLanes(d.y, first, count);
        F z = gatherLanes(d.z, first, count);
        F rho = sqrtLanes(x * x + z * z);
        F length = sqrtLanes(rho * rho + y * y);
        const auto up = !(length > 0.0f);  // zero or NaN: straight up
        x = up ? F{} : x, z = up ? F{} : z, y = up ? splat(1.0f) : y;
        rho = up ? F{} : rho, length = up ? splat(1.0f) : length;
        F phi = rho > 0.0f ? atan2Polynomial(z, x) : F{};
        phi = phi < 0.0f ? phi + kTwoPi : phi;
        F s = phi * kInverseTwoPi + turn;
        s -= floorLanes(s);
        const F t = 0.5f - atan2Polynomial(y, rho) * kInversePi;
        const F across = 1e-6f * length;
        const F ds = cone * length / (kTwoPi * (rho < across ? across : rho));  // std::max
        const F dsClamped = 1.0f < ds ? splat(1.0f) : ds;                       // std::min
        for (int k = 0; k < kWidth && first + std::size_t(k) < count; ++k)
            out[first + std::size_t(k)] = {s[k], t[k], dsClamped[k], dt};
    }
}

}  // namespace rs
