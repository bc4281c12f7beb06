// Image size limits: each side and the area, in the API and in scene files.
#include <gtest/gtest.h>

#include "io/scene_io.h"

namespace rs {
namespace {

TEST(ImageSize, AreaIsBoundedNotJustEachSide) {
    EXPECT_TRUE(imageSizeError(8192, 8192).empty());  // Exactly 64 Mpixels.
    EXPECT_NE(imageSizeError(8192, 8193).find("at most 64 Mpixels"), std::string::npos);
    EXPECT_NE(imageSizeError(16384, 16384).find("256 Mpixels"), std::string::npos);
    EXPECT_NE(imageSizeError(16385, 1).find("each side at most 16384"), std::string::npos);
}

TEST(ImageSize, SceneFileOverTheAreaLimit_IsRefusedAtLoad) {
    const SceneLoadResult r = parseScene(
        R"({"format": "raystudio-scene", "version": 1,
            "render": {"width": 16384, "height": 16384}})",
        ".", "big.scene.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].pointer, "/render");
    EXPECT_NE(r.errors[0].message.find("Mpixels"), std::string::npos) << r.errors[0].message;
}

}  // namespace
}  // namespace rs
