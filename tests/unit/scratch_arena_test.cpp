// Per-thread scratch arenas: blocks come from a huge-page-advised arena of the calling thread,
// the trace kernel's workspace lives there, and frees from anywhere and thread exits are safe.
#include "core/scratch_arena.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "integrator/trace_kernel.h"
#include "pixel_rays.h"
#include "snapshot/compiled_scene.h"
#include "test_scenes.h"
#include "vm_flags.h"

namespace rs {
namespace {

/// Runs `f` on a new thread (a fresh arena, as a tile worker's first tile has) and waits.
template <class F>
void onNewThread(F&& f) {
    std::thread t(std::forward<F>(f));
    t.join();
}

TEST(ScratchArena, BlocksComeFromTheThreadsHugePageAdvisedArena) {
    if (!kScratchArenas) GTEST_SKIP() << "sanitizer build: scratch comes from std::allocator";
    onNewThread([] {
        EXPECT_EQ(scratchBytesUsed(), 0u);
        ScratchVector<float> v(1000, 1.0f);
        ScratchVector<uint8_t> bytes(3);
        EXPECT_TRUE(scratchOwns(v.data()));
        EXPECT_TRUE(scratchOwns(bytes.data()));
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % 64, 0u);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(bytes.data()) % 64, 0u);
        EXPECT_GE(scratchBytesUsed(), 1000 * sizeof(float) + 3);
#if defined(__linux__)
        if (test::kernelHasHugePages()) {
            const std::string flags = test::vmFlagsOf(v.data());
            EXPECT_NE(flags.find(" hg"), std::string::npos) << "VmFlags: " << flags;
        }
#endif
    });
}

TEST(ScratchArena, TraceKernelWorkspaceLivesInTheArena) {
    if (!kScratchArenas) GTEST_SKIP() << "sanitizer build: scratch comes from std::allocator";
    SceneDocument doc = test::smallRoom(40, 30);
    doc.render.shadowSamples = 4;
    test::addSphereLight(doc, "sphere", Vec3(2, 2.5f, -4));
    const CompiledScene scene(doc);
    const test::PixelRays pixels(scene, doc.render.width, doc.render.height);
    const TraceKernel kernel(scene, TraceOptions::fromSettings(doc.render));
    onNewThread([&] {
        const std::size_t before = scratchBytesUsed();
        std::vector<Color> colors(pixels.size());
        TraceOutput out;
        out.color = colors.data();
        TraceCounters counters;
        ASSERT_TRUE(kernel.trace(pixels.batch(), out, counters));
        // The workspace's levels, shading points, light samples and shadow rays: tens of KB
        // for 1,200 camera rays, all of it in the arena (and all of it fitting there).
        EXPECT_GT(scratchBytesUsed(), before + 64 * 1024);
        EXPECT_LT(scratchBytesUsed(), kScratchArenaBytes);
    });
}

TEST(ScratchArena, FullArenaFallsBackAndFreesFromOtherThreadsAreSafe) {
    ScratchVector<double> big;
    ScratchVector<int> small(16, 5);
    onNewThread([&] {
        // Larger than an arena: std::allocator's block, freed to it on destruction.
        big.resize(kScratchArenaBytes / sizeof(double) + 1, 2.0);
        EXPECT_FALSE(scratchOwns(big.data()));
    });
    EXPECT_EQ(big.back(), 2.0);
    onNewThread([&] {
        // A block of the test thread's arena freed here: recognised and ignored.
        EXPECT_EQ(small[15], 5);
        small = {};
    });
    EXPECT_TRUE(small.empty());
    big = {};
}

TEST(ScratchArena, EndedThreadsArenaIsReusedFromTheStart) {
    if (!kScratchArenas) GTEST_SKIP() << "sanitizer build: scratch comes from std::allocator";
    const void* first = nullptr;
    onNewThread([&] {
        thread_local ScratchVector<float> kept;  // destroyed before the arena is handed back
        kept.resize(5000);
        first = kept.data();
    });
    onNewThread([&] {
        EXPECT_EQ(scratchBytesUsed(), 0u);
        ScratchVector<float> v(10);
        EXPECT_TRUE(scratchOwns(v.data()));
        EXPECT_TRUE(scratchOwns(first));  // arenas are kept for the process
    });
}

}  // namespace
}  // namespace rs
