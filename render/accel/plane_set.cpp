// Four-wide plane tests with the operations of intersect(PlaneShape), so t is the same bits.
#include "accel/plane_set.h"

namespace rs {

namespace {

/// Distances to four planes. A ray parallel to a plane gets +-inf or NaN here, which the
/// open-range tests reject like intersect(PlaneShape)'s denom == 0 branch.
inline Float4 distances(const Float4& px, const Float4& py, const Float4& pz, const Float4& nx,
                        const Float4& ny, const Float4& nz, const Vec3& o, const Vec3& d) {
    const Float4 denom = d.x * nx + d.y * ny + d.z * nz;
    const Float4 num = (px - o.x) * nx + (py - o.y) * ny + (pz - o.z) * nz;
    return num / denom;
}

}  // namespace

PlaneSet::PlaneSet(const std::vector<PlanePrimitive>& planes) {
    blocks_.assign((planes.size() + 3) / 4, Block{});
    for (std::size_t i = 0; i < planes.size(); ++i) {
        Block& b = blocks_[i / 4];
        const PlaneShape& s = planes[i].shape;
        const int k = int(i % 4);
        b.px[k] = s.point.x, b.py[k] = s.point.y, b.pz[k] = s.point.z;
        b.nx[k] = s.normal.x, b.ny[k] = s.normal.y, b.nz[k] = s.normal.z;
    }
}

int PlaneSet::closest(const Vec3& origin, const Vec3& dir, float tmin, float& tmax) const {
    int nearest = -1;
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        const Block& k4 = blocks_[b];
        const Float4 t = distances(k4.px, k4.py, k4.pz, k4.nx, k4.ny, k4.nz, origin, dir);
        for (int k = 0; k < 4; ++k) {
            if (t[k] > tmin && t[k] < tmax) {
                tmax = t[k];
                nearest = int(4 * b) + k;
            }
        }
    }
    return nearest;
}

bool PlaneSet::any(const Vec3& origin, const Vec3& dir, float tmin, float tmax) const {
    for (const Block& k4 : blocks_) {
        const Float4 t = distances(k4.px, k4.py, k4.pz, k4.nx, k4.ny, k4.nz, origin, dir);
        for (int k = 0; k < 4; ++k)
            if (t[k] > tmin && t[k] < tmax) return true;
    }
    return false;
}

}  // namespace rs
