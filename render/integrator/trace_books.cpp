// What the trace kernel records of a level besides colour (TraceKernel::keepBooks): each ray
// counted to its camera ray, the secondary segments, the first hit and whether a mirror or
// glass was met. The session's frame is built from these; renderImage asks for the first hit
// alone.
#include "integrator/trace_kernel.h"
#include "integrator/trace_level.h"

namespace rs {

void TraceKernel::keepBooks(const Level& level, const HitBatch& hits, int depth,
                            const TraceOutput& out) const {
    // Every array through a local pointer: the byte-sized stores (counts, flags) may alias
    // anything, so the compiler would reload each pointer from its vector after each one.
    const std::size_t n = level.size();
    const uint32_t* const owners = level.owner.data();
    const uint32_t* const slots = hits.slot;
    const float* const t = hits.t;
    if (uint32_t* const rays = out.rays; rays && depth > 0)  // trace() counted the camera rays.
        for (std::size_t i = 0; i < n; ++i) ++rays[owners[i]];
    if (out.segments && depth > 0) {
        const float *ox = level.ox.data(), *oy = level.oy.data(), *oz = level.oz.data();
        const float *dx = level.dx.data(), *dy = level.dy.data(), *dz = level.dz.data();
        PerRayAppender<TreeSegment> segments(out.segments);
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 o(ox[i], oy[i], oz[i]), d(dx[i], dy[i], dz[i]);
            segments.append(owners[i], slots[i] != kNoSlot ? TreeSegment{o, o + d * t[i], 0u}
                                                           : TreeSegment{o, d, 1u});
        }
    }
    PrimaryInfo* const primary = out.primary;
    if (!primary) return;
    const uint8_t* const specular = specular_.data();
    if (depth == 0) {
        const float *nx = hits.nx, *ny = hits.ny, *nz = hits.nz;
        for (std::size_t i = 0; i < n; ++i) {
            if (slots[i] == kNoSlot) continue;
            uint32_t materialIndex;
            ObjectId id;
            scene_.describe(slots[i], materialIndex, id);
            primary[owners[i]] =
                PrimaryInfo{id, t[i], Vec3(nx[i], ny[i], nz[i]), specular[materialIndex] != 0};
        }
        return;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (slots[i] == kNoSlot) continue;
        uint32_t materialIndex;
        ObjectId id;
        scene_.describe(slots[i], materialIndex, id);
        bool& touched = primary[owners[i]].touchedSpecular;
        touched = touched | (specular[materialIndex] != 0);
    }
}

}  // namespace rs
