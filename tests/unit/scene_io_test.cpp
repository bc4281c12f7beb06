// Scene reading and writing: defaults, x- keys, mesh paths, writer output and atomic saving.
#include "io/scene_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace rs {
namespace {

namespace fs = std::filesystem;
const std::string kData = RAYSTUDIO_TEST_DATA;

std::string scene(const std::string& body) {
    return "{ \"format\": \"raystudio-scene\", \"version\": 1" + (body.empty() ? "" : ", " + body) +
           " }";
}

std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A fresh, empty folder per test, removed afterwards.
class TempFolder {
public:
    TempFolder() {
        dir_ = fs::path(testing::TempDir()) /
               ("scene_io_" +
                std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    ~TempFolder() {
        std::error_code ec;
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(dir_, ec);
    }
    const fs::path& path() const { return dir_; }

private:
    fs::path dir_;
};

TEST(SceneReader, EmptyScene_GetsEveryDefault) {
    SceneLoadResult r = parseScene(scene(""), "");
    ASSERT_TRUE(r.ok()) << r.errorText();
    EXPECT_TRUE(r.document.sameContent(SceneDocument{}));
    EXPECT_EQ(r.document.render.width, 1280);
    EXPECT_EQ(r.document.camera.fovY, 55.0f);
}

TEST(SceneReader, AbsentKeys_TakeTheFormatsDefaults) {
    SceneLoadResult r = parseScene(scene(R"(
        "materials": [ { "name": "m" } ],
        "lights": [ { "name": "l", "type": "point", "position": [1, 2, 3] } ],
        "objects": [ { "name": "s", "type": "sphere", "center": [0, 0, 0], "radius": 2 } ])"),
                                   "");
    ASSERT_TRUE(r.ok()) << r.errorText();
    const Material& m = r.document.materials.at(0);
    EXPECT_EQ(m.color, Color(0.8f));
    EXPECT_EQ(m.diffuse, 1.0f);
    EXPECT_EQ(m.shininess, 32.0f);
    EXPECT_EQ(m.ior, 1.5f);
    const Light& l = r.document.lights.at(0);
    EXPECT_EQ(l.color, Color(1.0f));
    EXPECT_EQ(l.intensity, 1.0f);
    const Object& o = r.document.objects.at(0);
    EXPECT_TRUE(o.visible);
    EXPECT_EQ(o.material, "");  // the built-in grey
    EXPECT_TRUE(o.transform.isIdentity());
    EXPECT_NE(o.id, kNoObject);
    EXPECT_NE(o.id, l.id);
}

TEST(SceneReader, MinWeight_IsReadAndDefaultsToOne255th) {
    SceneLoadResult r = parseScene(scene(R"("render": { "min_weight": 0.01 })"), "");
    ASSERT_TRUE(r.ok()) << r.errorText();
    EXPECT_EQ(r.document.render.minWeight, 0.01f);
    r = parseScene(scene(R"("render": { "min_weight": 0 })"), "");
    ASSERT_TRUE(r.ok()) << r.errorText();
    EXPECT_EQ(r.document.render.minWeight, 0.0f);
    r = parseScene(scene(""), "");
    ASSERT_TRUE(r.ok()) << r.errorText();
    EXPECT_EQ(r.document.render.minWeight, 1.0f / 255.0f);
}

TEST(SceneReader, PlaneNormal_IsNormalised) {
    SceneLoadResult r = parseScene(scene(R"("objects": [ { "name": "p", "type": "plane",
        "point": [0, 0, 0], "normal": [0, 3, 4] } ])"),
                                   "");
    ASSERT_TRUE(r.ok()) << r.errorText();
    Vec3 n = std::get<PlaneGeometry>(r.document.objects[0].geometry).normal;
    EXPECT_NEAR(n.y, 0.6f, 1e-7f);
    EXPECT_NEAR(n.z, 0.8f, 1e-7f);
}

TEST(SceneReader, ScaleAsNumber_IsUniformAndRemembered) {
    SceneLoadResult r = parseScene(scene(R"("objects": [ { "name": "b", "type": "box",
        "min": [0, 0, 0], "max": [1, 1, 1], "scale": 2 } ])"),
                                   "");
    ASSERT_TRUE(r.ok()) << r.errorText();
    const Transform& t = r.document.objects[0].transform;
    EXPECT_EQ(t.scale, Vec3(2.0f));
    EXPECT_TRUE(t.scaleWrittenAsNumber);
}

TEST(SceneReader, XKeys_AreKeptInFileOrderAndWrittenBack) {
    std::string text = scene(R"("x-editor": { "zoom": 2, "a": [1, "b"] },
        "camera": { "x-b": 1, "fov_y": 40, "x-a": "two" },
        "materials": [ { "name": "m", "x-note": null } ],
        "objects": [ { "name": "s", "type": "sphere", "center": [0, 0, 0], "radius": 1,
                       "x-tag": [true] } ])");
    SceneLoadResult r = parseScene(text, "");
    ASSERT_TRUE(r.ok()) << r.errorText();
    // Kept verbatim and in file order (not sorted: "x-b" before "x-a").
    Extras expectedCamera = {{"x-b", "1"}, {"x-a", "\"two\""}};
    EXPECT_EQ(r.document.camera.extras, expectedCamera);
    EXPECT_EQ(r.document.extras, (Extras{{"x-editor", R"({"zoom":2,"a":[1,"b"]})"}}));
    EXPECT_EQ(r.document.materials[0].extras, (Extras{{"x-note", "null"}}));
    EXPECT_EQ(r.document.objects[0].extras, (Extras{{"x-tag", "[true]"}}));

    nlohmann::ordered_json written = nlohmann::ordered_json::parse(serializeScene(r.document, ""));
    EXPECT_EQ(written["x-editor"]["a"][1], "b");
    EXPECT_EQ(written["camera"]["x-a"], "two");
    EXPECT_EQ(written["objects"][0]["x-tag"][0], true);
    EXPECT_TRUE(written["materials"][0].contains("x-note"));
}

TEST(SceneReader, RelativeMeshPath_IsResolvedAgainstTheScenesFolder) {
    SceneLoadResult r = parseScene(scene(R"("objects": [ { "name": "m", "type": "mesh",
        "file": "meshes/cube.obj", "smooth_normals": false } ])"),
                                   kData);
    ASSERT_TRUE(r.ok()) << r.errorText();
    const auto& g = std::get<MeshGeometry>(r.document.objects[0].geometry);
    EXPECT_EQ(g.file, "meshes/cube.obj");
    EXPECT_EQ(fs::path(g.resolvedPath), fs::path(kData + "/meshes/cube.obj").lexically_normal());
    ASSERT_NE(g.data, nullptr);
    EXPECT_EQ(g.data->triangleCount(), 12u);
    EXPECT_TRUE(g.data->normals.empty());
}

TEST(SceneReader, LoadScene_ResolvesMeshesNextToTheFile) {
    TempFolder dir;
    fs::create_directories(dir.path() / "meshes");
    fs::copy_file(kData + "/meshes/tetra.ply", dir.path() / "meshes/t.ply");
    std::ofstream(dir.path() / "a.scene.json")
        << scene(R"("objects": [ { "name": "t", "type": "mesh", "file": "meshes/t.ply" } ])");
    SceneLoadResult r = loadScene((dir.path() / "a.scene.json").string());
    ASSERT_TRUE(r.ok()) << r.errorText();
    EXPECT_EQ(std::get<MeshGeometry>(r.document.objects[0].geometry).data->triangleCount(), 4u);
}

TEST(SceneWriter, Output_IsPrettyWithFormatAndVersionFirstAndDefaultsOmitted) {
    SceneLoadResult r = loadScene(kData + "/scenes/example.scene.json");
    ASSERT_TRUE(r.ok()) << r.errorText();
    std::string text = serializeScene(r.document, "");
    EXPECT_EQ(text.rfind("{\n  \"format\": \"raystudio-scene\",\n  \"version\": 1,\n", 0), 0u)
        << text;
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(text);
    const auto& glass = j["materials"][2];
    EXPECT_EQ(glass.begin().key(), "name");
    EXPECT_FALSE(glass.contains("ior"));       // 1.5 is the default
    EXPECT_FALSE(glass.contains("specular"));  // so is 0
    EXPECT_EQ(glass["transparency"], 1.0);
    // Floats are written as the short decimal the file had, not 0.60000002384185791.
    EXPECT_NE(text.find("\"radius\": 0.6\n"), std::string::npos) << text;
    EXPECT_FALSE(j["lights"][0].contains("radius"));  // point lights take none
}

TEST(SceneWriter, MinWeight_IsOmittedAtItsDefaultAndWrittenOtherwise) {
    SceneDocument doc;
    nlohmann::json j = nlohmann::json::parse(serializeScene(doc, ""));
    EXPECT_FALSE(j["render"].contains("min_weight")) << j.dump();
    doc.render.minWeight = 0.0f;
    j = nlohmann::json::parse(serializeScene(doc, ""));
    EXPECT_EQ(j["render"]["min_weight"], 0.0);
    doc.render.minWeight = 0.02f;
    j = nlohmann::json::parse(serializeScene(doc, ""));
    EXPECT_EQ(j["render"]["min_weight"], 0.02);
}

TEST(SceneWriter, UniformScaleFromNumber_IsWrittenAsANumber) {
    SceneDocument doc;
    Object o;
    o.name = "b";
    o.geometry = BoxGeometry{};
    o.transform.scale = Vec3(3.0f);
    o.transform.scaleWrittenAsNumber = true;
    doc.addObject(o);
    o.name = "c";
    o.transform.scaleWrittenAsNumber = false;
    doc.addObject(o);
    nlohmann::json j = nlohmann::json::parse(serializeScene(doc, ""));
    EXPECT_EQ(j["objects"][0]["scale"], 3.0);
    EXPECT_EQ(j["objects"][1]["scale"], nlohmann::json::array({3.0, 3.0, 3.0}));
}

TEST(SceneWriter, MeshPath_IsRelativeBelowTheFolderAndAbsoluteElsewhere) {
    SceneDocument doc;
    Object o;
    o.name = "m";
    MeshGeometry g;
    g.file = "whatever.obj";
    g.resolvedPath = kData + "/meshes/cube.obj";
    o.geometry = g;
    doc.addObject(o);
    nlohmann::json below = nlohmann::json::parse(serializeScene(doc, kData));
    EXPECT_EQ(below["objects"][0]["file"], "meshes/cube.obj");
    nlohmann::json beside = nlohmann::json::parse(serializeScene(doc, kData + "/scenes"));
    std::string file = beside["objects"][0]["file"];
    EXPECT_TRUE(fs::path(file).is_absolute()) << file;
    EXPECT_EQ(fs::path(file), fs::path(g.resolvedPath).lexically_normal());
}

TEST(SceneSave, SavedFile_LoadsBackAsTheSameScene) {
    TempFolder dir;
    SceneLoadResult r = loadScene(kData + "/scenes/example.scene.json");
    ASSERT_TRUE(r.ok()) << r.errorText();
    std::string error;
    fs::path target = dir.path() / "saved.scene.json";
    ASSERT_TRUE(saveScene(target.string(), r.document, error)) << error;
    SceneLoadResult back = loadScene(target.string());
    ASSERT_TRUE(back.ok()) << back.errorText();
    EXPECT_TRUE(back.document.sameContent(r.document));
    // Nothing but the scene is left in the folder (no temporary files).
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(SceneSave, PathIsADirectory_FailsNamingThePathAndLeavesItAlone) {
    TempFolder dir;
    fs::create_directory(dir.path() / "taken");
    std::string error;
    std::string target = (dir.path() / "taken").string();
    EXPECT_FALSE(saveScene(target, SceneDocument{}, error));
    EXPECT_NE(error.find(target), std::string::npos) << error;
    EXPECT_NE(error.find("directory"), std::string::npos) << error;
    EXPECT_TRUE(fs::is_directory(target));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(SceneSave, MissingFolder_FailsWithTheOsError) {
    TempFolder dir;
    std::string error;
    std::string target = (dir.path() / "no/such/a.scene.json").string();
    EXPECT_FALSE(saveScene(target, SceneDocument{}, error));
    EXPECT_NE(error.find(target), std::string::npos) << error;
    EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
}

TEST(SceneSave, UnwritableFolder_LeavesTheOldFileIntact) {
    TempFolder dir;
    fs::path target = dir.path() / "a.scene.json";
    std::ofstream(target) << "old contents";
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
    // Root ignores permissions; then the folder is not unwritable and there is nothing to test.
    if (std::ofstream(dir.path() / "probe")) GTEST_SKIP() << "running with CAP_DAC_OVERRIDE";
    std::string error;
    EXPECT_FALSE(saveScene(target.string(), SceneDocument{}, error));
    EXPECT_NE(error.find(target.string()), std::string::npos) << error;
    EXPECT_NE(error.find("Permission denied"), std::string::npos) << error;
    EXPECT_EQ(readFile(target), "old contents");
}

TEST(SceneSave, FolderNobodyCanWriteTo_LeavesTheOldFileIntact) {
    // procfs refuses new files even to root, so this runs where the test above is skipped.
    const fs::path target = "/proc/version";
    if (!fs::exists(target)) GTEST_SKIP() << "no procfs";
    const std::string before = readFile(target);
    std::string error;
    EXPECT_FALSE(saveScene(target.string(), SceneDocument{}, error));
    EXPECT_NE(error.find(target.string()), std::string::npos) << error;
    EXPECT_EQ(readFile(target), before);
}

TEST(SceneSave, Overwrite_ReplacesTheOldFileWhole) {
    TempFolder dir;
    fs::path target = dir.path() / "a.scene.json";
    std::ofstream(target) << std::string(100000, ' ') << "old";
    std::string error;
    ASSERT_TRUE(saveScene(target.string(), SceneDocument{}, error)) << error;
    EXPECT_EQ(readFile(target), serializeScene(SceneDocument{}, dir.path().string()));
}

}  // namespace
}  // namespace rs
