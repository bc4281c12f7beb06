// The trace kernel picks one of its shadeLevel instances per call from what the caller asks
// for (bookkeeping outputs or not, mirror and glass shown as Lambert or not). Asking for more
// outputs must never change a pixel: the colour-only instance and the instance that also
// counts rays, keeps segments and records and the first hits give the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <vector>

#include "integrator/sampling.h"
#include "integrator/trace_kernel.h"
#include "pixel_rays.h"
#include "snapshot/compiled_scene.h"
#include "test_scenes.h"

namespace rs {
namespace {

uint32_t bitsOf(float v) {
    return std::bit_cast<uint32_t>(v);
}

TEST(TraceKernelInstances, AskingForBookkeepingOutputsLeavesEveryPixelsBits) {
    // The small room without its back wall (rays that miss meet a coloured background), a glass
    // ball with no local share (no shading point of its own unless shown as Lambert), a mirror, a
    // point light and a sampled sphere light.
    SceneDocument doc = test::smallRoom(40, 30);
    doc.render.background = Color(0.2f, 0.3f, 0.5f);
    doc.render.shadowSamples = 4;
    doc.objects.eraseIf([](const Object& o) { return o.name == "back"; });
    test::addSphereLight(doc, "sphere", Vec3(2, 2.5f, -4));
    for (EngineKind engine : {EngineKind::Embree, EngineKind::Builtin}) {
        const CompiledScene scene(doc, nullptr, engine);
        const test::PixelRays pixels(scene, doc.render.width, doc.render.height);
        const std::size_t n = pixels.size();
        const CameraBatch rays = pixels.batch();
        std::vector<TraceOptions> optionSets(6, TraceOptions::fromSettings(doc.render));
        optionSets[1].shadows = ShadowQuality::HardOnly;
        optionSets[2].shadows = ShadowQuality::Off;
        optionSets[3].shadows = ShadowQuality::Deferred;
        optionSets[4].reflectionAsDiffuse = optionSets[4].refractionAsDiffuse = true;
        optionSets[5].refractionAsDiffuse = true, optionSets[5].shadows = ShadowQuality::Deferred;
        for (std::size_t o = 0; o < optionSets.size(); ++o) {
            const TraceKernel kernel(scene, optionSets[o]);
            std::vector<Color> plain(n), kept(n);
            TraceCounters plainCounters, keptCounters;
            TraceOutput colourOnly;
            colourOnly.color = plain.data();
            ASSERT_TRUE(kernel.trace(rays, colourOnly, plainCounters));

            std::vector<PrimaryInfo> primary(n);
            std::vector<uint32_t> rayCounts(n);
            PerRayStorage<ShadingRecord> records;
            PerRayStorage<TreeSegment> segments;
            TraceOutput all;
            all.color = kept.data();
            all.primary = primary.data();
            all.rays = rayCounts.data();
            all.records = records.lists(n, 8);
            all.segments = segments.lists(n, 16);
            ASSERT_TRUE(kernel.trace(rays, all, keptCounters));

            std::vector<ObjectId> ids(n);
            kernel.firstHits(rays, ids.data());
            uint64_t counted = 0;
            std::size_t missed = 0, recorded = 0;
            for (std::size_t i = 0; i < n; ++i) {
                ASSERT_EQ(bitsOf(plain[i].x), bitsOf(kept[i].x))
                    << "pixel " << i << " options " << o;
                ASSERT_EQ(bitsOf(plain[i].y), bitsOf(kept[i].y))
                    << "pixel " << i << " options " << o;
                ASSERT_EQ(bitsOf(plain[i].z), bitsOf(kept[i].z))
                    << "pixel " << i << " options " << o;
                ASSERT_EQ(primary[i].id, ids[i]) << "pixel " << i << " options " << o;
                counted += rayCounts[i];
                missed += ids[i] == kNoObject;
                recorded += records.count[i];
            }
            // Both calls traced the same rays; the per-pixel counts add up to them.
            EXPECT_EQ(plainCounters.rays, keptCounters.rays) << "options " << o;
            EXPECT_EQ(plainCounters.shadowRays, keptCounters.shadowRays) << "options " << o;
            EXPECT_EQ(counted, keptCounters.total()) << "options " << o;
            EXPECT_GT(missed, n / 20) << "options " << o;  // the background is seen
            EXPECT_LT(missed, n / 2) << "options " << o;
            if (optionSets[o].shadows == ShadowQuality::Deferred)
                EXPECT_GT(recorded, n / 4) << "options " << o;
            else
                EXPECT_EQ(recorded, 0u) << "options " << o;
        }
    }
}

}  // namespace
}  // namespace rs
