// A ray's footprint on a surface: what a texture lookup filters over.
#pragma once

#include "core/lanes.h"
#include "core/math.h"

namespace rs {

/// The half-axes of the ellipse one pixel's cone of rays covers on a surface, in world units
/// (ray cones: Ray Tracing Gems, "Texture Level of Detail Strategies for Real-Time Ray
/// Tracing"). Zero axes point-sample.
struct Footprint {
    Vec3 a1{0.0f}, a2{0.0f};
};

/// A footprint's half-axes a1 and a2 by component, for one ray (F = float) or for a ray in
/// each lane (F = FloatLanes).
template <class F>
struct FootprintAxes {
    F a1x, a1y, a1z, a2x, a2y, a2z;
};

/// The footprint of a cone of full width `width` (world units) arriving along unit direction
/// d at a surface with unit normal n: stretched by 1 / |cos| along the direction's projection
/// on the surface, at most 100 times (grazing angles); zero where the width is not positive.
/// One template body for one ray and for a lane of rays (core/lanes.h: lane-wise IEEE
/// arithmetic, so lane k has the bits of the scalar call).
template <class F>
[[gnu::always_inline]] inline FootprintAxes<F> footprintAxes(F dx, F dy, F dz, F nx, F ny, F nz,
                                                             F width) {
    const F zero{};
    const auto some = width > 0.0f;
    if (!anyLane(some)) return {zero, zero, zero, zero, zero, zero};
    const F half = 0.5f * width;
    const F dn = (dx * nx + dy * ny) + dz * nz;
    const F cosine = absLanes(dn);
    // The direction's projection on the surface, made unit.
    F ux = dx - nx * dn, uy = dy - ny * dn, uz = dz - nz * dn;
    const F length = sqrtLanes((ux * ux + uy * uy) + uz * uz);
    const auto slanted = length > 1e-6f;
    ux = ux / length, uy = uy / length, uz = uz / length;
    if (anyLane(slanted == 0)) {  // not above 1e-6, or NaN
        // Head-on: any direction in the surface, n x Y (n x X where n is near X), made unit.
        const auto nearX = absLanes(nx) > 0.9f;
        const F one = zero + 1.0f;
        const F ex = select(nearX, zero, one), ey = select(nearX, one, zero), ez = zero;
        const F cx = ny * ez - ey * nz, cy = nz * ex - ez * nx, cz = nx * ey - ex * ny;
        const F inverse = 1.0f / sqrtLanes((cx * cx + cy * cy) + cz * cz);
        ux = select(slanted, ux, cx * inverse);
        uy = select(slanted, uy, cy * inverse);
        uz = select(slanted, uz, cz * inverse);
    }
    // across = n x along; along stretched by 1 / max(|cos|, 0.01).
    const F vx = ny * uz - uy * nz, vy = nz * ux - uz * nx, vz = nx * uy - ux * ny;
    const F stretch = half / select(cosine < 0.01f, zero + 0.01f, cosine);
    return {select(some, ux * stretch, zero), select(some, uy * stretch, zero),
            select(some, uz * stretch, zero), select(some, vx * half, zero),
            select(some, vy * half, zero),    select(some, vz * half, zero)};
}

/// footprintAxes for one ray, as the two half-axes.
[[gnu::always_inline]] inline Footprint footprintAt(const Vec3& dir, const Vec3& n, float width) {
    const FootprintAxes<float> f = footprintAxes(dir.x, dir.y, dir.z, n.x, n.y, n.z, width);
    return {Vec3(f.a1x, f.a1y, f.a1z), Vec3(f.a2x, f.a2y, f.a2z)};
}

}  // namespace rs
