// DeepFrame::commit of traced camera rays, fed by hand-made tile results: every buffer of a
// traced pixel, the segment pools, the state counts and the block summaries, for a whole
// tile and for scattered pixels whose frame indices run on from one row into the next, and
// `base` written only when the result keeps it; deferred records appended (untouched pixels'
// records stay where they are) with the pool bounded by its compaction; undersampled blocks
// filling their spans, with the state counts of pixels in every state, and the summaries of
// blocks spans cover whole built from the block rays; an edit's marks applied to one block.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "session/frame/deep_frame.h"
#include "session/tile_output.h"

namespace rs {

/// The frame's own buffers, for the cases that set pixels up by hand.
struct DeepFrameTestAccess {
    static LargeVector<uint8_t>& flags(DeepFrame& f) { return f.flags_; }
    static void setState(DeepFrame& f, std::size_t i, int tile, uint8_t s) {
        f.setState(i, tile, s);
    }
};

namespace {

// One tile wide, two tiles high: the last pixel of a row and the first of the next have
// neighbouring frame indices, so a run of indices must not be taken for a run of columns.
constexpr int kWidth = 32, kHeight = 64;

/// What ray k of a result says, made up from the pixel and a salt.
struct Made {
    Color color;
    PrimaryInfo info;
    uint32_t rays;
    int segments;  ///< 0..3 secondary segments (escaping when the pixel is odd).
};

Made made(std::size_t i, int salt) {
    Made m;
    const float v = float(i) * 0.001f + float(salt);
    m.color = Color(v, v + 0.5f, v + 0.25f);
    m.info.id = ObjectId((i + std::size_t(salt)) % 5 == 0 ? kNoObject : (i % 7) + 1);
    m.info.depth = m.info.id == kNoObject ? kInfinity : 1.0f + v;
    m.info.normal = Vec3(0.0f, 1.0f, 0.0f);
    m.info.touchedSpecular = (i + std::size_t(salt)) % 3 == 0;
    m.rays = uint32_t(i % 11 + std::size_t(salt));
    m.segments = m.info.touchedSpecular ? int((i + std::size_t(salt)) % 4) : 0;
    return m;
}

TreeSegment segmentOf(std::size_t i, int salt, int s) {
    const float v = float(i) + 0.1f * float(s) + float(salt);
    return {Vec3(v, 1.0f, -2.0f), Vec3(v, 2.0f + float(s), -3.0f), uint32_t(i % 2)};
}

/// A result of tile 0 tracing `pixels` (in this order) as pass `salt` says.
TileResult resultFor(const std::vector<std::size_t>& pixels, int salt, uint64_t generation) {
    TileResult t;
    t.generation = generation;
    t.tile = 0;
    t.rect = {0, 0, 32, 32};
    t.tracedState = kBase;
    RayList& r = t.traced;
    for (const std::size_t i : pixels) {
        Ray ray;
        ray.origin = Vec3(float(i % kWidth), float(i / kWidth), 0.0f);
        ray.dir = Vec3(0.0f, 0.0f, -1.0f);
        r.add(ray, uint32_t(i), i, kTracedLastUpdate);
    }
    const std::size_t n = r.size();
    r.color.resize(n), r.info.resize(n), r.rays.resize(n);
    r.withSegments = true;
    const PerRayLists<TreeSegment> lists = r.segments.lists(n, kSegmentsPerPixel);
    {
        PerRayAppender<TreeSegment> segments(lists);
        for (std::size_t k = 0; k < n; ++k) {
            const Made m = made(r.pixel[k], salt);
            r.color[k] = m.color;
            r.info[k] = m.info;
            r.rays[k] = m.rays;
            lists.clear(k);
            for (int s = 0; s < m.segments; ++s)
                segments.append(uint32_t(k), segmentOf(r.pixel[k], salt, s));
        }
    }
    r.segments.group();
    return t;
}

/// Checks every buffer of pixel i against what pass `salt` made for it.
void expectPixel(const DeepFrame& f, std::size_t i, int salt, bool base) {
    const Made m = made(i, salt);
    SCOPED_TRACE("pixel " + std::to_string(i) + " of pass " + std::to_string(salt));
    EXPECT_EQ(f.color()[i], m.color);
    EXPECT_EQ(f.base()[i], base ? m.color : Color(0.0f));
    EXPECT_EQ(f.id()[i], m.info.id);
    EXPECT_EQ(f.depth()[i], m.info.depth);
    EXPECT_EQ(f.normal()[i], m.info.normal);
    EXPECT_EQ(f.cost()[i], m.rays);
    EXPECT_EQ(f.state()[i], kBase);
    EXPECT_EQ(f.flags()[i],
              uint8_t(kTracedLastUpdate | (m.info.touchedSpecular ? kTouchedSpecular : 0)));
    const glm::vec4 bound = m.info.id == kNoObject ? glm::vec4(0.0f, 0.0f, 0.0f, -1.0f)
                                                   : glm::vec4(float(i % kWidth), float(i / kWidth),
                                                               -m.info.depth, 0.0f);
    EXPECT_EQ(f.hitBound()[i], bound);
    ASSERT_EQ(int(f.segmentCount()[i]), m.segments);
    const auto& pool = f.tileSegments()[0];
    for (int s = 0; s < m.segments; ++s) {
        const TreeSegment want = segmentOf(i, salt, s);
        const TreeSegment& got = pool[f.segmentStart()[i] + uint32_t(s)];
        EXPECT_EQ(got.a, want.a);
        EXPECT_EQ(got.b, want.b);
        EXPECT_EQ(got.escapes, want.escapes);
    }
}

/// Live segments of tile 0 as its pixels reference them.
uint32_t referencedSegments(const DeepFrame& f) {
    uint32_t n = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) n += f.segmentCount()[f.index(x, y)];
    return n;
}

std::vector<std::size_t> wholeTile() {
    std::vector<std::size_t> pixels;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) pixels.push_back(std::size_t(y) * kWidth + std::size_t(x));
    return pixels;
}

TEST(FrameCommit, WholeTile_WritesEveryBuffer_PoolsAndSummaries) {
    DeepFrame f;
    f.resize(kWidth, kHeight);
    ASSERT_TRUE(f.commit(resultFor(wholeTile(), 1, 7), 7));
    for (const std::size_t i : wholeTile()) expectPixel(f, i, 1, true);
    EXPECT_EQ(f.tileStates()[0], (std::array<uint32_t, 4>{0, 0, 1024, 0}));
    EXPECT_EQ(f.tileStates()[1], (std::array<uint32_t, 4>{1024, 0, 0, 0}));
    EXPECT_EQ(f.tileLiveSegments()[0], referencedSegments(f));
    EXPECT_TRUE(f.summariesMatchPixels());
    // A result of another generation writes nothing.
    EXPECT_FALSE(f.commit(resultFor(wholeTile(), 2, 6), 7));
    for (const std::size_t i : wholeTile()) expectPixel(f, i, 1, true);
}

TEST(FrameCommit, ScatteredPixels_RunsEndWithTheirRow_OthersKept) {
    DeepFrame f;
    f.resize(kWidth, kHeight);
    ASSERT_TRUE(f.commit(resultFor(wholeTile(), 1, 7), 7));
    // Indices 124..131 run on from row 3 (x 28..31) into row 4 (x 0..3): different blocks.
    std::vector<std::size_t> scattered;
    for (std::size_t i = 124; i < 132; ++i) scattered.push_back(i);
    for (std::size_t i = 500; i < 517; ++i) scattered.push_back(i);
    scattered.push_back(1023);
    ASSERT_TRUE(f.commit(resultFor(scattered, 2, 7), 7));
    const std::set<std::size_t> again(scattered.begin(), scattered.end());
    for (const std::size_t i : wholeTile()) expectPixel(f, i, again.count(i) ? 2 : 1, true);
    EXPECT_EQ(f.tileStates()[0], (std::array<uint32_t, 4>{0, 0, 1024, 0}));
    EXPECT_EQ(f.tileLiveSegments()[0], referencedSegments(f));
    EXPECT_TRUE(f.summariesMatchPixels());
}

TEST(FrameCommit, BaseWrittenOnlyWhenTheResultKeepsIt) {
    DeepFrame f;
    f.resize(kWidth, kHeight);
    TileResult t = resultFor(wholeTile(), 1, 3);
    t.keepBase = false;  // A scene without supersampling: nothing reads base.
    ASSERT_TRUE(f.commit(t, 3));
    for (const std::size_t i : wholeTile()) expectPixel(f, i, 1, false);
    t = resultFor(wholeTile(), 1, 3);
    ASSERT_TRUE(f.commit(t, 3));
    for (const std::size_t i : wholeTile()) expectPixel(f, i, 1, true);
}

/// Record r of pixel i as pass `salt` made it.
ShadingRecord recordOf(std::size_t i, int salt, int r) {
    ShadingRecord rec{};
    rec.p = Vec3(float(i), float(salt), float(r));
    rec.weight = 0.5f + float(r);
    rec.seed = uint32_t(i * 31 + std::size_t(salt) * 7 + std::size_t(r));
    return rec;
}

/// resultFor() with 1..3 complete deferred records a pixel (an interactive pass's trace).
TileResult withRecords(const std::vector<std::size_t>& pixels, int salt, uint64_t generation) {
    TileResult t = resultFor(pixels, salt, generation);
    t.tracedState = kInteractive;
    RayList& r = t.traced;
    r.withRecords = true;
    const PerRayLists<ShadingRecord> lists = r.records.lists(r.size(), kRecordsPerPixel);
    {
        PerRayAppender<ShadingRecord> records(lists);
        for (std::size_t k = 0; k < r.size(); ++k) {
            lists.clear(k);
            for (int j = 0; j < int(r.pixel[k] % 3) + 1; ++j)
                records.append(uint32_t(k), recordOf(r.pixel[k], salt, j));
        }
    }
    r.records.group();
    return t;
}

void expectRecords(const DeepFrame& f, std::size_t i, int salt) {
    SCOPED_TRACE("records of pixel " + std::to_string(i) + " of pass " + std::to_string(salt));
    ASSERT_TRUE(f.flags()[i] & kDeferredValid);
    ASSERT_EQ(int(f.recordCount()[i]), int(i % 3) + 1);
    const auto& pool = f.tileRecords()[0];
    for (int j = 0; j < int(f.recordCount()[i]); ++j) {
        ASSERT_LT(f.recordStart()[i] + uint32_t(j), pool.size());
        const ShadingRecord& got = pool[f.recordStart()[i] + uint32_t(j)];
        const ShadingRecord want = recordOf(i, salt, j);
        EXPECT_EQ(got.p, want.p);
        EXPECT_EQ(got.weight, want.weight);
        EXPECT_EQ(got.seed, want.seed);
    }
}

TEST(FrameCommit, SparseRecords_AppendedWithoutMovingTheTilesOthers_PoolBounded) {
    DeepFrame f;
    f.resize(kWidth, kHeight);
    ASSERT_TRUE(f.commit(withRecords(wholeTile(), 1, 7), 7));
    for (const std::size_t i : wholeTile()) expectRecords(f, i, 1);
    const std::size_t wholeSize = f.tileRecords()[0].size();
    // A sparse commit writes its pixels' records only: every other pixel's stay where they
    // were (a commit that rebuilt the pool would cost the tile, not what it traced).
    const std::vector<uint32_t> startsBefore(f.recordStart().begin(),
                                             f.recordStart().begin() + 1024);
    const std::vector<std::size_t> few = {5, 6, 7, 300, 1000};
    ASSERT_TRUE(f.commit(withRecords(few, 2, 7), 7));
    std::size_t appended = 0;
    for (const std::size_t i : few) appended += i % 3 + 1;
    EXPECT_EQ(f.tileRecords()[0].size(), wholeSize + appended);
    const std::set<std::size_t> fewSet(few.begin(), few.end());
    int latest[1024];
    for (const std::size_t i : wholeTile()) {
        latest[i] = fewSet.count(i) ? 2 : 1;
        if (!fewSet.count(i)) {
            EXPECT_EQ(f.recordStart()[i], startsBefore[i]) << "pixel " << i;
        }
        expectRecords(f, i, latest[i]);
    }
    // Many sparse commits: the garbage is compacted away, so the pool stays within twice what
    // it kept after its last compaction plus one record a pixel, and every record is right.
    for (int pass = 3; pass < 400; ++pass) {
        std::vector<std::size_t> some;
        for (int k = 0; k < 7; ++k) some.push_back(std::size_t((pass * 131 + k * 37) % 1024));
        std::sort(some.begin(), some.end());
        some.erase(std::unique(some.begin(), some.end()), some.end());
        ASSERT_TRUE(f.commit(withRecords(some, pass, 7), 7));
        for (const std::size_t i : some) latest[i] = pass;
        EXPECT_LE(f.tileRecords()[0].size(),
                  2 * std::size_t(f.tileRecordsKept()[0]) + 1024 + 7 * 3);
    }
    EXPECT_LT(f.tileRecords()[0].size(), 3 * wholeSize);
    for (const std::size_t i : wholeTile()) expectRecords(f, i, latest[i]);
    // Pixels that stop waiting for shadows (an edit clears kDeferredValid) free their records at
    // the next compaction, and the others keep theirs.
    for (std::size_t i = 0; i < 1024; i += 2)
        DeepFrameTestAccess::flags(f)[i] &= uint8_t(~kDeferredValid);
    for (int pass = 400; pass < 800; ++pass) {
        const std::vector<std::size_t> one = {std::size_t(pass % 512) * 2 + 1};
        ASSERT_TRUE(f.commit(withRecords(one, pass, 7), 7));
        latest[one[0]] = pass;
    }
    EXPECT_LT(f.tileRecords()[0].size(), wholeSize);
    for (std::size_t i = 1; i < 1024; i += 2) expectRecords(f, i, latest[i]);
}

TEST(FrameCommit, UndersampledBlocks_FillTheirSpans_CountsFollowMixedStates) {
    DeepFrame f;
    f.resize(kWidth, kHeight);
    ASSERT_TRUE(f.commit(resultFor(wholeTile(), 1, 7), 7));  // every pixel at kBase
    // Mixed old states: some final, some stale, some interactive.
    for (std::size_t i = 0; i < 1024; i += 3) DeepFrameTestAccess::setState(f, i, 0, kFinal);
    for (std::size_t i = 1; i < 1024; i += 5) DeepFrameTestAccess::setState(f, i, 0, kStale);
    for (std::size_t i = 2; i < 1024; i += 7) DeepFrameTestAccess::setState(f, i, 0, kInteractive);
    TileResult t;
    t.generation = 7;
    t.rect = {0, 0, 32, 32};
    RayList& b = t.blocks;
    // 4x4 spans at (4, 0), (8, 8) and (28, 28); a 2x4 span at (0, 16).
    const std::vector<std::array<int, 4>> spans = {
        {4, 0, 4, 4}, {8, 8, 4, 4}, {28, 28, 4, 4}, {0, 16, 2, 4}};
    for (const auto& sp : spans) {
        Ray ray;
        ray.origin = Vec3(float(sp[0]), float(sp[1]), 0.0f);
        ray.dir = Vec3(0.0f, 0.0f, -1.0f);
        b.add(ray, 0, std::size_t(sp[1]) * kWidth + std::size_t(sp[0]),
              uint8_t(sp[2] | (sp[3] << 4)));
    }
    b.color.resize(b.size()), b.info.resize(b.size()), b.rays.resize(b.size());
    for (std::size_t k = 0; k < b.size(); ++k) {
        b.color[k] = Color(float(k) + 0.5f);
        b.info[k].id = ObjectId(k + 1);
        b.info[k].depth = 2.0f + float(k);
        b.info[k].normal = Vec3(1.0f, 0.0f, 0.0f);
        b.info[k].touchedSpecular = k == 1;
        b.rays[k] = uint32_t(10 + k);
    }
    std::array<uint32_t, 4> want = f.tileStates()[0];
    std::set<std::size_t> covered;
    for (const auto& sp : spans)
        for (int y = sp[1]; y < sp[1] + sp[3]; ++y)
            for (int x = sp[0]; x < sp[0] + sp[2]; ++x) {
                const std::size_t i = f.index(x, y);
                covered.insert(i);
                --want[f.state()[i]];
                ++want[kInteractive];
            }
    ASSERT_TRUE(f.commit(t, 7));
    for (std::size_t k = 0; k < spans.size(); ++k) {
        const auto& sp = spans[k];
        for (int y = sp[1]; y < sp[1] + sp[3]; ++y)
            for (int x = sp[0]; x < sp[0] + sp[2]; ++x) {
                const std::size_t i = f.index(x, y);
                SCOPED_TRACE("pixel " + std::to_string(i));
                EXPECT_EQ(f.color()[i], b.color[k]);
                EXPECT_EQ(f.id()[i], b.info[k].id);
                EXPECT_EQ(f.depth()[i], b.info[k].depth);
                EXPECT_EQ(f.normal()[i], b.info[k].normal);
                EXPECT_EQ(f.cost()[i], b.rays[k]);
                EXPECT_EQ(f.state()[i], kInteractive);
                EXPECT_EQ(f.flags()[i], uint8_t(kTracedLastUpdate |
                                                (k == 1 ? kTouchedSpecular | kTreeUnknown : 0)));
                EXPECT_EQ(f.hitBound()[i],
                          glm::vec4(float(sp[0]), float(sp[1]), -b.info[k].depth, 0.0f));
                EXPECT_EQ(f.segmentCount()[i], 0);
            }
    }
    for (const std::size_t i : wholeTile())
        if (!covered.count(i)) {
            ASSERT_EQ(f.color()[i], made(i, 1).color) << "pixel " << i << " outside every span";
        }
    EXPECT_EQ(f.tileStates()[0], want);
    EXPECT_EQ(f.tileLiveSegments()[0], referencedSegments(f));
    EXPECT_TRUE(f.summariesMatchPixels());
}

/// A quarter-resolution pass over all of tile 0: one 4x4 span per block ray, some misses,
/// some specular.
TileResult quarterPass(const DeepFrame& f, uint64_t generation) {
    TileResult t;
    t.generation = generation;
    t.rect = {0, 0, 32, 32};
    RayList& b = t.blocks;
    for (int y = 0; y < 32; y += 4)
        for (int x = 0; x < 32; x += 4) {
            Ray ray;
            ray.origin = Vec3(float(x), float(y), 0.0f);
            ray.dir = Vec3(0.0f, 0.0f, -1.0f);
            b.add(ray, 0, f.index(x, y), uint8_t(4 | (4 << 4)));
        }
    b.color.resize(b.size()), b.info.resize(b.size()), b.rays.resize(b.size());
    for (std::size_t k = 0; k < b.size(); ++k) {
        b.color[k] = Color(float(k));
        b.info[k].id = k % 5 == 0 ? kNoObject : ObjectId(k % 3 + 1);  // some misses
        b.info[k].depth = b.info[k].id == kNoObject ? kInfinity : 1.0f + 0.25f * float(k);
        b.info[k].normal = Vec3(0.0f, 0.0f, 1.0f);
        b.info[k].touchedSpecular = k % 7 == 3;  // some blocks specular, most not
        b.rays[k] = 1;
    }
    return t;
}

// A quarter-resolution pass over a whole tile: 4x4 spans cover every 8x8 block, so each block's
// summary is built from the block rays instead of read back; it must still describe the
// pixels (hits, misses, specular rays whose trees are not kept) after a pass that kept
// segments, and the blocks' old segments must no longer count.
TEST(FrameCommit, SpansCoveringWholeBlocks_SummariesFromTheRays_MatchThePixels) {
    DeepFrame f;
    f.resize(kWidth, kHeight);
    ASSERT_TRUE(f.commit(resultFor(wholeTile(), 1, 7), 7));  // segments and hits everywhere
    const TileSummary before = f.tileSummary()[0];
    ASSERT_TRUE(before.anySpecular);
    ASSERT_FALSE(before.segmentStarts.empty());
    ASSERT_TRUE(f.commit(quarterPass(f, 7), 7));
    EXPECT_TRUE(f.summariesMatchPixels());
    EXPECT_EQ(f.tileLiveSegments()[0], 0u);
    EXPECT_TRUE(f.tileSummary()[0].segmentStarts.empty());  // the old trees are gone
    EXPECT_TRUE(f.tileSummary()[0].anyUnknown);
    EXPECT_EQ(f.tileStates()[0][kInteractive], 1024u);
}

// Orbiting: every pixel of the tile is stale when its quarter-resolution pass commits, so the
// old states are not read but known from the tile's counts; after the first such pass no
// pixel keeps segments, so the next ones leave the counts alone. The counts, the live
// segments and the summaries must still describe the pixels, in both cases, and the old
// trees of the first must be gone.
TEST(FrameCommit, OrbitPasses_AllStaleTiles_CountsAndSegmentsKnownFromTheTile) {
    DeepFrame f;
    f.resize(kWidth, kHeight);
    ASSERT_TRUE(f.commit(resultFor(wholeTile(), 1, 7), 7));  // segments and hits everywhere
    ASSERT_GT(f.tileLiveSegments()[0], 0u);
    for (int pass = 0; pass < 2; ++pass) {
        SCOPED_TRACE("orbit pass " + std::to_string(pass));
        f.markAllStale();
        ASSERT_EQ(f.tileStates()[0][kStale], 1024u);
        ASSERT_TRUE(f.commit(quarterPass(f, 7), 7));
        const std::array<uint32_t, 4> interactive = {0, 1024, 0, 0};
        EXPECT_EQ(f.tileStates()[0], interactive);
        EXPECT_EQ(f.tileLiveSegments()[0], 0u);
        EXPECT_EQ(referencedSegments(f), 0u);
        EXPECT_TRUE(f.summariesMatchPixels());
    }
    // The second tile, never traced, is still all stale.
    EXPECT_EQ(f.tileStates()[1][kStale], 1024u);
}

// An edit's marks in one block: marked pixels go stale, lose their deferred records and get
// the re-traced overlay; the others only lose the overlay; the tile's counts follow, and
// other blocks are left alone.
TEST(FrameCommit, ApplyBlockMarks_MarkedPixelsGoStale_OthersLoseTheOverlay_CountsFollow) {
    DeepFrame f;
    f.resize(kWidth, kHeight);
    ASSERT_TRUE(f.commit(resultFor(wholeTile(), 1, 7), 7));  // kBase, overlay flag set
    for (std::size_t i = 0; i < 1024; i += 3) DeepFrameTestAccess::setState(f, i, 0, kFinal);
    for (std::size_t i = 2; i < 1024; i += 7) DeepFrameTestAccess::setState(f, i, 0, kInteractive);
    for (std::size_t i = 0; i < 1024; i += 2) DeepFrameTestAccess::flags(f)[i] |= kDeferredValid;
    const DeepFrame before = f;
    std::vector<uint8_t> mask(f.pixelCount(), 0);
    for (std::size_t i = 0; i < mask.size(); i += 5) mask[i] = 1;  // also outside the block
    const std::size_t block = 1 * std::size_t(f.blocksX()) + 2;    // pixels x 16..23, y 8..15
    f.applyBlockMarks(block, mask);
    std::array<uint32_t, 4> want = before.tileStates()[0];
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = f.index(x, y);
            SCOPED_TRACE("pixel " + std::to_string(i));
            const bool inBlock = x >= 16 && x < 24 && y >= 8 && y < 16;
            if (!inBlock) {
                EXPECT_EQ(f.state()[i], before.state()[i]);
                EXPECT_EQ(f.flags()[i], before.flags()[i]);
            } else if (mask[i]) {
                EXPECT_EQ(f.state()[i], kStale);
                EXPECT_EQ(f.flags()[i],
                          uint8_t((before.flags()[i] & ~kDeferredValid) | kTracedLastUpdate));
                --want[before.state()[i]];
                ++want[kStale];
            } else {
                EXPECT_EQ(f.state()[i], before.state()[i]);
                EXPECT_EQ(f.flags()[i], uint8_t(before.flags()[i] & ~kTracedLastUpdate));
            }
        }
    EXPECT_EQ(f.tileStates()[0], want);
    EXPECT_EQ(f.tileStates()[1], before.tileStates()[1]);
    EXPECT_TRUE(f.summariesMatchPixels());
}

// Every block of a frame whose sides are not whole blocks (the right-hand blocks are cut), with
// every state and flag combination and marks of any non-zero value (eight pixels of a block row
// go at once): the same states, flags and counts as the rule applied pixel by pixel.
TEST(FrameCommit, ApplyBlockMarks_AnyMarkValueAndCutBlocks_AsPixelByPixel) {
    DeepFrame f;
    f.resize(45, 37);
    std::vector<uint8_t> mask(f.pixelCount(), 0);
    uint32_t h = 12345;
    auto next = [&h] { return h = h * 1664525u + 1013904223u, h >> 8; };
    for (int y = 0; y < f.height(); ++y)
        for (int x = 0; x < f.width(); ++x) {
            const std::size_t i = f.index(x, y);
            DeepFrameTestAccess::setState(f, i, f.tileOf(x, y), uint8_t(next() % 4));
            DeepFrameTestAccess::flags(f)[i] = uint8_t(next() & 15);
            mask[i] = next() % 3 == 0 ? 0 : uint8_t(1u << (next() % 8));  // 1, 2, ..., 128
        }
    const DeepFrame before = f;
    for (std::size_t b = 0; b < std::size_t(f.blocksX() * f.blocksY()); ++b)
        f.applyBlockMarks(b, mask);
    std::size_t marked = 0;
    for (std::size_t i = 0; i < f.pixelCount(); ++i) {
        SCOPED_TRACE("pixel " + std::to_string(i));
        if (mask[i]) {
            ++marked;
            EXPECT_EQ(f.state()[i], kStale);
            EXPECT_EQ(f.flags()[i], markedStaleFlags(before.flags()[i]));
        } else {
            EXPECT_EQ(f.state()[i], before.state()[i]);
            EXPECT_EQ(f.flags()[i], uint8_t(before.flags()[i] & ~kTracedLastUpdate));
        }
    }
    ASSERT_GT(marked, f.pixelCount() / 2);
    std::vector<std::array<uint32_t, 4>> counts(f.tileStates().size(), std::array<uint32_t, 4>{});
    for (int y = 0; y < f.height(); ++y)
        for (int x = 0; x < f.width(); ++x)
            ++counts[std::size_t(f.tileOf(x, y))][f.state()[f.index(x, y)]];
    const std::vector<std::array<uint32_t, 4>> tileStates(f.tileStates().begin(),
                                                          f.tileStates().end());
    EXPECT_EQ(tileStates, counts);  // the tile counts follow the states
}

}  // namespace
}  // namespace rs
