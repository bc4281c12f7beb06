// The eight-lane loops of FlatSet. Not a header: flat_set.cpp compiles it twice through
// core/lane_instances.inl, for AVX2 (RS_LANES_AVX2 defined) and for the baseline. It touches
// raw arrays and its own inline functions only, as that file requires.
// Every expression is written in the association order of the scalar test it mirrors
// (glm's dot is (x + y) + z): that, and -ffp-contract=off, keeps the bits equal.
// Expects FlatView (raw tables) to be declared.

constexpr int kLanes = 8;
using F8 = float __attribute__((vector_size(32)));
using I8 = int32_t __attribute__((vector_size(32)));

inline F8 splat(float v) {
    return F8{v, v, v, v, v, v, v, v};
}
inline I8 splatI(int32_t v) {
    return I8{v, v, v, v, v, v, v, v};
}
inline F8 select(I8 m, F8 a, F8 b) {
    return m ? a : b;
}
inline I8 select(I8 m, I8 a, I8 b) {
    return m ? a : b;
}

inline F8 sqrt8(F8 x) {
#if defined(RS_LANES_AVX2)
    return F8(_mm256_sqrt_ps(__m256(x)));
#elif defined(__SSE2__)
    __m128 lo, hi;
    std::memcpy(&lo, &x, 16);
    std::memcpy(&hi, reinterpret_cast<const char*>(&x) + 16, 16);
    lo = _mm_sqrt_ps(lo);
    hi = _mm_sqrt_ps(hi);
    F8 r;
    std::memcpy(&r, &lo, 16);
    std::memcpy(reinterpret_cast<char*>(&r) + 16, &hi, 16);
    return r;
#else
    F8 r;
    for (int k = 0; k < kLanes; ++k) r[k] = std::sqrt(x[k]);
    return r;
#endif
}

/// Bit k set when lane k of `m` is true.
inline unsigned bits(I8 m) {
#if defined(RS_LANES_AVX2)
    return unsigned(_mm256_movemask_ps(__m256(m)));
#elif defined(__SSE2__)
    __m128 lo, hi;
    std::memcpy(&lo, &m, 16);
    std::memcpy(&hi, reinterpret_cast<const char*>(&m) + 16, 16);
    return unsigned(_mm_movemask_ps(lo)) | (unsigned(_mm_movemask_ps(hi)) << 4);
#else
    unsigned b = 0;
    for (int k = 0; k < kLanes; ++k) b |= unsigned(m[k] != 0) << k;
    return b;
#endif
}

/// Eight rays of a batch; a short last group repeats its last ray in the spare lanes.
struct Rays8 {
    F8 ox, oy, oz, dx, dy, dz, tmax;
    int lanes;
};

inline F8 load8(const float* p, std::size_t first, int lanes) {
    F8 v;
    if (lanes == kLanes) {
        std::memcpy(&v, p + first, sizeof v);
    } else {
        for (int k = 0; k < kLanes; ++k) v[k] = p[first + std::size_t(k < lanes ? k : lanes - 1)];
    }
    return v;
}

inline Rays8 loadRays(const RayBatch& r, std::size_t first) {
    const std::size_t left = r.count - first;
    const int lanes = left < std::size_t(kLanes) ? int(left) : kLanes;
    return {load8(r.ox, first, lanes),   load8(r.oy, first, lanes),
            load8(r.oz, first, lanes),   load8(r.dx, first, lanes),
            load8(r.dy, first, lanes),   load8(r.dz, first, lanes),
            load8(r.tmax, first, lanes), lanes};
}

/// intersect(PlaneShape)'s quotient (PlaneSet's distances) for one plane and eight rays.
inline F8 planeDistance(const Rays8& r, const FlatView& v, int j) {
    const F8 denom = r.dx * v.nx[j] + r.dy * v.ny[j] + r.dz * v.nz[j];
    const F8 num =
        (v.px[j] - r.ox) * v.nx[j] + (v.py[j] - r.oy) * v.ny[j] + (v.pz[j] - r.oz) * v.nz[j];
    return num / denom;
}

/// One sphere against eight rays: intersect(SphereShape) up to solveRecentredSphere, then
/// its root choice with range (0, tmax). True lanes get t, the offset and f.
struct SphereLanes {
    F8 t, offset, fx, fy, fz;
};

inline I8 sphereHit(const Rays8& r, F8 a, const FlatView& v, int s, F8 tmax, SphereLanes& out) {
    const float cx = v.cx[s], cy = v.cy[s], cz = v.cz[s];
    const F8 tProj = ((cx - r.ox) * r.dx + (cy - r.oy) * r.dy + (cz - r.oz) * r.dz) / a;
    const F8 fx = (r.ox - cx) + tProj * r.dx;
    const F8 fy = (r.oy - cy) + tProj * r.dy;
    const F8 fz = (r.oz - cz) + tProj * r.dz;
    const F8 bHalf = fx * r.dx + fy * r.dy + fz * r.dz;
    const F8 c = (fx * fx + fy * fy + fz * fz) - v.radius2[s];
    const F8 disc = bHalf * bHalf - a * c;
    const I8 valid = disc >= 0.0f;
    if (!bits(valid)) return splatI(0);
    const F8 root = sqrt8(select(valid, disc, splat(0.0f)));
    const F8 q = select(bHalf >= 0.0f, -(bHalf + root), -(bHalf - root));
    const I8 nonzero = q != 0.0f;
    const F8 s0raw = q / a, s1raw = c / q;
    const I8 swap = s0raw > s1raw;
    const F8 s0 = select(nonzero, select(swap, s1raw, s0raw), splat(0.0f));
    const F8 s1 = select(nonzero, select(swap, s0raw, s1raw), splat(0.0f));
    const F8 t0 = tProj + s0, t1 = tProj + s1;
    const I8 nearHit = valid & (t0 > 0.0f) & (t0 < tmax);
    const I8 farHit = valid & ~nearHit & (t1 > 0.0f) & (t1 < tmax);
    out.t = select(nearHit, t0, t1);
    out.offset = select(nearHit, s0, s1);
    out.fx = fx, out.fy = fy, out.fz = fz;
    return nearHit | farHit;
}

/// Lane-wise a < b ? a : b and a > b ? a : b (one instruction each where there is one).
inline F8 min8(F8 a, F8 b) {
#if defined(RS_LANES_AVX2)
    return F8(_mm256_min_ps(__m256(a), __m256(b)));
#else
    return select(a < b, a, b);
#endif
}
inline F8 max8(F8 a, F8 b) {
#if defined(RS_LANES_AVX2)
    return F8(_mm256_max_ps(__m256(a), __m256(b)));
#else
    return select(a > b, a, b);
#endif
}
/// The smallest and the largest lane of x, in every lane.
inline F8 lowest(F8 x) {
    x = min8(x, __builtin_shufflevector(x, x, 4, 5, 6, 7, 0, 1, 2, 3));
    x = min8(x, __builtin_shufflevector(x, x, 2, 3, 0, 1, 6, 7, 4, 5));
    return min8(x, __builtin_shufflevector(x, x, 1, 0, 3, 2, 5, 4, 7, 6));
}
inline F8 highest(F8 x) {
    x = max8(x, __builtin_shufflevector(x, x, 4, 5, 6, 7, 0, 1, 2, 3));
    x = max8(x, __builtin_shufflevector(x, x, 2, 3, 0, 1, 6, 7, 4, 5));
    return max8(x, __builtin_shufflevector(x, x, 1, 0, 3, 2, 5, 4, 7, 6));
}
inline float magnitude(float x) {
    return x < 0.0f ? -x : x;
}

/// Spheres (and planes) from this many on are culled for a group of rays before the lanes
/// test them.
constexpr int kCullFrom = 4;

/// The box around eight rays' segments o + t d, t in [0, tend], and a margin 100 times the
/// rounding of the exact tests at its coordinates (1e-4 of the largest); `finite` is false
/// when a segment is not finite (then there is no box and nothing is culled).
struct SegmentBox {
    F8 lox, hix, loy, hiy, loz, hiz;  ///< Every lane holds the bound.
    float size = 0.0f;                ///< The largest magnitude of a corner coordinate.
    bool finite = false;
};

inline SegmentBox segmentBox(const Rays8& r, F8 tend) {
    SegmentBox b;
    const F8 ex = r.ox + r.dx * tend, ey = r.oy + r.dy * tend, ez = r.oz + r.dz * tend;
    // x - x is 0 exactly when x is finite (NaN for infinities and NaN).
    if (bits(((ex - ex) == 0.0f) & ((ey - ey) == 0.0f) & ((ez - ez) == 0.0f)) != 0xffu) return b;
    b.lox = lowest(min8(r.ox, ex)), b.hix = highest(max8(r.ox, ex));
    b.loy = lowest(min8(r.oy, ey)), b.hiy = highest(max8(r.oy, ey));
    b.loz = lowest(min8(r.oz, ez)), b.hiz = highest(max8(r.oz, ez));
    const float corners[6] = {b.lox[0], b.hix[0], b.loy[0], b.hiy[0], b.loz[0], b.hiz[0]};
    for (float c : corners) b.size = b.size < magnitude(c) ? magnitude(c) : b.size;
    b.finite = true;
    return b;
}

/// A conservative cull of the world spheres for eight rays: bit s set unless sphere s lies
/// out of reach of the box around the rays' segments (all of them, when there is no box). A
/// sphere the exact test could hit within (0, tend) meets that box, up to rounding about
/// 1e-6 of the coordinates involved; the margins (`reach`, and 1e-4 of the box's own
/// coordinates) are 100 times that, so a culled sphere is one the lanes would have missed
/// in every lane, and skipping it leaves every bit of the answer as it was.
inline unsigned sphereCandidates(const FlatView& v, const SegmentBox& b) {
    const unsigned all = (1u << v.spheres) - 1u;  // at most FlatSet::kMaxShapes
    if (!b.finite) return all;
    const F8 margin = splat(1e-4f * (1.0f + b.size)), zero = splat(0.0f);
    unsigned keep = 0;
    for (int s = 0; s < v.spheres; s += kLanes) {
        const int lanes = v.spheres - s < kLanes ? v.spheres - s : kLanes;
        const F8 cx = load8(v.cx, std::size_t(s), lanes), cy = load8(v.cy, std::size_t(s), lanes);
        const F8 cz = load8(v.cz, std::size_t(s), lanes);
        // How far each centre lies outside the box along each axis (0 inside; the box is
        // not empty, so one of the two terms is 0).
        const F8 gx = max8(b.lox - cx, zero) + max8(cx - b.hix, zero);
        const F8 gy = max8(b.loy - cy, zero) + max8(cy - b.hiy, zero);
        const F8 gz = max8(b.loz - cz, zero) + max8(cz - b.hiz, zero);
        const F8 reach = load8(v.reach, std::size_t(s), lanes) + margin;
        const unsigned out = bits((gx * gx + gy * gy + gz * gz) > reach * reach);
        keep |= (~out & ((1u << lanes) - 1u)) << s;
    }
    return keep;
}

/// sphereCandidates for segments ending at `tend`, the box made only where there are enough
/// spheres to pay for it.
inline unsigned sphereCandidates(const FlatView& v, const Rays8& r, F8 tend) {
    if (v.spheres < kCullFrom) return (1u << v.spheres) - 1u;
    return sphereCandidates(v, segmentBox(r, tend));
}

/// A conservative cull of planes [from, from + lanes) for eight rays (lanes at most 8): bit
/// j set unless the box around the segments lies wholly on one side of plane from + j, by
/// more than 1e-4 of the coordinates involved (the box's, the plane point's) times the
/// normal's size. Then both ends of every segment lie on that side, the exact quotient is
/// <= 0 or >= tmax by far more than its rounding, and the lanes would miss it in every lane.
inline unsigned planeCandidates(const FlatView& v, const SegmentBox& b, int from, int lanes) {
    const unsigned all = (1u << lanes) - 1u;
    if (!b.finite) return all;
    // The plane tables are padded to whole groups of eight: plain loads.
    const std::size_t f = std::size_t(from);
    const F8 nx = load8(v.nx, f, kLanes), ny = load8(v.ny, f, kLanes), nz = load8(v.nz, f, kLanes);
    const F8 zero = splat(0.0f);
    const I8 px = nx > zero, py = ny > zero, pz = nz > zero;
    // The signed distance (x - p) . n at the box's nearest and farthest corners.
    const F8 offset = load8(v.pn, f, kLanes);
    const F8 lo = ((select(px, nx * b.lox, nx * b.hix) + select(py, ny * b.loy, ny * b.hiy)) +
                   select(pz, nz * b.loz, nz * b.hiz)) -
                  offset;
    const F8 hi = ((select(px, nx * b.hix, nx * b.lox) + select(py, ny * b.hiy, ny * b.loy)) +
                   select(pz, nz * b.hiz, nz * b.loz)) -
                  offset;
    const F8 margin =
        (1e-4f * (1.0f + b.size + load8(v.pmag, f, kLanes))) * load8(v.nsum, f, kLanes);
    const unsigned aside = bits((lo > margin) | (hi < -margin));
    return ~aside & all;
}

/// Closest hits of rays [first, first + 8): planes first in order, then spheres in order,
/// each taken only when strictly nearer (so the first of equal hits wins, as in the scalar
/// scans). The sphere normal is (f + offset d) / radius of the winner, as intersect() has it.
inline void closest8(const FlatView& v, const RayBatch& rays, std::size_t first,
                     const HitBatch& hits) {
    const Rays8 r = loadRays(rays, first);
    F8 best = r.tmax;
    I8 slot = splatI(int32_t(kNoSlot));
    F8 nx = splat(0.0f), ny = splat(0.0f), nz = splat(0.0f);
    for (int j = 0; j < v.planes; ++j) {
        const F8 t = planeDistance(r, v, j);
        const I8 m = (t > 0.0f) & (t < best);
        if (!bits(m)) continue;
        best = select(m, t, best);
        slot = select(m, splatI(int32_t(kPlaneSlot | uint32_t(j))), slot);
        nx = select(m, splat(v.nx[j]), nx);
        ny = select(m, splat(v.ny[j]), ny);
        nz = select(m, splat(v.nz[j]), nz);
    }
    const F8 a = r.dx * r.dx + r.dy * r.dy + r.dz * r.dz;
    // Segments end at the planes' hits: the spheres out of their reach cannot be nearer.
    for (unsigned left = sphereCandidates(v, r, best); left; left &= left - 1) {
        const int s = __builtin_ctz(left);
        SphereLanes h;
        const I8 m = sphereHit(r, a, v, s, best, h);
        if (!bits(m)) continue;
        best = select(m, h.t, best);
        slot = select(m, splatI(int32_t(v.prim[s])), slot);
        const float radius = v.radius[s];
        nx = select(m, (h.fx + h.offset * r.dx) / radius, nx);
        ny = select(m, (h.fy + h.offset * r.dy) / radius, ny);
        nz = select(m, (h.fz + h.offset * r.dz) / radius, nz);
    }
    const F8 t = select(slot == int32_t(kNoSlot), splat(kInfinity), best);
    if (r.lanes == kLanes) {  // the hit arrays are structure of arrays: a store per field
        std::memcpy(hits.t + first, &t, sizeof t);
        std::memcpy(hits.nx + first, &nx, sizeof nx);
        std::memcpy(hits.ny + first, &ny, sizeof ny);
        std::memcpy(hits.nz + first, &nz, sizeof nz);
        std::memcpy(hits.slot + first, &slot, sizeof slot);
        return;
    }
    for (int k = 0; k < r.lanes; ++k) {
        const std::size_t i = first + std::size_t(k);
        hits.t[i] = t[k];
        hits.nx[i] = nx[k], hits.ny[i] = ny[k], hits.nz[i] = nz[k];
        hits.slot[i] = uint32_t(slot[k]);
    }
}

/// Each 8-bit mask as eight bytes of 0 or 1 (byte k is bit k): a group's answers in one store.
struct LaneBytes {
    uint8_t bytes[256][kLanes];
    constexpr LaneBytes() : bytes{} {
        for (int m = 0; m < 256; ++m)
            for (int k = 0; k < kLanes; ++k) bytes[m][k] = uint8_t((m >> k) & 1);
    }
};
constexpr LaneBytes kLaneBytes{};

/// Any hit of rays [first, first + 8): spheres first (a shadow ray toward a light inside a
/// room rarely reaches a wall), stopping once every lane is blocked. With `skipBlocked`,
/// lanes already marked occluded count as blocked from the start.
inline void any8(const FlatView& v, const RayBatch& rays, std::size_t first, uint8_t* occluded,
                 bool skipBlocked) {
    const Rays8 r = loadRays(rays, first);
    const unsigned all = (1u << r.lanes) - 1u;
    unsigned blocked = 0;
    if (skipBlocked)
        for (int k = 0; k < r.lanes; ++k)
            blocked |= unsigned(occluded[first + std::size_t(k)] != 0) << k;
    if (blocked == all) return;
    const F8 a = r.dx * r.dx + r.dy * r.dy + r.dz * r.dz;
    // One box for both culls, made where there are enough spheres or planes to pay for it.
    const SegmentBox box =
        v.spheres >= kCullFrom || v.planes >= kCullFrom ? segmentBox(r, r.tmax) : SegmentBox{};
    for (unsigned left = sphereCandidates(v, box); left && (blocked & all) != all;
         left &= left - 1) {
        const int s = __builtin_ctz(left);
        SphereLanes h;
        blocked |= bits(sphereHit(r, a, v, s, r.tmax, h));
    }
    // Planes eight at a time: a shadow ray inside a room crosses none, so most are culled.
    for (int from = 0; from < v.planes && (blocked & all) != all; from += kLanes) {
        const int lanes = v.planes - from < kLanes ? v.planes - from : kLanes;
        for (unsigned left = planeCandidates(v, box, from, lanes); left && (blocked & all) != all;
             left &= left - 1) {
            const F8 t = planeDistance(r, v, from + __builtin_ctz(left));
            blocked |= bits((t > 0.0f) & (t < r.tmax));
        }
    }
    if (r.lanes == kLanes) {
        std::memcpy(occluded + first, &kLaneBytes.bytes[blocked], kLanes);
    } else {
        for (int k = 0; k < r.lanes; ++k) occluded[first + std::size_t(k)] = (blocked >> k) & 1u;
    }
}

/// For rays [first, first + 8) and each other primitive o: bit k of masks[o] set when ray k
/// may meet o's (slightly widened) world bounds within (0, tmax). A filter only, so it fails
/// open: NaN slabs (a ray in a face's plane) leave the interval unconstrained.
inline void boundsMasks(const FlatView& v, const RayBatch& rays, std::size_t first, const F8& tmax,
                        uint8_t* masks) {
    const Rays8 r = loadRays(rays, first);
    const F8 one = splat(1.0f);
    const F8 ix = one / r.dx, iy = one / r.dy, iz = one / r.dz;
    for (int o = 0; o < v.others; ++o) {
        const F8 x0 = (v.lox[o] - r.ox) * ix, x1 = (v.hix[o] - r.ox) * ix;
        const F8 y0 = (v.loy[o] - r.oy) * iy, y1 = (v.hiy[o] - r.oy) * iy;
        const F8 z0 = (v.loz[o] - r.oz) * iz, z1 = (v.hiz[o] - r.oz) * iz;
        // Per axis near and far; a NaN axis (0 * inf) is skipped by the selects below.
        const F8 nx = select(x0 < x1, x0, x1), fx = select(x0 < x1, x1, x0);
        const F8 ny = select(y0 < y1, y0, y1), fy = select(y0 < y1, y1, y0);
        const F8 nz = select(z0 < z1, z0, z1), fz = select(z0 < z1, z1, z0);
        F8 enter = splat(-kInfinity), exit = splat(kInfinity);
        enter = select(nx > enter, nx, enter), exit = select(fx < exit, fx, exit);
        enter = select(ny > enter, ny, enter), exit = select(fy < exit, fy, exit);
        enter = select(nz > enter, nz, enter), exit = select(fz < exit, fz, exit);
        const I8 miss = (enter > exit) | (exit < 0.0f) | (enter > tmax);
        masks[o] = uint8_t(~bits(miss) & ((1u << r.lanes) - 1u));
    }
}

inline void closestAll(const FlatView& v, const RayBatch& rays, const HitBatch& hits) {
    for (std::size_t first = 0; first < rays.count; first += kLanes) closest8(v, rays, first, hits);
}

inline void anyAll(const FlatView& v, const RayBatch& rays, uint8_t* occluded, bool skipBlocked) {
    for (std::size_t first = 0; first < rays.count; first += kLanes)
        any8(v, rays, first, occluded, skipBlocked);
}
