// Where rays look in a latitude-longitude environment, and how wide their cones are there.
#pragma once

#include <cstddef>

namespace rs {

/// Texture coordinates of a direction in the environment image (s along its width, t down
/// from the top row) and the full widths of a cone around it, in s and in t.
struct EnvironmentSpot {
    float s, t, ds, dt;
};

/// Directions, axis by axis (structure of arrays): direction i is (x[i], y[i], z[i]), of any
/// length (a zero or NaN direction looks straight up).
struct Directions {
    const float *x, *y, *z;
};

/// The spots of `count` directions, four at a time, with the map sphereUV uses: u = phi /
/// (2 pi), phi the angle from +X toward +Z, v = 0.5 + asin(y) / pi (the image's top row
/// straight up), s = u + rotationDegrees / 360 wrapped to [0, 1), t = 1 - v. A cone of full
/// angle `coneAngle` radians (0: a point) spans coneAngle / pi in t and coneAngle / (2 pi
/// cos(latitude)) in s, at most one turn. Each spot is bit for bit the one its direction
/// gets alone.
void environmentSpots(std::size_t count, const Directions& d, float rotationDegrees,
                      float coneAngle, EnvironmentSpot* out);

}  // namespace rs
