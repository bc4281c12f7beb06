// View bookmarks in the scene format (scenes/FORMAT.md, "views"): read, written back, their
// errors where they stand, a version-2 key, seen by the document diff, and the cameras of an
// imported asset turned into views.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/asset_looks.h"
#include "io/scene_io.h"
#include "scene/document_change.h"

namespace rs {
namespace {

using Json = nlohmann::ordered_json;

SceneLoadResult parse(const std::string& text) {
    return parseScene(text, RAYSTUDIO_SCENES_DIR, "views.scene.json");
}

/// The one error of `text`, as `/pointer: message`.
std::string oneError(const std::string& text) {
    const SceneLoadResult r = parse(text);
    if (r.errors.size() != 1) return "expected one error, got:\n" + r.errorText();
    return r.errors[0].pointer + ": " + r.errors[0].message;
}

const char* const kTwoViews = R"({
  "format": "raystudio-scene", "version": 2,
  "camera": { "position": [0, 1, 5], "target": [0, 0, 0] },
  "views": [
    { "name": "close-up", "camera": { "position": [0.8, 0.4, 1.8], "target": [0, 0, 0], "fov_y": 35 } },
    { "name": "plan", "x-note": "from above",
      "camera": { "projection": "orthographic", "position": [0, 8, 0], "target": [0, 0, 0],
                  "up": [0, 0, -1], "ortho_height": 6 } }
  ]
})";

TEST(SceneViews, ReadWithTheirCamerasAndExtras) {
    const SceneLoadResult r = parse(kTwoViews);
    ASSERT_TRUE(r.ok()) << r.errorText();
    const SceneDocument& doc = r.document;
    ASSERT_EQ(doc.views.size(), 2u);
    EXPECT_EQ(doc.views[0].name, "close-up");
    EXPECT_EQ(doc.views[0].camera.position, Vec3(0.8f, 0.4f, 1.8f));
    EXPECT_EQ(doc.views[0].camera.fovY, 35.0f);
    const ViewBookmark* plan = doc.findView("plan");
    ASSERT_TRUE(plan);
    EXPECT_EQ(plan->camera.projection, Projection::Orthographic);
    EXPECT_EQ(plan->camera.up, Vec3(0.0f, 0.0f, -1.0f));
    EXPECT_EQ(plan->camera.orthoHeight, 6.0f);
    EXPECT_EQ(plan->extras, (Extras{{"x-note", "\"from above\""}}));
    EXPECT_EQ(doc.findView("nowhere"), nullptr);
    // The scene camera is its own, untouched by the views.
    EXPECT_EQ(doc.camera.position, Vec3(0.0f, 1.0f, 5.0f));
}

TEST(SceneViews, WrittenAfterTheCameraOnlyWhenThereAreAny_AndReadBackTheSame) {
    SceneDocument doc = parse(kTwoViews).document;
    const Json written = Json::parse(serializeScene(doc, RAYSTUDIO_SCENES_DIR));
    EXPECT_EQ(written.at("version").get<int>(), 2);
    std::vector<std::string> keys;
    for (const auto& item : written.items()) keys.push_back(item.key());
    ASSERT_GE(keys.size(), 5u);
    EXPECT_EQ(keys[2], "camera");
    EXPECT_EQ(keys[3], "views");
    EXPECT_EQ(written.at("views").at(1).at("x-note").get<std::string>(), "from above");
    const SceneLoadResult again = parse(serializeScene(doc, RAYSTUDIO_SCENES_DIR));
    ASSERT_TRUE(again.ok()) << again.errorText();
    EXPECT_TRUE(again.document.sameContent(doc));

    doc.views.clear();
    const Json plain = Json::parse(serializeScene(doc, RAYSTUDIO_SCENES_DIR));
    EXPECT_FALSE(plain.contains("views"));
    EXPECT_EQ(plain.at("version").get<int>(), 1);
}

TEST(SceneViews, AreAVersion2Key) {
    EXPECT_EQ(oneError(R"({ "format": "raystudio-scene", "version": 1,
        "views": [ { "name": "a", "camera": { "position": [0, 0, 5] } } ] })"),
              "/views: needs format version 2 (the file says \"version\": 1)");
}

TEST(SceneViews, ErrorsNameTheViewAndKey) {
    const std::string head = R"({ "format": "raystudio-scene", "version": 2, "views": )";
    EXPECT_EQ(oneError(head + R"({ "name": "a" } })"),
              "/views: must be an array, got {\"name\":\"a\"}");
    EXPECT_EQ(oneError(head + R"([ { "name": "a" } ] })"),
              "/views/0/camera: missing required key \"camera\"");
    EXPECT_EQ(oneError(head + R"([ { "camera": {} } ] })"),
              "/views/0/name: missing required key \"name\"");
    EXPECT_EQ(oneError(head + R"([ { "name": "", "camera": {} } ] })"),
              "/views/0/name: name must not be empty");
    EXPECT_EQ(
        oneError(head + R"([ { "name": "a", "camera": {} }, { "name": "a", "camera": {} } ] })"),
        "/views/1/name: duplicate view name \"a\" (also at /views/0)");
    EXPECT_EQ(oneError(head + R"([ { "name": "a", "camera": { "target": [0, 0, 0] } } ] })"),
              "/views/0/camera/target: camera target must differ from its position");
    EXPECT_EQ(oneError(head + R"([ { "name": "a", "camera": { "fov_y": 200 } } ] })"),
              "/views/0/camera/fov_y: fov_y must be in (0, 180), got 200");
    EXPECT_EQ(oneError(head + R"([ { "name": "a", "camera": {}, "lens": 50 } ] })"),
              "/views/0/lens: unknown key \"lens\"");
    EXPECT_EQ(oneError(head + R"([ 3 ] })"), "/views/0: must be an object, got 3");
}

TEST(SceneViews, TheDocumentDiffSeesThemApartFromTheCamera) {
    SceneDocument before = parse(kTwoViews).document;
    SceneDocument after = before;
    after.views[1].name = "top";
    DocumentChange c = describeChange(before, after);
    EXPECT_TRUE(c.views);
    EXPECT_TRUE(c.any());
    EXPECT_FALSE(c.camera);
    EXPECT_FALSE(after.sameContent(before));
    EXPECT_TRUE(DocumentChange::everything().views);
    EXPECT_FALSE(describeChange(before, before).any());
}

TEST(SceneViews, AnAssetsCamerasBecomeViewsPlacedAsTheAssetAndNamedApart) {
    SceneDocument doc;
    doc.views.push_back(ViewBookmark{"Eye", Camera{}, {}});
    Object o;
    o.name = "asset";
    o.geometry = SphereGeometry{};
    o.transform.translate = Vec3(10.0f, 0.0f, 0.0f);
    o.transform.scale = Vec3(2.0f);
    const ObjectId id = doc.addObject(o);
    AssetContent asset;
    AssetView eye;
    eye.name = "Eye";
    eye.camera.position = Vec3(0.0f, 1.0f, 5.0f);
    eye.camera.target = Vec3(0.0f, 1.0f, 4.0f);
    AssetView unnamed;
    unnamed.camera.projection = Projection::Orthographic;
    unnamed.camera.orthoHeight = 3.0f;
    unnamed.camera.position = Vec3(0.0f, 4.0f, 0.0f);
    unnamed.camera.target = Vec3(0.0f, 0.0f, 0.0f);
    unnamed.camera.up = Vec3(0.0f, 0.0f, -1.0f);
    asset.views = {eye, unnamed};

    const std::vector<std::string> names = adoptAssetViews(doc, id, asset);
    EXPECT_EQ(names, (std::vector<std::string>{"Eye.001", "Camera"}));
    ASSERT_EQ(doc.views.size(), 3u);
    const ViewBookmark* placedEye = doc.findView("Eye.001");
    ASSERT_TRUE(placedEye);
    EXPECT_EQ(placedEye->camera.position, Vec3(10.0f, 2.0f, 10.0f));
    EXPECT_EQ(placedEye->camera.target, Vec3(10.0f, 2.0f, 8.0f));
    EXPECT_EQ(doc.findView("Camera")->camera.orthoHeight, 6.0f);
    // What adoption made is a valid file.
    const SceneLoadResult r = parse(serializeScene(doc, RAYSTUDIO_SCENES_DIR));
    EXPECT_TRUE(r.ok()) << r.errorText();
}

}  // namespace
}  // namespace rs
