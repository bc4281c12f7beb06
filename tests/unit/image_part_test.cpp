// Parts of a final image (render --tile I/N, merge): band geometry, part files, the merge's
// refusals, and that parts of every bundled scene merge bit-identically to a whole render.
#include "image/image_part.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>

#include "image/image_io.h"
#include "image/part_file.h"
#include "image/part_merge.h"
#include "integrator/renderer.h"
#include "io/render_fingerprint.h"
#include "io/scene_io.h"
#include "snapshot/compiled_scene.h"

namespace rs {
namespace {

namespace fs = std::filesystem;

TEST(ImagePart, PartRows_TileTheImageInOrderWithoutGapsOrOverlaps) {
    for (int height : {1, 7, 27, 720, 16384}) {
        for (int count : {1, 2, 3, 7, 64, 4096}) {
            if (count > height) continue;
            int next = 0;
            for (int i = 0; i < count; ++i) {
                const RowRange rows = partRows({i, count}, height);
                ASSERT_EQ(rows.begin, next) << height << " rows, part " << i << "/" << count;
                ASSERT_GT(rows.end, rows.begin);
                ASSERT_LE(rows.end - rows.begin, height / count + 1);
                next = rows.end;
            }
            EXPECT_EQ(next, height);
        }
    }
}

TEST(ImagePart, PartError_NamesBadIndexCountOrTooManyParts) {
    EXPECT_EQ(partError({0, 1}, 1), "");
    EXPECT_EQ(partError({6, 7}, 180), "");
    EXPECT_NE(partError({7, 7}, 180).find("between 0 and 6, got 7"), std::string::npos);
    EXPECT_NE(partError({-1, 7}, 180).find("got -1"), std::string::npos);
    EXPECT_NE(partError({0, 0}, 180).find("between 1 and"), std::string::npos);
    EXPECT_NE(partError({0, 181}, 180).find("at most 180 parts"), std::string::npos);
    EXPECT_NE(partError({0, kMaxImageParts + 1}, 16384).find("between 1 and 4096"),
              std::string::npos);
}

TEST(ImagePart, ParseImagePart_TakesIOverNOnly) {
    ImagePart p;
    std::string error;
    ASSERT_TRUE(parseImagePart("3/7", p, error));
    EXPECT_EQ(p, (ImagePart{3, 7}));
    for (const char* bad : {"", "3", "3/", "/7", "a/7", "3/7x", "3 /7", "3/7/1", "99999999999/2"}) {
        EXPECT_FALSE(parseImagePart(bad, p, error)) << bad;
        EXPECT_NE(error.find("expects I/N"), std::string::npos) << bad;
    }
}

/// A bundled scene, small, supersampled 3x, with a sphere light added (its shadow samples use
/// per-pixel seeds), adaptive or everywhere.
SceneDocument partScene(const std::string& name, bool adaptive) {
    SceneLoadResult r = loadScene(std::string(RAYSTUDIO_SCENES_DIR) + "/" + name);
    EXPECT_TRUE(r.ok()) << r.errorText();
    SceneDocument doc = std::move(r.document);
    doc.render.width = 40;
    doc.render.height = 23;
    doc.render.supersampling = 3;
    doc.render.adaptiveSupersampling = adaptive;
    doc.render.shadowSamples = 4;
    Light area;
    area.name = "part-test sphere light";
    area.type = LightType::Sphere;
    area.position = Vec3(0.5f, 2.5f, 1.0f);
    area.radius = 0.4f;
    area.intensity = 0.6f;
    doc.addLight(area);
    return doc;
}

bool sameBits(const Color& a, const Color& b) {
    return std::memcmp(&a, &b, sizeof(Color)) == 0;
}

class PartFiles : public ::testing::Test {
protected:
    void SetUp() override {
        // The process id too: two checkouts' suites running at once (CI beside a developer's
        // run) would otherwise share the folder, and one's TearDown remove the other's parts.
        dir_ = fs::path(testing::TempDir()) /
               ("raystudio-parts-" + std::to_string(::getpid()) + "-" +
                std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    /// Renders part `part` of `doc` into a part file like `render --tile` does; its path.
    std::string renderPart(const SceneDocument& doc, const CompiledScene& scene, ImagePart part,
                           const std::string& tag = "") {
        RenderOptions options;
        options.threads = 2;
        const RowRange rows = partRows(part, doc.render.height);
        options.firstRow = rows.begin;
        options.endRow = rows.end;
        const RenderResult r = renderImage(scene, options);
        PartHeader header;
        header.part = part;
        header.fullWidth = doc.render.width;
        header.fullHeight = doc.render.height;
        header.rows = rows;
        header.fingerprint = renderFingerprint(doc, EngineKind::Embree);
        header.tonemap = doc.render.tonemap;
        header.exposure = doc.render.exposure;
        const std::string path = (dir_ / (tag + "part-" + std::to_string(part.index) + "-of-" +
                                          std::to_string(part.count) + ".exr"))
                                     .string();
        std::string error;
        EXPECT_TRUE(writePart(path, header, r.image, r.ids, error)) << error;
        return path;
    }
    fs::path dir_;
};

TEST_F(PartFiles, PartsOfEveryBundledScene_MergeBitIdenticallyToAWholeRender) {
    int scenes = 0;
    for (const auto& entry : fs::directory_iterator(RAYSTUDIO_SCENES_DIR)) {
        if (entry.path().string().find(".scene.json") == std::string::npos) continue;
        ++scenes;
        for (bool adaptive : {false, true}) {
            const SceneDocument doc = partScene(entry.path().filename().string(), adaptive);
            const CompiledScene scene(doc);
            RenderOptions whole;
            whole.threads = 2;
            const RenderResult full = renderImage(scene, whole);
            for (int count : {1, 2, 3, 7}) {
                std::vector<std::string> paths;
                for (int i = count - 1; i >= 0; --i)
                    paths.push_back(renderPart(doc, scene, {i, count}));
                MergedImage merged;
                std::string error;
                ASSERT_TRUE(mergeParts(paths, merged, error)) << error;
                ASSERT_EQ(merged.image.width, full.image.width);
                ASSERT_EQ(merged.image.height, full.image.height);
                for (std::size_t p = 0; p < full.image.pixels.size(); ++p)
                    ASSERT_TRUE(sameBits(merged.image.pixels[p], full.image.pixels[p]))
                        << entry.path().filename() << (adaptive ? " adaptive" : " everywhere")
                        << ", " << count << " parts: pixel (" << p % 40 << ", " << p / 40 << ")";
                ASSERT_EQ(merged.ids.size(), full.ids.size());
                EXPECT_EQ(merged.ids, full.ids);
            }
        }
    }
    EXPECT_GE(scenes, 4);
}

TEST_F(PartFiles, PartFile_CarriesItsPlaceInTheImageAndTheFingerprint) {
    const SceneDocument doc = partScene("reference-room.scene.json", true);
    const CompiledScene scene(doc);
    const std::string path = renderPart(doc, scene, {1, 3});
    PartHeader h;
    std::string error;
    ASSERT_TRUE(readPartHeader(path, h, error)) << error;
    EXPECT_EQ(h.part, (ImagePart{1, 3}));
    EXPECT_EQ(h.fullWidth, 40);
    EXPECT_EQ(h.fullHeight, 23);
    EXPECT_EQ(h.rows, (RowRange{7, 15}));
    EXPECT_EQ(h.fingerprint, renderFingerprint(doc, EngineKind::Embree));
    EXPECT_TRUE(h.hasIds);
}

TEST_F(PartFiles, Merge_RefusesMissingDoubledAndForeignParts) {
    const SceneDocument doc = partScene("reference-room.scene.json", false);
    const CompiledScene scene(doc);
    const std::string p0 = renderPart(doc, scene, {0, 3}), p1 = renderPart(doc, scene, {1, 3}),
                      p2 = renderPart(doc, scene, {2, 3});
    MergedImage merged;
    std::string error;

    EXPECT_FALSE(mergeParts({p0, p2}, merged, error));
    EXPECT_NE(error.find("1 of 3 parts missing: 1"), std::string::npos) << error;

    EXPECT_FALSE(mergeParts({p0, p1, p1, p2}, merged, error));
    EXPECT_NE(error.find("part 1/3 is given twice"), std::string::npos) << error;

    SceneDocument other = doc;
    other.render.maxDepth += 1;  // other settings: another render, same size and parts
    const std::string foreign = renderPart(other, CompiledScene(other), {1, 3}, "other-");
    EXPECT_FALSE(mergeParts({p0, foreign, p2}, merged, error));
    EXPECT_NE(error.find("'" + foreign + "' belongs to another scene or other settings"),
              std::string::npos)
        << error;

    SceneDocument otherScene = partScene("soft-shadows.scene.json", false);
    const std::string alien = renderPart(otherScene, CompiledScene(otherScene), {1, 3}, "scene-");
    EXPECT_FALSE(mergeParts({p0, alien, p2}, merged, error));
    EXPECT_NE(error.find("belongs to another scene"), std::string::npos) << error;

    EXPECT_TRUE(mergeParts({p2, p0, p1}, merged, error)) << error;  // any order
}

TEST_F(PartFiles, ReadPartHeader_RefusesAnImageThatIsNotAPart) {
    const std::string plain = (dir_ / "plain.exr").string();
    std::string error;
    ASSERT_TRUE(writeImage(plain, ImageRgb(4, 4), ToneMap::Clamp, 0.0f, error)) << error;
    PartHeader h;
    EXPECT_FALSE(readPartHeader(plain, h, error));
    EXPECT_NE(error.find("is not a RayStudio part"), std::string::npos) << error;
    EXPECT_FALSE(readPartHeader((dir_ / "none.exr").string(), h, error));
    EXPECT_NE(error.find("cannot read"), std::string::npos) << error;
}

TEST(RenderFingerprint, ChangesWithSettingsMeshesAndEngineOnly) {
    const SceneDocument doc = partScene("mesh.scene.json", false);
    const std::string base = renderFingerprint(doc, EngineKind::Embree);
    EXPECT_EQ(base.size(), 16u);
    EXPECT_EQ(renderFingerprint(doc, EngineKind::Embree), base);
    EXPECT_NE(renderFingerprint(doc, EngineKind::Builtin), base);
    SceneDocument wider = doc;
    wider.render.width += 1;
    EXPECT_NE(renderFingerprint(wider, EngineKind::Embree), base);
    SceneDocument moved = doc;
    for (Object& o : moved.objects.editable()) {
        auto* mesh = std::get_if<MeshGeometry>(&o.geometry);
        if (!mesh) continue;
        auto data = std::make_shared<MeshData>(*mesh->data);
        data->positions[0].x += 0.25f;  // same file name, other triangles
        mesh->data = data;
    }
    EXPECT_NE(renderFingerprint(moved, EngineKind::Embree), base);
}

}  // namespace
}  // namespace rs
