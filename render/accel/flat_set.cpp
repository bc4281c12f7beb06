// FlatSet: its tables, and the run-time choice between the AVX2 and the baseline lane loops.
#include "accel/flat_set.h"

#include <cmath>
#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RS_FLAT_DISPATCH 1
#include <immintrin.h>
#elif defined(__SSE2__)
#include <immintrin.h>
#endif

namespace rs {

namespace {

/// The tables as raw pointers: all the lane loops may read.
struct FlatView {
    const float *cx, *cy, *cz, *radius, *radius2;
    const uint32_t* prim;
    int spheres;
    const float *px, *py, *pz, *nx, *ny, *nz;
    int planes;
};

}  // namespace

#if defined(RS_FLAT_DISPATCH)
namespace avx2 {
namespace {
#pragma GCC push_options
#pragma GCC target("avx2")
#define RS_FLAT_AVX2 1
#include "accel/flat_lanes.inl"
#undef RS_FLAT_AVX2
#pragma GCC pop_options
}  // namespace
}  // namespace avx2
#endif

namespace baseline {
namespace {
#include "accel/flat_lanes.inl"
}  // namespace
}  // namespace baseline

namespace {

bool useAvx2() {
#if defined(RS_FLAT_DISPATCH)
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
#else
    return false;
#endif
}

}  // namespace

bool FlatSet::suits(const std::vector<Primitive>& primitives) {
    if (primitives.size() > kMaxSpheres) return false;
    for (const Primitive& p : primitives)
        if (p.hasFrame || !std::holds_alternative<SphereShape>(p.shape)) return false;
    return true;
}

FlatSet::FlatSet(const std::vector<PlanePrimitive>& planes, const std::vector<Primitive>* spheres) {
    Tables& t = tables_;
    if (spheres) {
        for (const Primitive& p : *spheres) {
            const SphereShape& s = std::get<SphereShape>(p.shape);
            t.cx.push_back(s.center.x), t.cy.push_back(s.center.y), t.cz.push_back(s.center.z);
            t.radius.push_back(s.radius);
            t.radius2.push_back(s.radius * s.radius);
            t.prim.push_back(uint32_t(t.prim.size()));
        }
    }
    for (const PlanePrimitive& p : planes) {
        t.px.push_back(p.shape.point.x), t.py.push_back(p.shape.point.y), t.pz.push_back(p.shape.point.z);
        t.nx.push_back(p.shape.normal.x), t.ny.push_back(p.shape.normal.y), t.nz.push_back(p.shape.normal.z);
    }
}

namespace {

FlatView view(const FlatSet::Tables& t) {
    return {t.cx.data(), t.cy.data(), t.cz.data(), t.radius.data(), t.radius2.data(), t.prim.data(),
            int(t.cx.size()), t.px.data(), t.py.data(), t.pz.data(), t.nx.data(), t.ny.data(),
            t.nz.data(), int(t.px.size())};
}

}  // namespace

void FlatSet::closestHit(const RayBatch& rays, const HitBatch& hits, Lanes lanes) const {
    const FlatView v = view(tables_);
#if defined(RS_FLAT_DISPATCH)
    if (lanes == Lanes::Best && useAvx2()) return avx2::closestAll(v, rays, hits);
#else
    (void)lanes;
#endif
    baseline::closestAll(v, rays, hits);
}

void FlatSet::anyHit(const RayBatch& rays, uint8_t* occluded, bool skipBlocked, Lanes lanes) const {
    const FlatView v = view(tables_);
#if defined(RS_FLAT_DISPATCH)
    if (lanes == Lanes::Best && useAvx2()) return avx2::anyAll(v, rays, occluded, skipBlocked);
#else
    (void)lanes;
#endif
    baseline::anyAll(v, rays, occluded, skipBlocked);
}

}  // namespace rs
