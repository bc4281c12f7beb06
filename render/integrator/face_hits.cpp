// Where the hits of a level lie and which way they face, four rays at a time.
#include "integrator/face_hits.h"

#include <cstring>

#include "core/lanes.h"

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
    using Bytes = uint8_t __attribute__((vector_size(kLaneWidth)));
    // Local pointers: the byte stores of `inside` may alias anything, a vector's data
    // pointer included, which would be reloaded after each.
    float *px = sp.px.data(), *py = sp.py.data(), *pz = sp.pz.data();
    float *nx = sp.nx.data(), *ny = sp.ny.data(), *nz = sp.nz.data();
    float *vx = sp.vx.data(), *vy = sp.vy.data(), *vz = sp.vz.data();
    const float *t = hits.t, *hx = hits.nx, *hy = hits.ny, *hz = hits.nz;
    std::size_t i = 0;
    for (; i + w <= n; i += w) {
        L p[3], nf[3], v[3];
        const MaskLanes in =
            faceHit(loadLanes(ox + i), loadLanes(oy + i), loadLanes(oz + i), loadLanes(dx + i),
                    loadLanes(dy + i), loadLanes(dz + i), loadLanes(t + i), loadLanes(hx + i),
                    loadLanes(hy + i), loadLanes(hz + i), p, nf, v);
        storeLanes(px + i, p[0]), storeLanes(py + i, p[1]), storeLanes(pz + i, p[2]);
        storeLanes(nx + i, nf[0]), storeLanes(ny + i, nf[1]), storeLanes(nz + i, nf[2]);
        storeLanes(vx + i, v[0]), storeLanes(vy + i, v[1]), storeLanes(vz + i, v[2]);
        const Bytes flags = __builtin_convertvector(in & 1, Bytes);  // 1 where turned
        std::memcpy(inside + i, &flags, sizeof flags);
    }
    for (; i < n; ++i) {
        float p[3], nf[3], v[3];
        inside[i] = faceHit(ox[i], oy[i], oz[i], dx[i], dy[i], dz[i], hits.t[i], hits.nx[i],
                            hits.ny[i], hits.nz[i], p, nf, v);
        sp.set(i, Vec3(p[0], p[1], p[2]), Vec3(nf[0], nf[1], nf[2]), Vec3(v[0], v[1], v[2]));
    }
}

}  // namespace rs
