// The trace kernel's level of rays (internal to trace_kernel.cpp and trace_books.cpp): the
// rays of one depth of every ray tree in a batch, as structure of arrays.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "accel/ray_engine.h"
#include "core/scratch_arena.h"
#include "integrator/trace_kernel.h"

namespace rs {

/// One level's rays as structure of arrays. The arrays only grow (reserve), and push writes
/// each field by index: no per-field capacity check, no allocation once they have grown.
struct TraceKernel::Level {
    ScratchVector<float> ox, oy, oz, dx, dy, dz, tmax, weight;
    /// Width of the ray's cone where it starts (world units): it grows by the kernel's spread
    /// per unit travelled, and a hit's width is what textures filter over.
    ScratchVector<float> cone;
    ScratchVector<uint32_t> seed, owner;
    std::size_t count = 0;

    std::size_t size() const { return count; }
    void clear() { count = 0; }
    /// Room for `n` rays in all, so that push may be called until size() == n.
    void reserve(std::size_t n) {
        if (n <= ox.size()) return;
        const std::size_t grown = std::max(n, 2 * ox.size());
        for (auto* v : {&ox, &oy, &oz, &dx, &dy, &dz, &tmax, &weight, &cone}) v->resize(grown);
        seed.resize(grown);
        owner.resize(grown);
    }
    /// Appends a ray; reserve() must have made room for it. Always inlined: the shading loop
    /// calls it for every child ray, and a call there cost some 3 % of a render.
    [[gnu::always_inline]] void push(const Vec3& o, const Vec3& d, float w, uint32_t s,
                                     uint32_t who, float width) {
        const std::size_t i = count++;
        ox[i] = o.x, oy[i] = o.y, oz[i] = o.z;
        dx[i] = d.x, dy[i] = d.y, dz[i] = d.z;
        tmax[i] = kInfinity;
        weight[i] = w;
        cone[i] = width;
        seed[i] = s;
        owner[i] = who;
    }
    /// Camera rays [begin, end) of `rays` as the level (weight 1; owner: index in `rays`;
    /// seeds of 0 when `rays.seed` is null; cones `width` wide at their origins),
    /// written field by field through local pointers.
    void setCamera(const CameraBatch& rays, std::size_t begin, std::size_t end,
                   float width = 0.0f) {
        const std::size_t n = end - begin;
        reserve(n);
        float *pox = ox.data(), *poy = oy.data(), *poz = oz.data();
        float *pdx = dx.data(), *pdy = dy.data(), *pdz = dz.data();
        for (std::size_t j = 0; j < n; ++j) {
            const Vec3 &o = rays.origin[begin + j], &d = rays.dir[begin + j];
            pox[j] = o.x, poy[j] = o.y, poz[j] = o.z;
            pdx[j] = d.x, pdy[j] = d.y, pdz[j] = d.z;
        }
        std::fill_n(tmax.data(), n, kInfinity);
        std::fill_n(weight.data(), n, 1.0f);
        std::fill_n(cone.data(), n, width);
        if (rays.seed)
            std::copy_n(rays.seed + begin, n, seed.data());
        else
            std::fill_n(seed.data(), n, 0u);
        for (std::size_t j = 0; j < n; ++j) owner[j] = uint32_t(begin + j);
        count = n;
    }
    void append(const Level& from, std::size_t begin, std::size_t end) {
        reserve(count + (end - begin));
        auto copy = [&](auto& to, const auto& src) {
            std::copy(src.begin() + std::ptrdiff_t(begin), src.begin() + std::ptrdiff_t(end),
                      to.begin() + std::ptrdiff_t(count));
        };
        copy(ox, from.ox), copy(oy, from.oy), copy(oz, from.oz);
        copy(dx, from.dx), copy(dy, from.dy), copy(dz, from.dz);
        copy(tmax, from.tmax), copy(weight, from.weight), copy(cone, from.cone);
        copy(seed, from.seed), copy(owner, from.owner);
        count += end - begin;
    }
    RayBatch batch(bool coherent) const {
        RayBatch b{ox.data(), oy.data(), oz.data(),   dx.data(),
                   dy.data(), dz.data(), tmax.data(), size()};
        b.coherent = coherent;
        return b;
    }
};

}  // namespace rs
