// The order a pass traces its tiles in when the session has a focus: nearest first, by groups
// of tiles each traced whole and row by row (neighbouring tiles share the frame's pages).
#include <gtest/gtest.h>

#include <mutex>
#include <utility>
#include <vector>

#include "session/render_session.h"
#include "session_test_support.h"

namespace rs {
namespace {

using namespace std::chrono_literals;

struct TileOrder : SessionObserver {
    std::mutex mutex;
    std::vector<std::pair<int, int>> corners;  ///< (x0, y0) of each tile, as they finish.
    void tileDone(int x0, int y0, int, int, uint64_t) override {
        std::lock_guard lock(mutex);
        corners.emplace_back(x0, y0);
    }
};

TEST(SessionTileOrder, FullPassWithAFocus_TracesGroupsOfTilesWhole_RowByRow_NearestFirst) {
    SceneDocument doc;
    doc.render.width = 512;  // 16 x 8 tiles of 32: groups of 8 x 2 tiles are 256 x 64 pixels.
    doc.render.height = 256;
    doc.camera.position = Vec3(0, 0, 0);
    doc.camera.target = Vec3(0, -0.5f, -4);
    test::addMaterial(doc, "white", Color(0.75f), 0.9f, 0.3f);
    test::addPlane(doc, "floor", Vec3(0, -2, 0), Vec3(0, 1, 0), "white");
    test::addPointLight(doc, "key", Vec3(0, 3, -3));
    RenderSession session(1);  // One thread: tiles finish in the order the pass lists them.
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));

    session.setFocus(400.0f, 200.0f);  // In the group of x 256-511, y 192-255.
    TileOrder order;
    session.setObserver(&order);
    doc.camera.target.x += 1e-3f;  // Every pixel is traced again.
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    session.setObserver(nullptr);

    ASSERT_EQ(order.corners.size(), 128u);
    // Each run of 16 is one group, row by row; the focus's group comes first.
    for (std::size_t g = 0; g < 8; ++g) {
        const int gx = order.corners[g * 16].first, gy = order.corners[g * 16].second;
        EXPECT_EQ(gx % 256, 0);
        EXPECT_EQ(gy % 64, 0);
        for (int k = 0; k < 16; ++k)
            EXPECT_EQ(order.corners[g * 16 + std::size_t(k)],
                      std::make_pair(gx + (k % 8) * 32, gy + (k / 8) * 32))
                << "group " << g << ", tile " << k;
    }
    EXPECT_EQ(order.corners[0], std::make_pair(256, 192));
}

}  // namespace
}  // namespace rs
