// The asset material mapping (io/asset_material.h) on small assets the test writes and assimp
// reads: what assimp 5.2.5 really hands over for OBJ/MTL and glTF materials.
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <assimp/Importer.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/asset_material.h"

namespace rs {
namespace {

constexpr float kTol = 1e-5f;

bool hasNote(const AssetMaterial& a, const std::string& part) {
    for (const auto& n : a.notes)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

std::string allNotes(const AssetMaterial& a) {
    std::string all;
    for (const auto& n : a.notes) all += n + "\n";
    return all;
}

void expectColor(const Color& c, float r, float g, float b) {
    EXPECT_NEAR(c.x, r, kTol);
    EXPECT_NEAR(c.y, g, kTol);
    EXPECT_NEAR(c.z, b, kTol);
}

/// Every material of `scene`, mapped as an import of an asset in `dir` would.
std::vector<AssetMaterial> mapAll(const aiScene& scene, const std::string& dir) {
    AssetTextureContext context;
    context.assetDir = dir;
    std::vector<AssetMaterial> mapped;
    for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
        context.materialIndex = i;
        mapped.push_back(mapAssetMaterial(*scene.mMaterials[i], context));
    }
    return mapped;
}

const AssetMaterial* byName(const std::vector<AssetMaterial>& mapped, const std::string& name) {
    for (const auto& m : mapped)
        if (m.material.name == name) return &m;
    return nullptr;
}

/// A folder of its own, removed with what it holds.
struct TempDir {
    std::filesystem::path path;
    TempDir() {
        path = std::filesystem::temp_directory_path() /
               ("raystudio_asset_material_" + std::to_string(::getpid()));
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
};

TEST(AssetMaterialImport, ObjAndMtlReadThroughAssimp) {
    TempDir dir;
    std::ofstream(dir.path / "parts.obj") << "mtllib parts.mtl\n"
                                             "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                             "vt 0 0\nvt 1 0\nvt 0 1\n"
                                             "usemtl red\nf 1/1 2/2 3/3\n"
                                             "usemtl glass\nf 1/1 3/3 2/2\n"
                                             "usemtl veil\nf 2/2 1/1 3/3\n";
    std::ofstream(dir.path / "parts.mtl") << "newmtl red\nKd 0.8 0.1 0.2\nKs 0.5 0.5 0.5\n"
                                             "Ns 50\nmap_Kd tex\\red.png\n"
                                             "newmtl glass\nKd 1 1 1\nd 0.25\nNi 1.45\n"
                                             "newmtl veil\nKd 0.5 0.5 0.5\nTr 0.3\n";
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile((dir.path / "parts.obj").string(), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    const std::vector<AssetMaterial> mapped = mapAll(*scene, dir.path.string());
    auto find = [&](const std::string& name) { return byName(mapped, name); };
    const AssetMaterial* red = find("red");
    const AssetMaterial* glass = find("glass");
    const AssetMaterial* veil = find("veil");
    ASSERT_TRUE(red && glass && veil);

    expectColor(red->material.color, 0.8f, 0.1f, 0.2f);
    EXPECT_NEAR(red->material.specular, 0.5f, kTol);
    EXPECT_NEAR(red->material.shininess, 50.0f, kTol);
    EXPECT_NEAR(red->material.transparency, 0.0f, kTol);
    const auto* t = std::get_if<ImageTexture>(&red->material.pattern);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->image.file, "tex/red.png");
    EXPECT_EQ(t->image.resolvedPath, (dir.path / "tex" / "red.png").string());

    EXPECT_NEAR(glass->material.transparency, 0.75f, kTol);  // 1 - d
    EXPECT_NEAR(glass->material.ior, 1.45f, kTol);
    EXPECT_EQ(glass->material.pattern.index(), 0u);

    // assimp reads Tr as d = 1 - Tr; with MTL's default Ni 1 the veil does not bend light.
    expectColor(veil->material.color, 0.5f, 0.5f, 0.5f);
    EXPECT_NEAR(veil->material.transparency, 0.3f, kTol);
    EXPECT_NEAR(veil->material.ior, 1.0f, kTol);
}

/// A glTF with three triangles and three materials, its buffer inline (base64 of 9 position
/// floats, 6 uv floats and 3 16-bit indices with 2 bytes of padding).
std::string threeMaterialGltf() {
    const std::string buffer =
        "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/"
        "AAABAAIAAAA=";
    std::string meshes, nodes;
    for (int m = 0; m < 3; ++m) {
        const std::string i = std::to_string(m), comma = m ? "," : "";
        meshes += comma + R"({"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},)" +
                  R"("indices":2,"material":)" + i + "}]}";
        nodes += comma + R"({"mesh":)" + i + "}";
    }
    return R"({"asset":{"version":"2.0"},)"
           R"("extensionsUsed":["KHR_materials_transmission","KHR_materials_ior",)"
           R"("KHR_texture_transform"],)"
           R"("buffers":[{"byteLength":68,"uri":"data:application/octet-stream;base64,)" +
           buffer +
           R"("}],)"
           R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
           R"({"buffer":0,"byteOffset":36,"byteLength":24},)"
           R"({"buffer":0,"byteOffset":60,"byteLength":6}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]},)"
           R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"},)"
           R"({"bufferView":2,"componentType":5123,"count":3,"type":"SCALAR"}],)"
           R"("images":[{"uri":"wood.png"}],"samplers":[{"wrapS":33071}],)"
           R"("textures":[{"source":0,"sampler":0}],)"
           R"("materials":[)"
           R"({"name":"glass","pbrMetallicRoughness":{"baseColorFactor":[0.9,0.95,1,1],)"
           R"("metallicFactor":0,"roughnessFactor":0},"extensions":{)"
           R"("KHR_materials_transmission":{"transmissionFactor":1},)"
           R"("KHR_materials_ior":{"ior":1.33}}},)"
           R"({"name":"wood","pbrMetallicRoughness":{"baseColorTexture":{"index":0,)"
           R"("extensions":{"KHR_texture_transform":{"offset":[0.25,0.1],"scale":[2,3]}}},)"
           R"("metallicFactor":0.2,"roughnessFactor":0.5}},)"
           R"({"name":"veil","alphaMode":"BLEND",)"
           R"("pbrMetallicRoughness":{"baseColorFactor":[1,0,0,0.4]}}],)"
           R"("meshes":[)" +
           meshes + R"(],"nodes":[)" + nodes + R"(],"scenes":[{"nodes":[0,1,2]}],"scene":0})";
}

TEST(AssetMaterialImport, GltfReadThroughAssimp) {
    TempDir dir;
    std::ofstream(dir.path / "parts.gltf") << threeMaterialGltf();
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile((dir.path / "parts.gltf").string(), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    const std::vector<AssetMaterial> mapped = mapAll(*scene, dir.path.string());
    auto find = [&](const std::string& name) { return byName(mapped, name); };
    const AssetMaterial* glass = find("glass");
    const AssetMaterial* wood = find("wood");
    const AssetMaterial* veil = find("veil");
    ASSERT_TRUE(glass && wood && veil);

    // KHR_materials_transmission and KHR_materials_ior arrive; smooth dielectric.
    expectColor(glass->material.color, 0.9f, 0.95f, 1.0f);
    EXPECT_NEAR(glass->material.transparency, 1.0f, kTol);
    EXPECT_NEAR(glass->material.ior, 1.33f, kTol);
    EXPECT_NEAR(glass->material.reflectivity, 0.0f, kTol);

    // m 0.2, r 0.5: reflectivity 0.2 * 0.5, specular 0.5, shininess 0.5 / 0.0625 - 0.5.
    EXPECT_NEAR(wood->material.reflectivity, 0.1f, kTol);
    EXPECT_NEAR(wood->material.specular, 0.5f, kTol);
    EXPECT_NEAR(wood->material.shininess, 7.5f, 1e-4f);
    const auto* t = std::get_if<ImageTexture>(&wood->material.pattern);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->image.resolvedPath, (dir.path / "wood.png").string());
    // glTF scale [2, 3], offset [0.25, 0.1] in V-up terms: offset_v = 1 - 3 - 0.1.
    EXPECT_NEAR(t->scaleU, 2.0f, kTol);
    EXPECT_NEAR(t->scaleV, 3.0f, kTol);
    EXPECT_NEAR(t->offsetU, 0.25f, kTol);
    EXPECT_NEAR(t->offsetV, -2.1f, kTol);
    EXPECT_TRUE(hasNote(*wood, "clamps in u")) << allNotes(*wood);  // wrapS CLAMP_TO_EDGE
    EXPECT_FALSE(hasNote(*wood, "in v")) << allNotes(*wood);

    // Alpha 0.4 under BLEND lets 0.6 straight through.
    EXPECT_NEAR(veil->material.transparency, 0.6f, kTol);
    EXPECT_NEAR(veil->material.ior, 1.0f, kTol);
}

}  // namespace
}  // namespace rs
