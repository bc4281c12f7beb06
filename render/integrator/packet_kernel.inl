// The eight-lane kernel of PacketTracer. Not a header: packet_tracer.cpp includes it twice,
// into namespace avx2 under `#pragma GCC target("avx2")` (with RS_PACKET_AVX2 defined) and
// into namespace baseline, so one source gives both machine-code versions. It works on raw
// arrays only: templates from other headers (std::vector) are instantiated outside the
// AVX2 region, so no code the rest of the program can reach is compiled for AVX2.
// Expects PathNode, RayArrays and PacketTables to be declared.

constexpr int kLanes = 8;
/// Eight floats (GCC/Clang vector extension): lane-wise IEEE arithmetic, one AVX register or
/// two SSE/NEON ones. Every expression below is written in the association order of the
/// scalar code it mirrors (glm's dot is (x + y) + z), which is what keeps the bits equal.
using F8 = float __attribute__((vector_size(32)));
/// Lane masks: all ones (true) or zero, as vector comparisons return them.
using I8 = int32_t __attribute__((vector_size(32)));

inline F8 splat(float v) { return F8{v, v, v, v, v, v, v, v}; }
inline I8 splatI(int32_t v) { return I8{v, v, v, v, v, v, v, v}; }

inline F8 sqrt8(F8 x) {
#if defined(RS_PACKET_AVX2)
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
#if defined(RS_PACKET_AVX2)
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

inline F8 select(I8 m, F8 a, F8 b) { return m ? a : b; }
inline I8 select(I8 m, I8 a, I8 b) { return m ? a : b; }

/// base[index[k]] in lane k (every index valid).
inline F8 gather(const float* base, I8 index) {
#if defined(RS_PACKET_AVX2)
    return F8(_mm256_i32gather_ps(base, __m256i(index), 4));
#else
    return F8{base[index[0]], base[index[1]], base[index[2]], base[index[3]],
              base[index[4]], base[index[5]], base[index[6]], base[index[7]]};
#endif
}

inline I8 gather(const int32_t* base, I8 index) {
#if defined(RS_PACKET_AVX2)
    return I8(_mm256_i32gather_epi32(base, __m256i(index), 4));
#else
    return I8{base[index[0]], base[index[1]], base[index[2]], base[index[3]],
              base[index[4]], base[index[5]], base[index[6]], base[index[7]]};
#endif
}

/// Which table entry each lane reads, and whether all lanes that matter read the same one:
/// neighbouring rays mostly hit the same shape, and one broadcast is far cheaper than a gather.
struct Lookup {
    I8 index;
    bool uniform;
    int32_t first;
};

/// `index` restricted to the lanes of `mask` (the others may read anything).
inline Lookup lookup(I8 index, I8 mask) {
    const unsigned m = bits(mask);
    if (!m) return {index, true, 0};
    const int32_t first = index[__builtin_ctz(m)];
    return {index, (bits(index == first) & m) == m, first};
}

inline F8 fetch(const float* table, const Lookup& l) {
    return l.uniform ? splat(table[l.first]) : gather(table, l.index);
}

inline I8 fetch(const int32_t* table, const Lookup& l) {
    return l.uniform ? splatI(table[l.first]) : gather(table, l.index);
}

/// The largest lane (no NaN lanes).
inline float maxLane(F8 v) {
    v = select(v > __builtin_shufflevector(v, v, 4, 5, 6, 7, 0, 1, 2, 3), v,
               __builtin_shufflevector(v, v, 4, 5, 6, 7, 0, 1, 2, 3));
    v = select(v > __builtin_shufflevector(v, v, 2, 3, 0, 1, 6, 7, 4, 5), v,
               __builtin_shufflevector(v, v, 2, 3, 0, 1, 6, 7, 4, 5));
    v = select(v > __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6), v,
               __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6));
    return v[0];
}

inline F8 load(const float* p) {
    F8 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

/// Eight rays, structure of arrays.
struct Rays8 {
    F8 ox, oy, oz, dx, dy, dz;
};

/// Sphere-root selection of solveRecentredSphere for eight lanes: true in the lanes with a
/// root in (tmin, tmax); `t` and `offset` are set there.
inline I8 solveSpheres(F8 a, F8 tProj, F8 bHalf, F8 c, F8 disc, F8 tmin, F8 tmax, F8& t,
                       F8& offset) {
    const I8 valid = disc >= 0.0f;
    const F8 root = sqrt8(select(valid, disc, splat(0.0f)));
    const F8 q = select(bHalf >= 0.0f, -(bHalf + root), -(bHalf - root));
    const I8 nonzero = q != 0.0f;
    F8 s0 = q / a, s1 = c / q;
    const I8 swap = s0 > s1;
    const F8 lo = select(swap, s1, s0), hi = select(swap, s0, s1);
    s0 = select(nonzero, lo, splat(0.0f));
    s1 = select(nonzero, hi, splat(0.0f));
    const F8 t0 = tProj + s0, t1 = tProj + s1;
    const I8 near = valid & (t0 > tmin) & (t0 < tmax);
    const I8 far = valid & ~near & (t1 > tmin) & (t1 < tmax);
    t = select(near, t0, t1);
    offset = select(near, s0, s1);
    return near | far;
}

/// The re-centred sphere quadratic of intersect(SphereShape) for eight rays and one sphere.
inline I8 sphereHit(const Rays8& r, F8 a, float cx, float cy, float cz, float radius2, F8 tmin,
                    F8 tmax, F8& t, F8& offset) {
    const F8 tProj = ((cx - r.ox) * r.dx + (cy - r.oy) * r.dy + (cz - r.oz) * r.dz) / a;
    const F8 fx = (r.ox - cx) + tProj * r.dx;
    const F8 fy = (r.oy - cy) + tProj * r.dy;
    const F8 fz = (r.oz - cz) + tProj * r.dz;
    const F8 bHalf = fx * r.dx + fy * r.dy + fz * r.dz;
    const F8 c = (fx * fx + fy * fy + fz * fz) - radius2;
    const F8 disc = bHalf * bHalf - a * c;
    if (!bits(disc >= 0.0f)) return splatI(0);
    return solveSpheres(a, tProj, bHalf, c, disc, tmin, tmax, t, offset);
}

/// Distances to one plane (intersect(PlaneShape)'s quotient) for eight rays.
inline F8 planeDistance(const Rays8& r, float px, float py, float pz, float nx, float ny,
                        float nz) {
    const F8 denom = r.dx * nx + r.dy * ny + r.dz * nz;
    const F8 num = (px - r.ox) * nx + (py - r.oy) * ny + (pz - r.oz) * nz;
    return num / denom;
}

/// The closest hits of eight rays: `plane` and `sphere` hold the index (into planes() and
/// primitives()) of the winner of each kind, -1 for none; a sphere index wins over a plane.
struct Hits8 {
    F8 t, offset;
    I8 plane, sphere;
};

/// The tracer's SIMD loops over raw arrays; PacketTracer's methods drive them level by level.
class PacketKernel {
public:
    PacketKernel(const CompiledScene& scene, const PacketTables& tables, int maxDepth,
                 bool shadows, float eps)
        : scene_(scene), tables_(tables), maxDepth_(maxDepth), shadows_(shadows), eps_(eps) {}

    /// The camera rays through image points (px[k], py[k]), k < count <= 8, with
    /// CameraModel::generateRay's operations, traced as level 0. `ids`, `normals` and
    /// `depths` (each may be null) receive traceCamera's PrimaryInfo fields per lane, and
    /// `points` (may be null) the hit point, Ray::at(depth).
    void traceCamera(const float* px, const float* py, int count, const RaySubset* subset,
                     PathNode* nodes, const RayArrays& next, std::size_t& nextCount,
                     ObjectId* ids, Vec3* normals, float* depths, Vec3* points,
                     TraceCounters& counters) const {
        const Rays8 r = cameraRays(px, py, count);
        traceBatch(r, count, 0, subset, nodes, next, nextCount, ids, normals, depths, points,
                   counters);
    }

    /// The id of the first thing each camera ray through (px[k], py[k]) hits (CompiledScene::
    /// intersect's answer), kNoObject for none; no shading.
    void firstHits(const float* px, const float* py, int count, const RaySubset* subset,
                   ObjectId* ids) const {
        Hits8 h;
        closestHit(cameraRays(px, py, count), subset, h);
        for (int k = 0; k < count; ++k)
            ids[k] = h.sphere[k] >= 0 ? tables_.sphereId[std::size_t(h.sphere[k])]
                     : h.plane[k] >= 0 ? tables_.planeId[std::size_t(h.plane[k])]
                                       : kNoObject;
    }

    /// CameraModel::generateRay for eight image points (lanes past `count` repeat the first).
    Rays8 cameraRays(const float* px, const float* py, int count) const {
        const CameraModel& camera = scene_.camera();
        const Vec3 o = camera.origin(), f = camera.forward(), right = camera.right(),
                   up = camera.up();
        F8 u, v;
        for (int k = 0; k < kLanes; ++k) {
            u[k] = px[k < count ? k : 0];
            v[k] = py[k < count ? k : 0];
        }
        u = (2.0f * u * camera.invWidth() - 1.0f) * camera.halfWidth();
        v = (1.0f - 2.0f * v * camera.invHeight()) * camera.halfHeight();
        Rays8 r;
        if (camera.orthographic()) {
            r.ox = (o.x + right.x * u) + up.x * v;
            r.oy = (o.y + right.y * u) + up.y * v;
            r.oz = (o.z + right.z * u) + up.z * v;
            r.dx = splat(f.x), r.dy = splat(f.y), r.dz = splat(f.z);
        } else {
            const F8 dx = (f.x + right.x * u) + up.x * v;
            const F8 dy = (f.y + right.y * u) + up.y * v;
            const F8 dz = (f.z + right.z * u) + up.z * v;
            const F8 s = 1.0f / sqrt8(dx * dx + dy * dy + dz * dz);
            r.ox = splat(o.x), r.oy = splat(o.y), r.oz = splat(o.z);
            r.dx = dx * s, r.dy = dy * s, r.dz = dz * s;
        }
        return r;
    }

    /// Secondary rays [i, i + count) of `rays` (count <= 8, readable up to i + 8) of tree
    /// level `level`.
    void traceSecondary(const RayArrays& rays, std::size_t i, int count, int level,
                        PathNode* nodes, const RayArrays& next, std::size_t& nextCount,
                        TraceCounters& counters) const {
        Rays8 r;
        r.ox = load(rays.ox + i), r.oy = load(rays.oy + i), r.oz = load(rays.oz + i);
        r.dx = load(rays.dx + i), r.dy = load(rays.dy + i), r.dz = load(rays.dz + i);
        traceBatch(r, count, level, nullptr, nodes, next, nextCount, nullptr, nullptr, nullptr,
                   nullptr, counters);
    }

    /// Closest hits over planes then spheres, in scene order with strict comparisons, as
    /// CompiledScene::intersect and intersectFlat test them.
    void closestHit(const Rays8& r, const RaySubset* subset, Hits8& h) const {
        const PlaneBlock4* planeBlocks = subset ? subset->planes : scene_.planeBlocks().data();
        const std::size_t planeCount =
            subset ? std::size_t(subset->planeBlocks) : scene_.planeBlocks().size();
        const F8 tmin = splat(0.0f);
        F8 tmax = splat(kInfinity);
        h.plane = splatI(-1);
        h.sphere = splatI(-1);
        h.offset = splat(0.0f);
        for (std::size_t b = 0; b < planeCount; ++b) {
            const PlaneBlock4& block = planeBlocks[b];
            for (int k = 0; k < 4; ++k) {
                if (block.nx[k] == 0.0f && block.ny[k] == 0.0f && block.nz[k] == 0.0f)
                    continue;  // padding
                const F8 t = planeDistance(r, block.px[k], block.py[k], block.pz[k], block.nx[k],
                                           block.ny[k], block.nz[k]);
                const I8 m = (t > tmin) & (t < tmax);
                const int32_t index =
                    int32_t(subset ? subset->planeIndex[4 * b + std::size_t(k)] : 4 * b + std::size_t(k));
                tmax = select(m, t, tmax);
                h.plane = select(m, splatI(index), h.plane);
            }
        }
        const SphereBlock4* sphereBlocks = subset ? subset->spheres : scene_.sphereBlocks().data();
        const std::size_t sphereCount =
            subset ? std::size_t(subset->sphereBlocks) : scene_.sphereBlocks().size();
        const F8 a = r.dx * r.dx + r.dy * r.dy + r.dz * r.dz;
        for (std::size_t b = 0; b < sphereCount; ++b) {
            const SphereBlock4& block = sphereBlocks[b];
            for (int k = 0; k < 4; ++k) {
                if (std::isnan(block.radius2[k])) continue;  // padding
                F8 t, offset;
                const I8 m = sphereHit(r, a, block.cx[k], block.cy[k], block.cz[k],
                                       block.radius2[k], tmin, tmax, t, offset);
                if (!bits(m)) continue;
                tmax = select(m, t, tmax);
                h.offset = select(m, offset, h.offset);
                h.sphere = select(m, splatI(int32_t(block.prim[k])), h.sphere);
            }
        }
        h.t = tmax;
    }

    /// True in the live lanes whose shadow ray from `o` along unit `d` meets something with
    /// t in (0, tmax): the light buffer's cells of all lanes name the candidates, and each
    /// candidate gets CompiledScene::occludedToLight's exact test in every lane.
    I8 occluded(std::size_t light, const Rays8& r, F8 tmax, I8 live) const {
        const LightBuffer* buffer = scene_.lightBuffer(light);
        const auto& spheres = scene_.flatSpheres();
        const auto& planes = scene_.planes();
        uint32_t sphereMask = 0;  // flat scenes have at most 16 spheres
        uint64_t planeMask = 0;
        bool allPlanes = !buffer;
        const unsigned liveBits = bits(live);
        if (buffer) {
            // LightBuffer::cell's operations for eight origins.
            constexpr int kRes = LightBuffer::kResolution;
            const Vec3& L = buffer->light();
            const F8 vx = r.ox - L.x, vy = r.oy - L.y, vz = r.oz - L.z;
            const F8 ax = select(vx < 0.0f, -vx, vx), ay = select(vy < 0.0f, -vy, vy),
                     az = select(vz < 0.0f, -vz, vz);
            const I8 onX = (ax >= ay) & (ax >= az), onY = ~onX & (ay >= az);
            const I8 face = select(onX, select(vx < 0.0f, splatI(1), splatI(0)),
                                   select(onY, select(vy < 0.0f, splatI(3), splatI(2)),
                                          select(vz < 0.0f, splatI(5), splatI(4))));
            const F8 m = select(onX, ax, select(onY, ay, az));
            const F8 a = select(onX, vy, select(onY, vz, vx));
            const F8 b = select(onX, vz, select(onY, vx, vy));
            const F8 distance2 = vx * vx + vy * vy + vz * vz;
            if ((bits(m > 0.0f) & liveBits) != liveBits) {
                allPlanes = true;  // an origin at the light: test everything
                sphereMask = spheres.size() >= 32 ? ~0u : (1u << spheres.size()) - 1u;
            } else {
                const F8 inv = 1.0f / m;
                auto cellIndex = [](F8 u) {
                    const I8 i = __builtin_convertvector((u + 1.0f) * (0.5f * float(kRes)), I8);
                    return select(i < 0, splatI(0), select(i >= kRes, splatI(kRes - 1), i));
                };
                const I8 cell = (face * kRes + cellIndex(b * inv)) * kRes + cellIndex(a * inv);
                const uint32_t* starts = buffer->starts();
                const LightBuffer::Entry* entries = buffer->entries();
                // Neighbouring rays mostly share a cell: each distinct list is read once, with
                // the farthest origin's distance (an entry is in reach of some lane then).
                for (unsigned todo = liveBits; todo;) {
                    const int32_t c = cell[__builtin_ctz(todo)];
                    const I8 sameMask = live & (cell == c);
                    todo &= ~bits(sameMask);
                    const float farthest = maxLane(select(sameMask, distance2, splat(0.0f)));
                    for (uint32_t e = starts[c], end = starts[c + 1]; e < end; ++e) {
                        const LightBuffer::Entry& entry = entries[e];
                        if (!(farthest >= entry.minDistance2)) continue;
                        if (entry.item & LightBuffer::kPlaneBit) {
                            const uint32_t p = entry.item & ~LightBuffer::kPlaneBit;
                            if (p < 64) planeMask |= uint64_t(1) << p;
                            else allPlanes = true;
                        } else {
                            sphereMask |= 1u << entry.item;
                        }
                    }
                }
            }
        } else {
            sphereMask = spheres.size() >= 32 ? ~0u : (1u << spheres.size()) - 1u;
        }
        I8 blocked = splatI(0);
        const F8 tmin = splat(0.0f);
        const F8 a = r.dx * r.dx + r.dy * r.dy + r.dz * r.dz;
        for (; sphereMask; sphereMask &= sphereMask - 1) {
            const SphereShape& s = spheres[std::size_t(__builtin_ctz(sphereMask))];
            F8 t, offset;
            blocked |= sphereHit(r, a, s.center.x, s.center.y, s.center.z, s.radius * s.radius,
                                 tmin, tmax, t, offset);
            if ((bits(blocked) & liveBits) == liveBits) return live;
        }
        for (std::size_t i = 0; i < planes.size(); ++i) {
            if (!allPlanes && (i >= 64 || !(planeMask >> i & 1u))) continue;
            const PlaneShape& s = planes[i].shape;
            const F8 t = planeDistance(r, s.point.x, s.point.y, s.point.z, s.normal.x,
                                       s.normal.y, s.normal.z);
            blocked |= (t > tmin) & (t < tmax);
            if ((bits(blocked) & liveBits) == liveBits) return live;
        }
        return blocked & live;
    }

    /// Traces `count` rays (lanes 0..count-1 of `r`) of tree level `level`: their nodes go to
    /// `nodes`, their children to `next` from `nextCount` on (room for 2 * count more). For the camera level, `primaryIds`/`primaryNormals`
    /// (when not null) receive the first hits.
    void traceBatch(const Rays8& r, int count, int level, const RaySubset* subset,
                    PathNode* nodes, const RayArrays& next, std::size_t& nextCount,
                    ObjectId* primaryIds, Vec3* primaryNormals, float* primaryDepths,
                    Vec3* primaryPoints, TraceCounters& counters) const {
        counters.rays += uint64_t(count);
        Hits8 h;
        closestHit(r, subset, h);

        // The hit normal (raw, outward) and material of each lane; spheres' normals with the
        // operations of intersectFlat. Lanes past `count` repeat rays and are left out.
        const PacketTables& tb = tables_;
        const I8 lanes = I8{0, 1, 2, 3, 4, 5, 6, 7} < count;
        const I8 isSphere = lanes & (h.sphere >= 0);
        const I8 isPlane = lanes & ~isSphere & (h.plane >= 0);
        const I8 hitMask = isSphere | isPlane;
        const unsigned hitBits = bits(hitMask);
        const I8 si = select(isSphere, h.sphere, splatI(0));
        const I8 pi = select(isPlane, h.plane, splatI(0));
        F8 hnx, hny, hnz;
        I8 material;
        {
            const Lookup sphere = lookup(si, isSphere);
            const F8 ccx = fetch(tb.sphereX.data(), sphere), ccy = fetch(tb.sphereY.data(), sphere),
                     ccz = fetch(tb.sphereZ.data(), sphere);
            const F8 rad = select(isSphere, fetch(tb.sphereRadius.data(), sphere), splat(1.0f));
            const F8 a = r.dx * r.dx + r.dy * r.dy + r.dz * r.dz;
            const F8 tProj = ((ccx - r.ox) * r.dx + (ccy - r.oy) * r.dy + (ccz - r.oz) * r.dz) / a;
            const F8 fx = (r.ox - ccx) + tProj * r.dx;
            const F8 fy = (r.oy - ccy) + tProj * r.dy;
            const F8 fz = (r.oz - ccz) + tProj * r.dz;
            const Lookup plane = lookup(pi, isPlane);
            hnx = select(isSphere, (fx + h.offset * r.dx) / rad, fetch(tb.planeNx.data(), plane));
            hny = select(isSphere, (fy + h.offset * r.dy) / rad, fetch(tb.planeNy.data(), plane));
            hnz = select(isSphere, (fz + h.offset * r.dz) / rad, fetch(tb.planeNz.data(), plane));
            material = select(hitMask,
                              select(isSphere, fetch(tb.sphereMaterial.data(), sphere),
                                     fetch(tb.planeMaterial.data(), plane)),
                              splatI(0));
        }
        if (level == 0) {
            for (int k = 0; k < count; ++k) {
                const bool hit = hitBits >> k & 1u;
                if (primaryIds)
                    primaryIds[k] = !hit ? kNoObject
                                         : isSphere[k] ? tb.sphereId[std::size_t(si[k])]
                                                       : tb.planeId[std::size_t(pi[k])];
                if (primaryNormals)
                    primaryNormals[k] = hit ? Vec3(hnx[k], hny[k], hnz[k]) : Vec3(0.0f);
                if (primaryDepths) primaryDepths[k] = hit ? h.t[k] : kInfinity;
                if (primaryPoints)
                    primaryPoints[k] = hit ? Vec3(r.ox[k], r.oy[k], r.oz[k]) +
                                                 Vec3(r.dx[k], r.dy[k], r.dz[k]) * h.t[k]
                                           : Vec3(0.0f);
            }
        }
        if (!hitBits) {
            for (int k = 0; k < count; ++k) nodes[k] = PathNode{};
            return;
        }

        // Shading point, normal facing the ray, viewer direction (trace()).
        const F8 px = r.ox + r.dx * h.t, py = r.oy + r.dy * h.t, pz = r.oz + r.dz * h.t;
        const I8 inside = (hnx * r.dx + hny * r.dy + hnz * r.dz) > 0.0f;
        const F8 nx = select(inside, -hnx, hnx), ny = select(inside, -hny, hny),
                 nz = select(inside, -hnz, hnz);
        const F8 vx = -r.dx, vy = -r.dy, vz = -r.dz;

        // Material terms per lane.
        const auto& materials = scene_.materials();
        const Lookup mat = lookup(material, hitMask);
        const F8 colR = fetch(tb.red.data(), mat), colG = fetch(tb.green.data(), mat),
                 colB = fetch(tb.blue.data(), mat);
        const F8 diffuse = fetch(tb.diffuse.data(), mat);
        const F8 specular = fetch(tb.specular.data(), mat);
        const F8 cutoff = fetch(tb.cutoff.data(), mat);
        const F8 localWeight = select(hitMask, fetch(tb.localWeight.data(), mat), splat(0.0f));

        // Local term: localWeight * (ambient + directLight) where localWeight > 0.
        const I8 shaded = localWeight > 0.0f;
        F8 localR = splat(0.0f), localG = splat(0.0f), localB = splat(0.0f);
        I8 shadowRays = splatI(0);
        if (bits(shaded)) {
            const Color& amb = scene_.settings().ambient;
            const F8 ambR = (amb.x * colR) * diffuse, ambG = (amb.y * colG) * diffuse,
                     ambB = (amb.z * colB) * diffuse;
            Rays8 shadow;
            shadow.ox = px + nx * eps_;
            shadow.oy = py + ny * eps_;
            shadow.oz = pz + nz * eps_;
            const F8 dcR = diffuse * colR, dcG = diffuse * colG, dcB = diffuse * colB;
            F8 sumR = splat(0.0f), sumG = splat(0.0f), sumB = splat(0.0f);
            const auto& lights = scene_.lights();
            for (std::size_t li = 0; li < lights.size(); ++li) {
                const CompiledLight& light = lights[li];
                const F8 tx = light.position.x - px, ty = light.position.y - py,
                         tz = light.position.z - pz;
                const F8 dist = sqrt8(tx * tx + ty * ty + tz * tz);
                I8 live = shaded & ~(dist <= 0.0f);
                const F8 lx = tx / dist, ly = ty / dist, lz = tz / dist;
                const F8 nl = nx * lx + ny * ly + nz * lz;
                live &= ~(nl <= 0.0f);
                const F8 rx = (2.0f * nl) * nx - lx, ry = (2.0f * nl) * ny - ly,
                         rz = (2.0f * nl) * nz - lz;
                const F8 rv = rx * vx + ry * vy + rz * vz;
                F8 spec = splat(0.0f);
                const unsigned specBits =
                    bits(live & (specular > 0.0f) & (rv > cutoff) & (rv > 0.0f));
                for (unsigned m = specBits; m; m &= m - 1) {
                    const int k = __builtin_ctz(m);
                    spec[k] = materials[std::size_t(material[k])].specular *
                              std::pow(rv[k], materials[std::size_t(material[k])].shininess);
                }
                if (shadows_ && bits(live)) {
                    counters.shadowRays += uint64_t(__builtin_popcount(bits(live)));
                    shadowRays -= live;  // true lanes are -1
                    shadow.dx = lx, shadow.dy = ly, shadow.dz = lz;
                    live &= ~occluded(li, shadow, dist - eps_, live);
                }
                const F8 lsR = select(live, 0.0f + (dcR * nl + spec), splat(0.0f));
                const F8 lsG = select(live, 0.0f + (dcG * nl + spec), splat(0.0f));
                const F8 lsB = select(live, 0.0f + (dcB * nl + spec), splat(0.0f));
                // trace() divides by the sample count, 1 here: exact, so left out.
                sumR = sumR + lsR * light.power.x;
                sumG = sumG + lsG * light.power.y;
                sumB = sumB + lsB * light.power.z;
            }
            localR = select(shaded, localWeight * (ambR + sumR), splat(0.0f));
            localG = select(shaded, localWeight * (ambG + sumG), splat(0.0f));
            localB = select(shaded, localWeight * (ambB + sumB), splat(0.0f));
        }

        // Nodes and children, lane by lane (trace()'s tail).
        for (int k = 0; k < count; ++k) {
            PathNode& node = nodes[k];
            node = PathNode{};
            if (!(hitBits >> k & 1u)) continue;
            node.hit = true;
            node.t = h.t[k];
            node.shadowRays = uint32_t(shadowRays[k]);
            node.local = Color(localR[k], localG[k], localB[k]);
            const CompiledMaterial& m = materials[std::size_t(material[k])];
            node.specularMaterial = m.reflectivity > 0.0f || m.transparency > 0.0f;
            if (level >= maxDepth_ || (m.reflectivity <= 0.0f && m.transparency <= 0.0f))
                continue;
            node.specular = true;
            const Vec3 d(r.dx[k], r.dy[k], r.dz[k]);
            const Vec3 p(px[k], py[k], pz[k]);
            const Vec3 n(nx[k], ny[k], nz[k]);
            float reflectWeight = m.reflectivity;
            if (m.transparency > 0.0f) {
                const float eta = inside[k] ? m.ior : 1.0f / m.ior;
                Vec3 t;
                if (refractDir(d, n, eta, t)) {
                    const float f = schlick(-glm::dot(n, d), m.ior);
                    reflectWeight += m.transparency * f;
                    node.refractWeight = m.transparency * (1.0f - f);
                    node.refract = int32_t(nextCount);
                    next.set(nextCount++, p - n * eps_, t);
                } else {
                    reflectWeight += m.transparency;
                }
            }
            node.reflectWeight = reflectWeight;
            if (reflectWeight > 0.0f) {
                node.reflect = int32_t(nextCount);
                next.set(nextCount++, p + n * eps_, d - 2.0f * glm::dot(d, n) * n);
            }
        }
    }

private:
    const CompiledScene& scene_;
    const PacketTables& tables_;
    int maxDepth_;
    bool shadows_;
    float eps_;
};
