// Dirty-region marking: footprints, specular pixels, retinted objects, shadow-ray crossings.
#include "session/dirty_region.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "core/parallel.h"
#include "session/dirty_bounds.h"
#include "session/frame/byte_lanes.h"

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

/// Whether the ray from `from` along `dir` meets `box` within t in [0, tmax] (t in units of
/// |dir|): the core's slab test, whose rounding guard keeps the answer conservative (a box
/// the segment truly touches is never rejected), so no pixel that may change goes unmarked.
bool probeHits(const Vec3& from, const Vec3& dir, float tmax, const Aabb& box) {
    return intersectSlabs(box, Ray::make(from, dir), 0.0f, tmax);
}

/// Segment [a, b] against a box.
bool segmentHitsBox(const Vec3& a, const Vec3& b, const Aabb& box) {
    return probeHits(a, b - a, 1.0f, box);
}

Aabb grown(const Aabb& b, float r) {
    return Aabb{b.min - Vec3(r), b.max + Vec3(r)};
}

/// Can a shadow ray from anywhere in `points` to light `l` cross `region`? Segments from a
/// box to a sphere stay within (box half-diagonal + light radius) of the centre-to-centre
/// segment, so test that segment against the region grown by as much.
bool shadowsMayCross(const Aabb& points, const CompiledLight& l, const Aabb& region) {
    if (points.empty()) return false;
    const float r = 0.5f * glm::length(points.extent()) + l.radius;
    return segmentHitsBox(points.center(), l.position, grown(region, r));
}

/// Can a segment from a point of `starts` to a point of `ends` cross `region`? Such segments
/// stay within max(start radius, end radius) of the segment joining the two box centres.
bool segmentsMayCross(const Aabb& starts, const Aabb& ends, const Aabb& region) {
    if (starts.empty() || ends.empty()) return false;
    Aabb hull = starts;  // Every such segment lies in the box around both boxes.
    hull.expand(ends);
    if (!hull.overlaps(region)) return false;
    const float r = 0.5f * std::max(glm::length(starts.extent()), glm::length(ends.extent()));
    return segmentHitsBox(starts.center(), ends.center(), grown(region, r));
}

/// Everything marking needs, computed once per edit.
struct MarkContext {
    const SceneEdit& edit;
    const DeepFrame& frame;
    const std::vector<CompiledLight>& lights;
    std::vector<PixelRect> footprints;
    bool shadows;
    std::vector<Aabb> regions;       ///< The edit's regions, overlapping ones merged.
    std::vector<ShadowCone> cones;   ///< Per (region, light), region-major.
    std::vector<Aabb> grownRegions;  ///< Per (region, light): grown by the light's radius.
    bool segments = true;            ///< Test secondary segments against the regions themselves.
    const CameraModel* camera = nullptr;
    float lightSlack = 0.0f;  ///< Rounding allowance of the light-facing test (scene scale).
};

/// Whether a changed light can add to pixel i: unless the pixel sees only one shading point
/// (no mirror or glass in its tree, one sample) and every changed light sphere lies wholly
/// below that point's horizon, where the integrator adds nothing (n . l <= 0 for every
/// sample) or outside its spot cone, the pixel is marked. Background pixels see no light.
bool lightMayChange(const MarkContext& c, std::size_t i) {
    const DeepFrame& f = c.frame;
    if (f.id()[i] == kNoObject && f.sampleCount()[i] == 0) return false;
    const glm::vec4 hb = f.hitBound()[i];
    if ((f.flags()[i] & (kTouchedSpecular | kTreeUnknown)) || f.sampleCount()[i] > 0 ||
        hb.w != 0.0f)
        return true;
    const Vec3 p(hb);
    const Vec3 toEye = c.camera->orthographic() ? -c.camera->forward() : c.camera->origin() - p;
    Vec3 ns;
    if (!faceViewer(f.normal()[i], toEye, ns)) return true;  // Grazing: either side.
    for (const LightSphere& l : c.edit.lights)
        if (lightMayReach(p, ns, l, c.lightSlack)) return true;
    return false;
}

/// Merges overlapping boxes (a drag step's old and new bounds nearly coincide): fewer tests,
/// and the union still contains both.
std::vector<Aabb> mergeOverlapping(std::vector<Aabb> boxes) {
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t i = 0; i < boxes.size() && !merged; ++i)
            for (std::size_t j = i + 1; j < boxes.size() && !merged; ++j)
                if (boxes[i].overlaps(boxes[j])) {
                    boxes[i].expand(boxes[j]);
                    boxes.erase(boxes.begin() + long(j));
                    merged = true;
                }
    }
    return boxes;
}

/// Whether any of the pixel's secondary segments (or shadow rays from their end points) can
/// reach an edited region.
bool treeMayCross(const MarkContext& c, std::size_t i, int tile) {
    if (c.frame.flags()[i] & kTreeUnknown) return true;
    const auto& pool = c.frame.tileSegments()[std::size_t(tile)];
    const uint32_t start = c.frame.segmentStart()[i];
    for (uint32_t k = 0; k < c.frame.segmentCount()[i]; ++k) {
        const TreeSegment& s = pool[start + k];
        // Cheap rejections first (no divisions): the segment's own box, the light cones.
        Aabb span;
        span.expand(s.a);
        if (!s.escapes) span.expand(s.b);
        for (const Aabb& region : c.regions) {
            if (!c.segments) break;
            if (!s.escapes && !span.overlaps(region)) continue;
            const bool hits = s.escapes ? probeHits(s.a, s.b, kInfinity, region)
                                        : probeHits(s.a, s.b - s.a, 1.0f, region);
            if (hits) return true;
        }
        if (!c.shadows || s.escapes) continue;
        for (std::size_t li = 0; li < c.lights.size(); ++li)
            for (std::size_t r = 0; r < c.regions.size(); ++r)
                if (c.cones[r * c.lights.size() + li].mayContain(s.b, 0.0f) &&
                    probeHits(s.b, c.lights[li].position - s.b, 1.0f,
                              c.grownRegions[r * c.lights.size() + li]))
                    return true;
    }
    return false;
}

/// Whether a ray of pixel i may have left the scene: its centre ray missed, one of its
/// supersamples missed, or a secondary ray of its tree escaped.
bool seesEnvironment(const DeepFrame& f, std::size_t i, int tile) {
    if (f.id()[i] == kNoObject || (f.sampleCount()[i] > 0 && (f.flags()[i] & kSampleMissed)))
        return true;
    if (!(f.flags()[i] & kTouchedSpecular)) return false;
    if (f.flags()[i] & kTreeUnknown) return true;
    const auto& pool = f.tileSegments()[std::size_t(tile)];
    for (uint32_t k = 0; k < f.segmentCount()[i]; ++k)
        if (pool[f.segmentStart()[i] + k].escapes) return true;
    return false;
}

/// Which per-pixel tests a tile needs; all false: no pixel of the tile can be affected.
struct TileTests {
    bool footprint = false, retint = false, primaryShadow = false, tree = false, light = false;
    bool environment = false;
    bool any() const {
        return footprint || retint || primaryShadow || tree || light || environment;
    }
};

TileTests tileTests(const MarkContext& c, const PixelRect& r, const TileSummary& t) {
    TileTests tests;
    tests.retint = !c.edit.retinted.empty();
    tests.light = !c.edit.lights.empty();
    tests.environment = c.edit.environment;
    for (const PixelRect& f : c.footprints)
        if (f.x0 < r.x1 && r.x0 < f.x1 && f.y0 < r.y1 && r.y0 < f.y1) tests.footprint = true;
    // Each slab test is preceded by the division-free light-cone test of its points.
    auto coneMayContain = [&](std::size_t r, std::size_t li, const Aabb& points) {
        return !points.empty() && c.cones[r * c.lights.size() + li].mayContain(
                                      points.center(), 0.5f * glm::length(points.extent()));
    };
    for (std::size_t r = 0; r < c.regions.size(); ++r) {
        const Aabb& region = c.regions[r];
        if (c.shadows && !tests.primaryShadow)
            for (std::size_t li = 0; li < c.lights.size(); ++li)
                if (coneMayContain(r, li, t.hitBox) &&
                    shadowsMayCross(t.hitBox, c.lights[li], region))
                    tests.primaryShadow = true;
        if (!t.anySpecular || tests.tree) continue;
        if (t.anyUnknown ||
            (c.segments &&
             (t.anyEscape || segmentsMayCross(t.segmentStarts, t.segmentEnds, region))))
            tests.tree = true;
        if (c.shadows && !tests.tree)
            for (std::size_t li = 0; li < c.lights.size(); ++li)
                if (coneMayContain(r, li, t.segmentEnds) &&
                    shadowsMayCross(t.segmentEnds, c.lights[li], region))
                    tests.tree = true;
    }
    if (tests.retint && t.anySpecular) tests.tree = true;
    return tests;
}

/// Whether block `r` lies wholly inside one of the edit's footprints (each of its pixels may
/// change, whatever its other tests say).
bool insideFootprint(const MarkContext& c, const PixelRect& r) {
    for (const PixelRect& f : c.footprints)
        if (f.x0 <= r.x0 && r.x1 <= f.x1 && f.y0 <= r.y0 && r.y1 <= f.y1) return true;
    return false;
}

/// What marking found in a block: no pixel, some, or every pixel (then growing needs no look
/// at its neighbours).
enum BlockMarks : uint8_t { kNone = 0, kSome = 1, kWhole = 2 };

bool pixelMayChange(const MarkContext& c, const TileTests& tests, int x, int y, int tile) {
    const std::size_t i = c.frame.index(x, y);
    if (tests.footprint)
        for (const PixelRect& f : c.footprints)
            if (x >= f.x0 && x < f.x1 && y >= f.y0 && y < f.y1) return true;
    if (tests.retint) {
        for (ObjectId id : c.edit.retinted)
            if (c.frame.id()[i] == id) return true;
        // The id is the centre sample's; a supersampled pixel also averages samples that
        // may have hit a retinted object: one whose samples hit some other object.
        if (c.frame.sampleCount()[i] > 0 && (c.frame.flags()[i] & kSampleOtherObject)) return true;
    }
    if (tests.tree && (c.frame.flags()[i] & kTouchedSpecular)) {
        // A retinted object may be seen in a mirror: then any specular pixel.
        if (!c.edit.retinted.empty() || treeMayCross(c, i, tile)) return true;
    }
    if (tests.light && lightMayChange(c, i)) return true;
    if (tests.environment && seesEnvironment(c.frame, i, tile)) return true;
    const glm::vec4 hb = c.frame.hitBound()[i];
    if (tests.primaryShadow && hb.w >= 0.0f) {
        // Any segment from the hit points to any point of a light stays within
        // (hit radius + light radius) of the centre-to-centre segment.
        const Vec3 p(hb);
        for (std::size_t li = 0; li < c.lights.size(); ++li) {
            for (std::size_t r = 0; r < c.regions.size(); ++r) {
                if (!c.cones[r * c.lights.size() + li].mayContain(p, hb.w)) continue;
                const Aabb& g = c.grownRegions[r * c.lights.size() + li];
                if (probeHits(p, c.lights[li].position - p, 1.0f, hb.w > 0.0f ? grown(g, hb.w) : g))
                    return true;
            }
        }
    }
    return false;
}

/// Zeroes the pixels of `blocks` (block indices in increasing order) in a frame-sized byte
/// buffer, row-major like `frame`: neighbouring blocks of a block row are cleared together,
/// a pixel row at a time (a footprint's blocks come in long runs).
void clearBlocks(std::vector<uint8_t>& v, const DeepFrame& frame, const std::vector<int>& blocks) {
    const int B = DeepFrame::kBlock, bxs = frame.blocksX();
    for (std::size_t k = 0; k < blocks.size();) {
        const int first = blocks[k], row = first / bxs;
        std::size_t e = k + 1;
        while (e < blocks.size() && blocks[e] == blocks[e - 1] + 1 && blocks[e] / bxs == row) ++e;
        const int x0 = (first % bxs) * B,
                  x1 = std::min(frame.width(), (blocks[e - 1] % bxs + 1) * B);
        for (int y = row * B; y < std::min(frame.height(), (row + 1) * B); ++y)
            std::memset(v.data() + frame.index(x0, y), 0, std::size_t(x1 - x0));
        k = e;
    }
}

/// Sets the n bytes at p to 1: a whole block row in one store.
void markRow(uint8_t* p, int n) {
    if (n == DeepFrame::kBlock) {
        constexpr uint64_t ones = 0x0101010101010101ull;
        std::memcpy(p, &ones, sizeof ones);
    } else {
        std::memset(p, 1, std::size_t(n));
    }
}

/// Makes `mask` an empty marking of `frame`: only the previous marking's blocks are cleared
/// when it was for a frame of the same sides.
void resetMask(DirtyMask& mask, const DeepFrame& frame) {
    const std::size_t blockCount = std::size_t(frame.blocksX()) * std::size_t(frame.blocksY());
    if (mask.width != frame.width() || mask.height != frame.height() ||
        mask.pixels.size() != frame.pixelCount() || mask.touched.size() != blockCount) {
        mask.width = frame.width();
        mask.height = frame.height();
        mask.pixels.assign(frame.pixelCount(), 0);
        mask.touched.assign(blockCount, 0);
    } else {
        clearBlocks(mask.pixels, frame, mask.blocks);
        for (const int b : mask.blocks) mask.touched[std::size_t(b)] = 0;
    }
    mask.blocks.clear();
}

/// Marks every pixel of the frame `mask` was reset for.
std::size_t markEverything(DirtyMask& mask) {
    mask.blocks.resize(mask.touched.size());  // Before any mark is written.
    for (std::size_t b = 0; b < mask.blocks.size(); ++b) mask.blocks[b] = int(b);
    std::fill(mask.touched.begin(), mask.touched.end(), 1);
    std::fill(mask.pixels.begin(), mask.pixels.end(), 1);
    return mask.pixels.size();
}

/// Fills in what marking `c.edit` in `scope` needs: false when the scope leaves nothing to
/// mark.
bool prepareContext(MarkContext& c, const CompiledScene& after, MarkScope scope) {
    const SceneEdit& edit = c.edit;
    c.camera = &after.camera();
    c.lightSlack = 1e-4f * std::max(1.0f, glm::length(after.sceneBounds().extent()));
    if (scope == MarkScope::WithoutShadows) c.shadows = false;
    if (scope == MarkScope::ShadowsOnly) {
        // Retints, light and environment edits are never deferred.
        if (!c.shadows || !edit.retinted.empty() || !edit.lights.empty() || edit.environment)
            return false;
        c.segments = false;
    }
    c.regions = mergeOverlapping(edit.regions);
    if (scope != MarkScope::ShadowsOnly)
        for (const Aabb& box : edit.regions)
            c.footprints.push_back(screenFootprint(after.camera(), box));
    for (const Aabb& box : c.regions) {
        for (const CompiledLight& l : c.lights) {
            c.cones.push_back(makeCone(l, box));
            c.grownRegions.push_back(grown(box, l.radius));
        }
    }
    return true;
}

/// How many blocks and pixels marking looked at.
struct Looked {
    std::size_t blocks = 0, pixels = 0;
};

/// Marks into `core` (frame-sized, zero) the pixels that may change, and each block's
/// BlockMarks into `blockMarked`. A tile whose summary (the union of its blocks') passes no
/// test is skipped whole.
Looked markCore(const MarkContext& c, std::vector<uint8_t>& core,
                std::vector<uint8_t>& blockMarked) {
    const DeepFrame& frame = c.frame;
    const int w = frame.width(), h = frame.height();
    const int blocksX = frame.blocksX(), blocksY = frame.blocksY();
    const int B = DeepFrame::kBlock, T = frame.tileSize(), perTile = T / B;
    std::atomic<std::size_t> blocksTested{0}, pixelsTested{0};
    parallelForIndex(0, frame.tilesX() * frame.tilesY(), [&](int t) {
        const int tx = t % frame.tilesX(), ty = t / frame.tilesX();
        const PixelRect tr{tx * T, ty * T, std::min(w, (tx + 1) * T), std::min(h, (ty + 1) * T)};
        if (!tileTests(c, tr, frame.tileSummary()[std::size_t(t)]).any()) return;
        std::size_t tested = 0, pixels = 0;
        for (int by = ty * perTile; by < std::min(blocksY, (ty + 1) * perTile); ++by) {
            for (int bx = tx * perTile; bx < std::min(blocksX, (tx + 1) * perTile); ++bx) {
                const int b = by * blocksX + bx;
                const PixelRect r{bx * B, by * B, std::min(w, (bx + 1) * B),
                                  std::min(h, (by + 1) * B)};
                const TileTests tests = tileTests(c, r, frame.blockSummary()[std::size_t(b)]);
                ++tested;
                if (!tests.any()) continue;
                if (tests.footprint && insideFootprint(c, r)) {
                    // Every pixel passes its first test: no need to ask each one.
                    for (int y = r.y0; y < r.y1; ++y)
                        markRow(core.data() + frame.index(r.x0, y), r.x1 - r.x0);
                    blockMarked[std::size_t(b)] = kWhole;
                    continue;
                }
                bool any = false;
                pixels += std::size_t(r.area());
                for (int y = r.y0; y < r.y1; ++y)
                    for (int x = r.x0; x < r.x1; ++x)
                        if (pixelMayChange(c, tests, x, y, t)) core[frame.index(x, y)] = any = true;
                blockMarked[std::size_t(b)] = any ? kSome : kNone;
            }
        }
        blocksTested += tested;
        pixelsTested += pixels;
    });
    return {blocksTested.load(), pixelsTested.load()};
}

/// The blocks next to (or at) a marked one, in increasing order: only those can get a mark.
std::vector<int> blocksNearMarks(const std::vector<uint8_t>& blockMarked, int blocksX,
                                 int blocksY) {
    const int blocks = blocksX * blocksY;
    std::vector<uint8_t> near(std::size_t(blocks), 0);
    for (int b = 0; b < blocks; ++b) {
        if (!blockMarked[std::size_t(b)]) continue;
        const int bx = b % blocksX, by = b / blocksX;
        for (int ny = std::max(0, by - 1); ny <= std::min(blocksY - 1, by + 1); ++ny)
            for (int nx = std::max(0, bx - 1); nx <= std::min(blocksX - 1, bx + 1); ++nx)
                near[std::size_t(ny * blocksX + nx)] = 1;
    }
    std::vector<int> nearBlocks;
    for (int b = 0; b < blocks; ++b)
        if (near[std::size_t(b)]) nearBlocks.push_back(b);
    return nearBlocks;
}

/// Grows the marks of `core` to their 8 neighbours into `mask` over mask.blocks; returns the
/// pixels marked, and adds the pixels looked at to `pixelsGrown`.
std::size_t growMarks(const DeepFrame& frame, const std::vector<uint8_t>& core,
                      const std::vector<uint8_t>& blockMarked, DirtyMask& mask,
                      std::size_t& pixelsGrown) {
    const int w = frame.width(), h = frame.height(), blocksX = frame.blocksX();
    const int B = DeepFrame::kBlock;
    std::atomic<std::size_t> count{0}, grownPixels{0};
    parallelForIndex(0, int(mask.blocks.size()), [&](int k) {
        const int b = mask.blocks[std::size_t(k)];
        const int bx = b % blocksX, by = b / blocksX;
        mask.touched[std::size_t(b)] = 1;
        const int y1 = std::min(h, (by + 1) * B), x1 = std::min(w, (bx + 1) * B);
        if (blockMarked[std::size_t(b)] == kWhole) {
            // Every pixel is marked itself, so its grown mark is too.
            for (int y = by * B; y < y1; ++y)
                markRow(mask.pixels.data() + frame.index(bx * B, y), x1 - bx * B);
            count += std::size_t(y1 - by * B) * std::size_t(x1 - bx * B);
            return;
        }
        const std::size_t local =
            growBlockMarks(core.data(), w, h, bx * B, by * B, mask.pixels.data());
        count += local;
        grownPixels += std::size_t(y1 - by * B) * std::size_t(x1 - bx * B);
    });
    pixelsGrown = grownPixels.load();
    return count.load();
}

}  // namespace

std::size_t growBlockMarks(const uint8_t* core, int width, int height, int x0, int y0,
                           uint8_t* out) {
    const int B = DeepFrame::kBlock;
    const int x1 = std::min(width, x0 + B), y1 = std::min(height, y0 + B);
    const std::size_t w = std::size_t(width);
    std::size_t count = 0;
    for (int y = y0; y < y1; ++y) {
        const int ya = std::max(0, y - 1), yb = std::min(height - 1, y + 1);
        uint8_t* row = out + std::size_t(y) * w;
        if (x1 - x0 == B) {
            // The OR of the three rows, then of each byte with its two neighbours: a shift
            // each way moves byte k-1 and byte k+1 onto byte k; the pixels left and right of
            // the block reach only its first and last byte.
            static_assert(DeepFrame::kBlock == 8);
            uint64_t v = 0;
            uint8_t left = 0, right = 0;
            for (int yy = ya; yy <= yb; ++yy) {
                const uint8_t* p = core + std::size_t(yy) * w + std::size_t(x0);
                uint64_t word;
                std::memcpy(&word, p, sizeof word);
                v |= word;
                if (x0 > 0) left |= p[-1];
                if (x1 < width) right |= p[B];
            }
            const uint64_t d = v | (v << 8) | (v >> 8) | uint64_t(left) | (uint64_t(right) << 56);
            std::memcpy(row + x0, &d, sizeof d);
            count += lanes::sumOfBytes(d);
            continue;
        }
        for (int x = x0; x < x1; ++x) {
            uint8_t d = 0;
            for (int yy = ya; yy <= yb; ++yy)
                for (int xx = std::max(0, x - 1); xx <= std::min(width - 1, x + 1); ++xx)
                    d |= core[std::size_t(yy) * w + std::size_t(xx)];
            row[x] = d;
            count += d;
        }
    }
    return count;
}

std::size_t markDirtyPixels(const SceneEdit& edit, const CompiledScene& after,
                            const DeepFrame& frame, DirtyMask& mask, MarkScope scope,
                            MarkStats* stats) {
    if (stats) *stats = MarkStats{};
    resetMask(mask, frame);
    if (edit.everything) return markEverything(mask);
    if (!edit.traced()) return 0;

    MarkContext c{edit, frame, after.lights(), {}, after.settings().shadowSamples > 0, {}, {}, {}};
    if (!prepareContext(c, after, scope)) return 0;

    // Mark, then grow each mark to its 8 neighbours (a neighbour's change can flip an
    // adaptive supersampling decision). Growing visits only blocks next to marked ones.
    const int blocks = frame.blocksX() * frame.blocksY();
    std::vector<uint8_t> blockMarked(std::size_t(blocks), 0);
    // The marks before growing. Reused between edits and zero between them: each marking
    // clears the blocks it marked, not the frame. Bound to references here because a
    // thread_local named inside the worker lambdas would be each worker's own.
    thread_local std::vector<uint8_t> coreBuffer;
    thread_local bool coreBufferZero = false;  // False while a marking (or a throw) left marks.
    std::vector<uint8_t>& core = coreBuffer;
    bool& coreZero = coreBufferZero;
    if (!coreZero || core.size() != mask.pixels.size()) core.assign(mask.pixels.size(), 0);
    coreZero = false;
    const Looked looked = markCore(c, core, blockMarked);
    // Before any mark is written (the mask's invariant).
    mask.blocks = blocksNearMarks(blockMarked, frame.blocksX(), frame.blocksY());
    std::size_t pixelsGrown = 0;
    const std::size_t count = growMarks(frame, core, blockMarked, mask, pixelsGrown);
    // Only blocks with a mark wrote to `core`.
    std::vector<int> markedBlocks;
    for (int b = 0; b < blocks; ++b)
        if (blockMarked[std::size_t(b)] != kNone) markedBlocks.push_back(b);
    clearBlocks(core, frame, markedBlocks);
    coreZero = true;
    if (stats) {
        stats->blocksTested = looked.blocks;
        stats->blocksGrown = mask.blocks.size();
        stats->pixelsTested = looked.pixels;
        stats->pixelsGrown = pixelsGrown;
    }
    return count;
}

}  // namespace rs
