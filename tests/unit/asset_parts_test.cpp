// An imported asset's parts keep their own materials: the import groups the triangles by the
// file's material (MeshData::parts) and brings the mapped looks through the child's wire; a
// mesh object's `part_materials` names a material per part, which the snapshot traces as one
// primitive per part; adopting the looks adds the materials and writes embedded images.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/asset_content.h"
#include "io/asset_looks.h"
#include "io/child_process.h"
#include "io/mesh_io.h"
#include "io/mesh_wire.h"
#include "io/scene_io.h"
#include "session/scene_update.h"
#include "snapshot/compiled_scene.h"

namespace rs {
namespace {
namespace fs = std::filesystem;

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() /
               ("raystudio-asset-parts-" + std::to_string(getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string file(const std::string& name, const std::string& text) const {
        std::ofstream(path / name, std::ios::binary) << text;
        return (path / name).string();
    }
};

/// Two unit quads in the plane z = 0, facing +z: x in [-2, 0] uses "left", x in [0, 2]
/// "right"; the faces interleave the two materials (left, right, left, right).
std::string twoQuadsObj(TempDir& dir) {
    dir.file("quads.mtl",
             "newmtl left\nKd 0.9 0.1 0.1\nKs 0 0 0\n\n"
             "newmtl right\nKd 0.1 0.2 0.9\nKs 0.5 0.5 0.5\nNs 40\n");
    return dir.file("quads.obj",
                    "mtllib quads.mtl\n"
                    "v -2 -1 0\nv 0 -1 0\nv 0 1 0\nv -2 1 0\n"
                    "v 0 -1 0\nv 2 -1 0\nv 2 1 0\nv 0 1 0\n"
                    "usemtl left\nf 1 2 3\n"
                    "usemtl right\nf 5 6 7\n"
                    "usemtl left\nf 1 3 4\n"
                    "usemtl right\nf 5 7 8\n");
}

std::string throughPipe(const std::function<void(int)>& write) {
    int fds[2];
    if (::pipe(fds) != 0) return {};
    std::string bytes;
    std::thread reader([&] {
        char buffer[4096];
        ssize_t n;
        while ((n = ::read(fds[0], buffer, sizeof buffer)) > 0) bytes.append(buffer, size_t(n));
    });
    write(fds[1]);
    ::close(fds[1]);
    reader.join();
    ::close(fds[0]);
    return bytes;
}

/// The file material index of the look named `name`, or -1.
int lookIndex(const AssetContent& asset, const std::string& name) {
    for (const AssetLook& l : asset.looks)
        if (l.material.name == name) return int(l.index);
    return -1;
}

TEST(AssetParts, Import_GroupsTrianglesByMaterial_AndBringsTheirLooks) {
    TempDir dir;
    const MeshLoadResult r = loadMesh(twoQuadsObj(dir), false);
    ASSERT_TRUE(r.ok()) << r.error;
    const MeshData& mesh = *r.mesh;
    ASSERT_EQ(mesh.triangleCount(), 4u);
    ASSERT_TRUE(r.asset);
    const int left = lookIndex(*r.asset, "left"), right = lookIndex(*r.asset, "right");
    ASSERT_GE(left, 0);
    ASSERT_GE(right, 0);
    // One run per material, in material order, covering the four triangles.
    ASSERT_EQ(mesh.parts.size(), 2u);
    EXPECT_LT(mesh.parts[0].material, mesh.parts[1].material);
    EXPECT_EQ(mesh.parts[0].firstTriangle, 0u);
    EXPECT_EQ(mesh.parts[0].triangleCount, 2u);
    EXPECT_EQ(mesh.parts[1].firstTriangle, 2u);
    EXPECT_EQ(mesh.parts[1].triangleCount, 2u);
    // Each run holds the triangles of its side (left: every vertex x <= 0).
    for (const MeshPart& part : mesh.parts)
        for (uint32_t t = part.firstTriangle; t < part.firstTriangle + part.triangleCount; ++t)
            for (int k = 0; k < 3; ++k) {
                const float x = mesh.positions[mesh.indices[3 * t + k]].x;
                if (int(part.material) == left)
                    EXPECT_LE(x, 0.0f);
                else
                    EXPECT_GE(x, 0.0f);
            }
    // The looks are the MTL's (Kd as colour; Ks and Ns as the highlight).
    const Material& l = r.asset->look(uint32_t(left))->material;
    const Material& rt = r.asset->look(uint32_t(right))->material;
    EXPECT_EQ(l.color, Color(0.9f, 0.1f, 0.1f));
    EXPECT_EQ(rt.color, Color(0.1f, 0.2f, 0.9f));
    EXPECT_EQ(l.specular, 0.0f);
    EXPECT_NEAR(rt.specular, 0.5f, 1e-6f);
    EXPECT_EQ(rt.shininess, 40.0f);
    // Only materials some triangle uses come along (assimp adds a default one to every OBJ).
    EXPECT_EQ(r.asset->looks.size(), 2u);
}

TEST(AssetParts, Wire_CarriesPartsLooksAndImages_AndRefusesPartsThatDoNotCover) {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
    mesh.indices = {0, 1, 2, 1, 3, 2};
    mesh.parts = {{0, 1, 0}, {1, 1, 3}};
    AssetContent asset;
    asset.images.push_back({"inner.png", "png", std::string("\x89PNG\r\n\x1a\n-bytes", 14)});
    AssetLook a;
    a.index = 0;
    a.material.name = "paint";
    a.material.color = Color(0.25f, 0.5f, 0.75f);
    a.notes = {"its emissive colour is not kept"};
    AssetLook b;
    b.index = 3;
    b.material.name = "decal";
    b.embeddedImage = 0;
    ImageTexture t;
    t.scaleU = 2.0f, t.offsetV = 0.25f;
    b.material.pattern = t;
    asset.looks = {a, b};
    const MeshLoadResult back = decodeMeshWire(
        throughPipe([&](int fd) { writeMeshWire(fd, mesh, asset, "/assets"); }), "/assets/m.glb");
    ASSERT_TRUE(back.ok()) << back.error;
    EXPECT_EQ(back.mesh->parts, mesh.parts);
    ASSERT_TRUE(back.asset);
    ASSERT_EQ(back.asset->looks.size(), 2u);
    EXPECT_EQ(back.asset->looks[0].material, a.material);
    EXPECT_EQ(back.asset->looks[0].notes, a.notes);
    EXPECT_EQ(back.asset->looks[1].index, 3u);
    EXPECT_EQ(back.asset->looks[1].embeddedImage, 0);
    const auto* tb = std::get_if<ImageTexture>(&back.asset->looks[1].material.pattern);
    ASSERT_TRUE(tb);
    EXPECT_EQ(tb->scaleU, 2.0f);
    EXPECT_EQ(tb->offsetV, 0.25f);
    EXPECT_TRUE(tb->image.empty());
    ASSERT_EQ(back.asset->images.size(), 1u);
    EXPECT_EQ(back.asset->images[0].bytes, asset.images[0].bytes);
    EXPECT_EQ(back.asset->images[0].formatHint, "png");

    // Parts with a gap, out of material order, or past the triangles are not a mesh.
    for (const std::vector<MeshPart>& bad :
         {std::vector<MeshPart>{{0, 1, 0}, {2, 1, 1}}, std::vector<MeshPart>{{0, 1, 3}, {1, 1, 0}},
          std::vector<MeshPart>{{0, 3, 0}}}) {
        mesh.parts = bad;
        const MeshLoadResult refused =
            decodeMeshWire(throughPipe([&](int fd) { writeMeshWire(fd, mesh); }), "/m.obj");
        EXPECT_FALSE(refused.ok());
        EXPECT_NE(refused.error.find("parts that do not cover"), std::string::npos)
            << refused.error;
    }
}

/// A scene looking down -z at the two quads, with materials "red" and "blue".
SceneDocument twoPartScene(const MeshLoadResult& loaded) {
    SceneDocument doc;
    doc.camera.position = Vec3(0, 0, 5);
    doc.camera.target = Vec3(0, 0, 0);
    Material red, blue, grey;
    red.name = "red", red.color = Color(1, 0, 0);
    blue.name = "blue", blue.color = Color(0, 0, 1);
    grey.name = "grey";
    doc.materials = {grey, red, blue};
    Object o;
    o.name = "quads";
    o.material = "grey";
    MeshGeometry g;
    g.file = g.resolvedPath = loaded.mesh->sourcePath;
    g.smoothNormals = false;
    g.data = loaded.mesh;
    o.geometry = g;
    doc.addObject(o);
    return doc;
}

/// The material index the ray from (x, 0, 5) down -z hits, or -1.
int materialAt(const CompiledScene& scene, float x) {
    SurfaceHit hit;
    if (!scene.intersect(Ray::make(Vec3(x, 0.0f, 5.0f), Vec3(0.0f, 0.0f, -1.0f)), 100.0f, hit))
        return -1;
    return int(hit.material);
}

TEST(AssetParts, PartMaterials_AreTracedPartByPart_InEveryEngine) {
    TempDir dir;
    const MeshLoadResult loaded = loadMesh(twoQuadsObj(dir), false);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    const int left = lookIndex(*loaded.asset, "left"), right = lookIndex(*loaded.asset, "right");
    SceneDocument doc = twoPartScene(loaded);
    // Material table indices: 0 the built-in grey, then the document's in order.
    constexpr int kGrey = 1, kRed = 2, kBlue = 3;
    for (EngineKind engine : {EngineKind::Embree, EngineKind::Builtin}) {
        SCOPED_TRACE(engine == EngineKind::Embree ? "embree" : "builtin");
        // Without part materials the whole mesh is the object's material.
        EXPECT_EQ(materialAt(CompiledScene(doc, nullptr, engine), -1.0f), kGrey);
        EXPECT_EQ(materialAt(CompiledScene(doc, nullptr, engine), 1.0f), kGrey);

        auto& parts = std::get<MeshGeometry>(doc.findObject(1)->geometry).partMaterials;
        parts.assign(std::size_t(std::max(left, right)) + 1, "");
        parts[std::size_t(left)] = "red";
        parts[std::size_t(right)] = "blue";
        const CompiledScene split(doc, nullptr, engine);
        EXPECT_EQ(materialAt(split, -1.0f), kRed);
        EXPECT_EQ(materialAt(split, 1.0f), kBlue);
        EXPECT_EQ(split.primitives().size(), 2u);
        // The object's bounds are both parts'.
        const Aabb box = split.objectBounds(1);
        EXPECT_EQ(box.min.x, -2.0f);
        EXPECT_EQ(box.max.x, 2.0f);

        // Moved, both parts go along and keep their materials.
        SceneDocument moved = doc;
        moved.findObject(1)->transform.translate = Vec3(10, 0, 0);
        const CompiledScene refit = split.refitted(moved, {1});
        EXPECT_EQ(materialAt(refit, -1.0f), -1);
        EXPECT_EQ(materialAt(refit, 9.0f), kRed);
        EXPECT_EQ(materialAt(refit, 11.0f), kBlue);
        // A box proxy stands in for every part.
        const CompiledScene proxied = split.withBoxProxy(1);
        ASSERT_EQ(proxied.primitives().size(), 2u);
        for (const Primitive& p : proxied.primitives())
            EXPECT_TRUE(std::holds_alternative<BoxShape>(p.shape));

        // A part left unnamed ("" / null) shows the object's material.
        parts[std::size_t(right)] = "";
        EXPECT_EQ(materialAt(CompiledScene(doc, nullptr, engine), 1.0f), kGrey);
        parts.clear();
    }
}

TEST(AssetParts, EditingAPartsMaterial_RetintsTheObject) {
    TempDir dir;
    const MeshLoadResult loaded = loadMesh(twoQuadsObj(dir), false);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    SceneDocument before = twoPartScene(loaded);
    auto& parts = std::get<MeshGeometry>(before.findObject(1)->geometry).partMaterials;
    parts = {"red", "blue"};
    const auto snapshot = std::make_shared<const CompiledScene>(before);
    SceneDocument after = before;
    after.materials[2].color = Color(0, 1, 0);  // "blue", used by a part only
    const SceneUpdate update = updateScene(before, snapshot, after, EngineKind::Embree);
    EXPECT_EQ(update.edit.retinted, std::vector<ObjectId>{1});
    EXPECT_EQ(update.snapshot->materials()[3].color, Color(0, 1, 0));
}

TEST(AssetParts, SceneFile_PartMaterials_RoundTripAndAreChecked) {
    TempDir dir;
    twoQuadsObj(dir);
    const std::string head =
        R"({"format": "raystudio-scene", "version": 2,
            "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40},
            "materials": [{"name": "red", "color": [1, 0, 0]}, {"name": "blue", "color": [0, 0, 1]}],
            "objects": [{"name": "quads", "type": "mesh", "file": "quads.obj", "part_materials": )";
    const SceneLoadResult ok = parseScene(head + R"(["red", null, "blue"]}]})", dir.path.string());
    ASSERT_TRUE(ok.ok()) << ok.errorText();
    const auto& g = std::get<MeshGeometry>(ok.document.objects[0].geometry);
    EXPECT_EQ(g.partMaterials, (std::vector<std::string>{"red", "", "blue"}));
    const std::string saved = serializeScene(ok.document, dir.path.string());
    EXPECT_NE(saved.find("\"part_materials\""), std::string::npos);
    const SceneLoadResult again = parseScene(saved, dir.path.string());
    ASSERT_TRUE(again.ok()) << again.errorText();
    EXPECT_TRUE(again.document.sameContent(ok.document));
    EXPECT_NE(saved.find("\"version\": 2"), std::string::npos);

    const std::pair<std::string, std::string> bad[] = {
        {R"("red"}]})", "/objects/0/part_materials: part_materials must be an array"},
        {R"(["red", "green"]}]})",
         "/objects/0/part_materials/1: material \"green\" is not defined in /materials"},
        {R"(["red", 3]}]})", "/objects/0/part_materials/1: a part's material must be"},
    };
    for (const auto& [tail, message] : bad) {
        const SceneLoadResult r = parseScene(head + tail, dir.path.string());
        EXPECT_FALSE(r.ok());
        EXPECT_NE(r.errorText().find(message), std::string::npos) << r.errorText();
    }
    std::string v1 = head + R"(["red"]}]})";
    v1.replace(v1.find("\"version\": 2"), 12, "\"version\": 1");
    const SceneLoadResult old = parseScene(v1, dir.path.string());
    EXPECT_NE(old.errorText().find("/objects/0/part_materials: needs format version 2"),
              std::string::npos)
        << old.errorText();
}

TEST(AssetParts, Adopting_AddsRenamedMaterials_AndWritesEmbeddedImages) {
    TempDir dir;
    SceneDocument doc;
    Material taken;
    taken.name = "paint";
    doc.materials.push_back(taken);
    Object o;
    o.name = "asset";
    o.geometry = MeshGeometry{};
    const ObjectId id = doc.addObject(o);
    AssetContent asset;
    asset.images.push_back({"", "png", "png bytes"});
    AssetLook a;
    a.index = 2;
    a.material.name = "paint";
    a.notes = {"its emissive colour is not kept"};
    AssetLook b;
    b.index = 5;
    b.material.name = "decal";
    b.embeddedImage = 0;
    b.material.pattern = ImageTexture{};
    asset.looks = {a, b};

    const AdoptedLooks adopted =
        adoptAssetLooks(doc, id, asset, "thing.glb", (dir.path / "images").string());
    EXPECT_EQ(adopted.materials, (std::vector<std::string>{"paint.001", "decal"}));
    ASSERT_EQ(doc.materials.size(), 3u);
    const auto& parts = std::get<MeshGeometry>(doc.findObject(id)->geometry).partMaterials;
    EXPECT_EQ(parts, (std::vector<std::string>{"", "", "paint.001", "", "", "decal"}));
    const fs::path image = dir.path / "images" / "thing-0.png";
    ASSERT_EQ(adopted.images, std::vector<std::string>{image.string()});
    std::ifstream in(image, std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "png bytes");
    const auto* t = std::get_if<ImageTexture>(&doc.materials[2].pattern);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->image.source(), image.string());
    ASSERT_EQ(adopted.notes.size(), 1u);
    EXPECT_EQ(adopted.notes[0],
              "asset \"thing.glb\", part \"paint\": its emissive colour is not kept");

    // A folder that cannot be made: the part stays untextured, and a note says why.
    SceneDocument other;
    const ObjectId id2 = other.addObject(o);
    const std::string blocker = dir.file("blocker", "a file, not a folder");
    const AdoptedLooks failed = adoptAssetLooks(other, id2, asset, "thing.glb", blocker + "/x");
    EXPECT_TRUE(std::holds_alternative<std::monostate>(other.materials[1].pattern));
    ASSERT_EQ(failed.notes.size(), 2u);
    EXPECT_NE(failed.notes[1].find("asset \"thing.glb\", part \"decal\": its embedded image 0: "
                                   "cannot create folder"),
              std::string::npos)
        << failed.notes[1];
}

TEST(AssetParts, MissingTextureFile_LeavesThePartUntextured_WithANoteNamingIt) {
    TempDir dir;
    dir.file("m.mtl", "newmtl wood\nKd 0.6 0.4 0.2\nmap_Kd gone.png\n");
    const std::string obj =
        dir.file("m.obj",
                 "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                 "usemtl wood\nf 1/1 2/2 3/3\n");
    const MeshLoadResult r = loadMesh(obj, false);
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_TRUE(r.asset);
    ASSERT_EQ(r.asset->looks.size(), 1u);
    const AssetLook& wood = r.asset->looks[0];
    EXPECT_TRUE(std::holds_alternative<std::monostate>(wood.material.pattern));
    EXPECT_EQ(wood.material.color, Color(0.6f, 0.4f, 0.2f));
    std::string notes;
    for (const std::string& n : wood.notes) notes += n + "\n";
    EXPECT_NE(notes.find("gone.png"), std::string::npos) << notes;
    EXPECT_NE(notes.find("left untextured"), std::string::npos) << notes;
}

TEST(AssetParts, TexturePathFromAnotherMachine_IsFoundByNameInTheAssetsFolder) {
    TempDir dir;
    fs::copy_file(std::string(RAYSTUDIO_SCENES_DIR) + "/textures/tiles.png", dir.path / "wood.png");
    dir.file("m.mtl", "newmtl wood\nKd 1 1 1\nmap_Kd D:\\work\\maps\\wood.png\n");
    const std::string obj =
        dir.file("m.obj",
                 "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                 "usemtl wood\nf 1/1 2/2 3/3\n");
    const MeshLoadResult r = loadMesh(obj, false);
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.asset->looks.size(), 1u);
    const auto* t = std::get_if<ImageTexture>(&r.asset->looks[0].material.pattern);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->image.source(), (dir.path / "wood.png").string());
    std::string notes;
    for (const std::string& n : r.asset->looks[0].notes) notes += n + "\n";
    EXPECT_NE(notes.find("using \"wood.png\" from the asset's folder"), std::string::npos) << notes;
}

TEST(AssetParts, ShownMaterial_IsTheOnePartsOwn_OnlyWhenEveryPartHasItsOwn) {
    auto asset = [](std::vector<MeshPart> parts, std::vector<std::string> partMaterials) {
        auto data = std::make_shared<MeshData>();
        data->parts = std::move(parts);
        MeshGeometry mesh;
        mesh.data = data;
        mesh.partMaterials = std::move(partMaterials);
        Object o;
        o.material = "object";
        o.geometry = mesh;
        return o;
    };
    // One part with its own material: that material is what shows.
    const Object one = asset({{0, 4, 2}}, {"", "", "painted"});
    EXPECT_TRUE(everyPartHasItsOwn(one));
    EXPECT_EQ(shownMaterial(one), "painted");
    // One part without: the object's.
    const Object plain = asset({{0, 4, 0}}, {"", "painted"});
    EXPECT_FALSE(everyPartHasItsOwn(plain));
    EXPECT_EQ(shownMaterial(plain), "object");
    // Two parts, each its own: the object's material shows nowhere, but no one part speaks
    // for the object.
    const Object two = asset({{0, 2, 0}, {2, 2, 1}}, {"red", "blue"});
    EXPECT_TRUE(everyPartHasItsOwn(two));
    EXPECT_EQ(shownMaterial(two), "object");
    // Not loaded, or not a mesh: the object's.
    Object unloaded = asset({}, {"red"});
    std::get<MeshGeometry>(unloaded.geometry).data.reset();
    EXPECT_FALSE(everyPartHasItsOwn(unloaded));
    EXPECT_EQ(shownMaterial(unloaded), "object");
    Object ball;
    ball.material = "object";
    ball.geometry = SphereGeometry{Vec3(0.0f), 1.0f};
    EXPECT_FALSE(everyPartHasItsOwn(ball));
    EXPECT_EQ(shownMaterial(ball), "object");
}

}  // namespace
}  // namespace rs
