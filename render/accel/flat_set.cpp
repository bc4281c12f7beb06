// FlatSet: its tables, and the run-time choice between the AVX2 and the baseline lane loops.
#include "accel/flat_set.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/avx2_dispatch.h"

namespace rs {

namespace {

/// The tables as raw pointers: all the lane loops may read.
struct FlatView {
    const float *cx, *cy, *cz, *radius, *radius2, *reach;
    const uint32_t* prim;
    int spheres;
    const float *px, *py, *pz, *nx, *ny, *nz;
    const float *pn, *nsum, *pmag;  ///< Each plane's p . n, |n.x| + |n.y| + |n.z|, max |p.i|.
    int planes;
    const float *lox, *loy, *loz, *hix, *hiy, *hiz;  ///< Widened bounds of the others.
    int others;
};

}  // namespace

#define RS_LANE_SOURCE "accel/flat_lanes.inl"
#include "core/lane_instances.inl"

namespace {

void othersMasks(const FlatView& v, const RayBatch& rays, std::size_t first, const float* tmax,
                 uint8_t* masks, FlatSet::Lanes lanes) {
#if defined(RS_AVX2_DISPATCH)
    if (lanes == FlatSet::Lanes::Best && avx2Available()) {
        avx2::F8 t;
        std::memcpy(&t, tmax, sizeof t);
        return avx2::boundsMasks(v, rays, first, t, masks);
    }
#else
    (void)lanes;
#endif
    baseline::F8 t;
    std::memcpy(&t, tmax, sizeof t);
    baseline::boundsMasks(v, rays, first, t, masks);
}

}  // namespace

bool FlatSet::suits(const std::vector<Primitive>& primitives) {
    if (primitives.size() > kMaxShapes) return false;
    for (const Primitive& p : primitives)
        if (std::holds_alternative<MeshShape>(p.shape)) return false;
    return true;
}

FlatSet::FlatSet(const std::vector<PlanePrimitive>& planes,
                 const std::vector<Primitive>* primitives)
    : primitives_(primitives) {
    Tables& t = tables_;
    for (std::size_t i = 0; primitives && i < primitives->size(); ++i) {
        const Primitive& p = (*primitives)[i];
        const auto* s = std::get_if<SphereShape>(&p.shape);
        if (!s || p.hasFrame) {
            others_.push_back(uint32_t(i));
            // Widened so that rounding in the filter never drops a ray the exact test hits.
            const Aabb& b = p.worldBounds;
            const Vec3 pad = 1e-4f * (glm::abs(b.min) + glm::abs(b.max) + Vec3(1.0f));
            t.lox.push_back(b.min.x - pad.x), t.loy.push_back(b.min.y - pad.y),
                t.loz.push_back(b.min.z - pad.z);
            t.hix.push_back(b.max.x + pad.x), t.hiy.push_back(b.max.y + pad.y),
                t.hiz.push_back(b.max.z + pad.z);
            continue;
        }
        t.cx.push_back(s->center.x), t.cy.push_back(s->center.y), t.cz.push_back(s->center.z);
        t.radius.push_back(s->radius);
        t.radius2.push_back(s->radius * s->radius);
        // The cull before the lanes (sphereCandidates) keeps a sphere unless its distance to
        // the rays' box exceeds this: the radius plus a margin 100 times the rounding of the
        // exact test (about 1e-6 of the coordinates involved).
        t.reach.push_back(s->radius +
                          1e-4f * (1.0f + std::abs(s->center.x) + std::abs(s->center.y) +
                                   std::abs(s->center.z) + s->radius));
        t.prim.push_back(uint32_t(i));
    }
    t.planes = int(planes.size());
    for (const PlanePrimitive& p : planes) {
        t.px.push_back(p.shape.point.x), t.py.push_back(p.shape.point.y),
            t.pz.push_back(p.shape.point.z);
        t.nx.push_back(p.shape.normal.x), t.ny.push_back(p.shape.normal.y),
            t.nz.push_back(p.shape.normal.z);
        // For the planes' cull (planeCandidates), which leaves a margin for their rounding.
        const Vec3 q = p.shape.point, n = p.shape.normal;
        t.pn.push_back(glm::dot(q, n));
        t.nsum.push_back(std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
        t.pmag.push_back(std::max(std::abs(q.x), std::max(std::abs(q.y), std::abs(q.z))));
    }
    // The cull loads the planes' normals and terms eight at a time: padded with copies of the
    // last plane to whole groups of eight (the lanes past the count are never used).
    const std::size_t planeCount = t.px.size();
    for (std::size_t k = planeCount; k % 8 != 0; ++k)
        for (auto* v : {&t.px, &t.py, &t.pz, &t.nx, &t.ny, &t.nz, &t.pn, &t.nsum, &t.pmag})
            v->push_back(v->back());
}

namespace {

inline Ray rayAt(const RayBatch& rays, std::size_t i) {
    return Ray::make(Vec3(rays.ox[i], rays.oy[i], rays.oz[i]),
                     Vec3(rays.dx[i], rays.dy[i], rays.dz[i]));
}

FlatView view(const FlatSet::Tables& t) {
    return {t.cx.data(),    t.cy.data(),   t.cz.data(),      t.radius.data(), t.radius2.data(),
            t.reach.data(), t.prim.data(), int(t.cx.size()), t.px.data(),     t.py.data(),
            t.pz.data(),    t.nx.data(),   t.ny.data(),      t.nz.data(),     t.pn.data(),
            t.nsum.data(),  t.pmag.data(), t.planes,         t.lox.data(),    t.loy.data(),
            t.loz.data(),   t.hix.data(),  t.hiy.data(),     t.hiz.data(),    int(t.lox.size())};
}

}  // namespace

void FlatSet::closestHit(const RayBatch& rays, const HitBatch& hits, Lanes lanes) const {
    const FlatView v = view(tables_);
#if defined(RS_AVX2_DISPATCH)
    if (lanes == Lanes::Best && avx2Available())
        avx2::closestAll(v, rays, hits);
    else
#else
    (void)lanes;
#endif
        baseline::closestAll(v, rays, hits);
    if (others_.empty()) return;
    // The others ray by ray, each only where its bounds filter lets the ray through.
    uint8_t masks[kMaxShapes];
    for (std::size_t first = 0; first < rays.count; first += 8) {
        const std::size_t end = std::min(rays.count, first + 8);
        float tmax[8];
        for (std::size_t i = first; i < first + 8; ++i) {
            const std::size_t k = std::min(i, end - 1);
            tmax[i - first] = hits.slot[k] != kNoSlot ? hits.t[k] : rays.tmax[k];
        }
        othersMasks(v, rays, first, tmax, masks, lanes);
        for (std::size_t o = 0; o < others_.size(); ++o) {
            for (unsigned m = masks[o]; m; m &= m - 1) {
                const std::size_t i = first + std::size_t(__builtin_ctz(m));
                ShapeHit sh;
                float& bound = tmax[i - first];
                if (!intersectPrimitive((*primitives_)[others_[o]], rayAt(rays, i), 0.0f, bound,
                                        sh))
                    continue;
                bound = sh.t;
                hits.t[i] = sh.t;
                hits.nx[i] = sh.n.x, hits.ny[i] = sh.n.y, hits.nz[i] = sh.n.z;
                hits.slot[i] = others_[o];
            }
        }
    }
}

void FlatSet::anyHit(const RayBatch& rays, uint8_t* occluded, bool skipBlocked, Lanes lanes) const {
    const FlatView v = view(tables_);
#if defined(RS_AVX2_DISPATCH)
    if (lanes == Lanes::Best && avx2Available())
        avx2::anyAll(v, rays, occluded, skipBlocked);
    else
#else
    (void)lanes;
#endif
        baseline::anyAll(v, rays, occluded, skipBlocked);
    if (others_.empty()) return;
    uint8_t masks[kMaxShapes];
    for (std::size_t first = 0; first < rays.count; first += 8) {
        const std::size_t end = std::min(rays.count, first + 8);
        unsigned open = 0;
        for (std::size_t i = first; i < end; ++i) open |= unsigned(occluded[i] == 0) << (i - first);
        if (!open) continue;
        float tmax[8];
        for (std::size_t i = first; i < first + 8; ++i)
            tmax[i - first] = rays.tmax[std::min(i, end - 1)];
        othersMasks(v, rays, first, tmax, masks, lanes);
        for (std::size_t o = 0; o < others_.size() && open; ++o) {
            for (unsigned m = masks[o] & open; m; m &= m - 1) {
                const std::size_t i = first + std::size_t(__builtin_ctz(m));
                ShapeHit sh;
                if (intersectPrimitive((*primitives_)[others_[o]], rayAt(rays, i), 0.0f,
                                       rays.tmax[i], sh)) {
                    occluded[i] = 1;
                    open &= ~(1u << (i - first));
                }
            }
        }
    }
}

}  // namespace rs
