// Centre samples' shadow rays and answers, four points at a time where all four are listed
// (a room's walls all face its light), point by point elsewhere.
#include "integrator/centre_shadows.h"

#include <algorithm>
#include <cstring>

#include "core/lanes.h"

namespace rs {

namespace {

constexpr std::size_t kLane = std::size_t(kLaneWidth);

/// Whether points [i, i + kLane) all lie before `end` and all have a listed sample.
inline bool allListed(const uint8_t* listed, std::size_t i, std::size_t end) {
    uint32_t bytes;
    std::memcpy(&bytes, listed + i, sizeof bytes);
    return i + kLane <= end && bytes == 0x01010101u;
}

}  // namespace

std::size_t writeCentreShadows(const ShadingPoints& pts, const CentreSamples& c, std::size_t first,
                               std::size_t end, float eps, uint32_t light,
                               const ShadowRayArrays& out, std::size_t r) {
    const uint8_t* listed = c.listed.data();
    const float *px = pts.px.data(), *py = pts.py.data(), *pz = pts.pz.data();
    const float *nx = pts.nx.data(), *ny = pts.ny.data(), *nz = pts.nz.data();
    const float *dx = c.dx.data(), *dy = c.dy.data(), *dz = c.dz.data(), *dist = c.dist.data();
    const uint32_t lights[kLane] = {light, light, light, light};
    for (std::size_t i = first; i < end; i += kLane) {
        if (allListed(listed, i, end)) {
            storeLanes(out.ox + r, shadowOrigin(loadLanes(px + i), loadLanes(nx + i), eps));
            storeLanes(out.oy + r, shadowOrigin(loadLanes(py + i), loadLanes(ny + i), eps));
            storeLanes(out.oz + r, shadowOrigin(loadLanes(pz + i), loadLanes(nz + i), eps));
            storeLanes(out.dx + r, loadLanes(dx + i));
            storeLanes(out.dy + r, loadLanes(dy + i));
            storeLanes(out.dz + r, loadLanes(dz + i));
            storeLanes(out.tmax + r, shadowLength(loadLanes(dist + i), eps));
            std::memcpy(out.light + r, lights, sizeof lights);
            r += kLane;
            continue;
        }
        for (std::size_t j = i; j < std::min(end, i + kLane); ++j) {
            if (!listed[j]) continue;
            out.ox[r] = shadowOrigin(px[j], nx[j], eps);
            out.oy[r] = shadowOrigin(py[j], ny[j], eps);
            out.oz[r] = shadowOrigin(pz[j], nz[j], eps);
            out.dx[r] = dx[j], out.dy[r] = dy[j], out.dz[r] = dz[j];
            out.tmax[r] = shadowLength(dist[j], eps);
            out.light[r] = light;
            ++r;
        }
    }
    return r;
}

std::size_t readCentreAnswers(const CentreSamples& c, std::size_t first, std::size_t end,
                              const uint8_t* occluded, uint8_t* blocked, std::size_t r) {
    const uint8_t* listed = c.listed.data();
    for (std::size_t i = first; i < end; i += kLane) {
        if (allListed(listed, i, end)) {
            // Four answers in a row: listed & occluded byte by byte, as below.
            uint32_t answers;
            std::memcpy(&answers, occluded + r, sizeof answers);
            answers &= 0x01010101u;
            std::memcpy(blocked + i, &answers, sizeof answers);
            r += kLane;
            continue;
        }
        for (std::size_t j = i; j < std::min(end, i + kLane); ++j) {
            blocked[j] = uint8_t(listed[j] & occluded[r]);
            r += listed[j];
        }
    }
    return r;
}

}  // namespace rs
