// Dirty-region marking: footprints, specular pixels, retinted objects, shadow-ray crossings.
#include "session/dirty_region.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace rs {

PixelRect screenFootprint(const CameraModel& camera, const Aabb& box) {
    const PixelRect all{0, 0, camera.width(), camera.height()};
    if (box.empty()) return {};
    float minX = kInfinity, minY = kInfinity, maxX = -kInfinity, maxY = -kInfinity;
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                          (i & 4) ? box.max.z : box.min.z);
        float px, py;
        if (!camera.project(corner, px, py)) return all;  // Reaches behind the eye.
        minX = std::min(minX, px);
        maxX = std::max(maxX, px);
        minY = std::min(minY, py);
        maxY = std::max(maxY, py);
    }
    PixelRect r;
    r.x0 = std::max(0, int(std::floor(minX)) - 1);
    r.y0 = std::max(0, int(std::floor(minY)) - 1);
    r.x1 = std::min(camera.width(), int(std::floor(maxX)) + 2);
    r.y1 = std::min(camera.height(), int(std::floor(maxY)) + 2);
    return r;
}

namespace {

/// Segment [a, b] against a box: a slab test on the parametric range [0, 1].
bool segmentHitsBox(const Vec3& a, const Vec3& b, const Aabb& box) {
    const Vec3 d = b - a;
    float t0 = 0.0f, t1 = 1.0f;
    for (int k = 0; k < 3; ++k) {
        if (std::abs(d[k]) < 1e-12f) {
            if (a[k] < box.min[k] || a[k] > box.max[k]) return false;
            continue;
        }
        const float inv = 1.0f / d[k];
        float tn = (box.min[k] - a[k]) * inv, tf = (box.max[k] - a[k]) * inv;
        if (tn > tf) std::swap(tn, tf);
        t0 = std::max(t0, tn);
        t1 = std::min(t1, tf);
        if (t0 > t1) return false;
    }
    return true;
}

Aabb grown(const Aabb& b, float r) { return Aabb{b.min - Vec3(r), b.max + Vec3(r)}; }

}  // namespace

std::size_t markDirtyPixels(const SceneEdit& edit, const CompiledScene& after,
                            const DeepFrame& frame, std::vector<uint8_t>& mask) {
    const int w = frame.width, h = frame.height;
    mask.assign(frame.pixelCount(), 0);
    if (edit.everything) {
        std::fill(mask.begin(), mask.end(), 1);
        return mask.size();
    }
    if (edit.regions.empty() && edit.retinted.empty()) return 0;

    std::vector<PixelRect> footprints;
    for (const Aabb& box : edit.regions) footprints.push_back(screenFootprint(after.camera(), box));
    const bool shadows = after.settings().shadowSamples > 0 && !edit.regions.empty();
    const auto& lights = after.lights();

    std::vector<uint8_t> core(mask.size(), 0);
    tbb::parallel_for(0, h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = frame.index(x, y);
            bool dirty = (frame.flags[i] & kTouchedSpecular) != 0;
            for (std::size_t k = 0; !dirty && k < footprints.size(); ++k) {
                const PixelRect& r = footprints[k];
                dirty = x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
            }
            for (std::size_t k = 0; !dirty && k < edit.retinted.size(); ++k)
                dirty = frame.id[i] == edit.retinted[k];
            const glm::vec4 hb = frame.hitBound[i];
            if (!dirty && shadows && hb.w >= 0.0f) {
                // Any segment from the hit points to any point of a light stays within
                // (hit radius + light radius) of the centre-to-centre segment.
                const Vec3 c(hb);
                for (std::size_t l = 0; !dirty && l < lights.size(); ++l)
                    for (std::size_t k = 0; !dirty && k < edit.regions.size(); ++k)
                        dirty = segmentHitsBox(c, lights[l].position,
                                               grown(edit.regions[k], hb.w + lights[l].radius));
            }
            core[i] = dirty;
        }
    });
    // Grow by one pixel: a neighbour's change can flip an adaptive supersampling decision.
    std::atomic<std::size_t> count{0};
    tbb::parallel_for(0, h, [&](int y) {
        std::size_t local = 0;
        for (int x = 0; x < w; ++x) {
            uint8_t d = 0;
            for (int dy = -1; dy <= 1 && !d; ++dy)
                for (int dx = -1; dx <= 1 && !d; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx >= 0 && ny >= 0 && nx < w && ny < h) d = core[frame.index(nx, ny)];
                }
            mask[frame.index(x, y)] = d;
            local += d;
        }
        count += local;
    });
    return count.load();
}

}  // namespace rs
