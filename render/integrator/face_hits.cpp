// Where the hits of a level lie and which way they face, four rays at a time.
#include "integrator/face_hits.h"

#include "integrator/lanes.h"

#include <cstring>

namespace rs {

namespace {

/// Where a hit lies and which way it faces (one ray, or a lane of rays): p = o + t d, the
/// normal h turned toward the ray, the direction -d to the viewer, as glm's vector
/// expressions have them (so lane k has the bits of the one-ray call); returns whether h
/// had to be turned (the ray is inside: thesis Algorithm 6).
template <class F>
inline auto faceHit(F ox, F oy, F oz, F dx, F dy, F dz, F t, F hx, F hy, F hz, F* p, F* n, F* v) {
    p[0] = ox + dx * t, p[1] = oy + dy * t, p[2] = oz + dz * t;
    const auto inside = ((hx * dx + hy * dy) + hz * dz) > 0.0f;
    n[0] = select(inside, -hx, hx), n[1] = select(inside, -hy, hy), n[2] = select(inside, -hz, hz);
    v[0] = -dx, v[1] = -dy, v[2] = -dz;
    return inside;
}

}  // namespace

void faceHits(const float* ox, const float* oy, const float* oz, const float* dx, const float* dy,
              const float* dz, const HitBatch& hits, std::size_t n, ShadingPoints& sp,
              uint8_t* inside) {
    using L = FloatLanes;
    constexpr std::size_t w = std::size_t(kLaneWidth);
    auto at = [](const float* a, std::size_t i) {
        L v;
        std::memcpy(&v, a + i, sizeof v);
        return v;
    };
    auto put = [](std::vector<float>& a, std::size_t i, L v) {
        std::memcpy(a.data() + i, &v, sizeof v);
    };
    std::size_t i = 0;
    for (; i + w <= n; i += w) {
        L p[3], nf[3], v[3];
        const MaskLanes in =
            faceHit(at(ox, i), at(oy, i), at(oz, i), at(dx, i), at(dy, i), at(dz, i), at(hits.t, i),
                    at(hits.nx, i), at(hits.ny, i), at(hits.nz, i), p, nf, v);
        put(sp.px, i, p[0]), put(sp.py, i, p[1]), put(sp.pz, i, p[2]);
        put(sp.nx, i, nf[0]), put(sp.ny, i, nf[1]), put(sp.nz, i, nf[2]);
        put(sp.vx, i, v[0]), put(sp.vy, i, v[1]), put(sp.vz, i, v[2]);
        for (std::size_t k = 0; k < w; ++k) inside[i + k] = in[k] ? 1 : 0;
    }
    for (; i < n; ++i) {
        float p[3], nf[3], v[3];
        inside[i] = faceHit(ox[i], oy[i], oz[i], dx[i], dy[i], dz[i], hits.t[i], hits.nx[i],
                            hits.ny[i], hits.nz[i], p, nf, v);
        sp.set(i, Vec3(p[0], p[1], p[2]), Vec3(nf[0], nf[1], nf[2]), Vec3(v[0], v[1], v[2]));
    }
}

}  // namespace rs
