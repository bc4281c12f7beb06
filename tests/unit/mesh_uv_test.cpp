// A mesh's first UV channel: imported from the file, carried over the import wire, and used
// by image textures at a hit (scenes/FORMAT.md "Texture coordinates per shape").
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "closed_form_support.h"
#include "integrator/whitted.h"
#include "io/child_process.h"
#include "io/mesh_io.h"
#include "io/mesh_wire.h"
#include "test_scenes.h"
#include "texture/shape_uv.h"

namespace rs {
namespace {

namespace fs = std::filesystem;
using test::addMaterial;
using test::expectColorNear;

// --- The triangle map ------------------------------------------------------------------------

TEST(MeshUv, TriangleUV_InterpolatesAndItsGradientsAreTheTrianglesLinearMap) {
    // p0 = 0, p1 = (2, 0, 0), p2 = (0, 4, 0) with uvs 0, (1, 0), (0, 1): u = x / 2, v = y / 4.
    const ShapeUV uv = triangleUV(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 4, 0), glm::vec2(0, 0),
                                  glm::vec2(1, 0), glm::vec2(0, 1), 0.25f, 0.5f);
    // The point 0.25 p1 + 0.5 p2 = (0.5, 2, 0).
    EXPECT_NEAR(uv.u, 0.5 / 2.0, 1e-6);
    EXPECT_NEAR(uv.v, 2.0 / 4.0, 1e-6);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(uv.dudp[k], k == 0 ? 0.5 : 0.0, 1e-6) << k;
        EXPECT_NEAR(uv.dvdp[k], k == 1 ? 0.25 : 0.0, 1e-6) << k;
    }
    // A sheared triangle: the gradient still reproduces the change along both edges.
    const Vec3 p0(1, 1, 1), p1(3, 2, 1), p2(2, 4, 3);
    const glm::vec2 t0(0.1f, 0.2f), t1(0.7f, 0.3f), t2(0.4f, 0.9f);
    const ShapeUV s = triangleUV(p0, p1, p2, t0, t1, t2, 0.0f, 0.0f);
    EXPECT_NEAR(glm::dot(s.dudp, p1 - p0), 0.6, 1e-5);
    EXPECT_NEAR(glm::dot(s.dudp, p2 - p0), 0.3, 1e-5);
    EXPECT_NEAR(glm::dot(s.dvdp, p1 - p0), 0.1, 1e-5);
    EXPECT_NEAR(glm::dot(s.dvdp, p2 - p0), 0.7, 1e-5);
    // Degenerate: no gradient.
    const ShapeUV flat = triangleUV(p0, p0, p0, t0, t1, t2, 0.0f, 0.0f);
    EXPECT_EQ(flat.dudp, Vec3(0.0f));
    EXPECT_EQ(flat.dvdp, Vec3(0.0f));
}

// --- The import wire -------------------------------------------------------------------------

std::string throughPipe(const std::function<void(int)>& write) {
    ChildLimits limits;
    limits.wallTime = std::chrono::milliseconds(60000);
    return runInChildProcess(write, limits).output;
}

MeshData texturedTriangle() {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.uvs = {glm::vec2(0.25f, 0.5f), glm::vec2(1.5f, -2.0f), glm::vec2(0.125f, 3.0f)};
    mesh.indices = {0, 1, 2};
    return mesh;
}

TEST(MeshUvWire, UVs_RoundTripBitForBit) {
    const MeshData mesh = texturedTriangle();
    const std::string bytes = throughPipe([&](int fd) { writeMeshWire(fd, mesh); });
    const MeshLoadResult r = decodeMeshWire(bytes, "/t.obj");
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.mesh->uvs.size(), 3u);
    EXPECT_EQ(std::memcmp(r.mesh->uvs.data(), mesh.uvs.data(), 3 * sizeof(glm::vec2)), 0);
    EXPECT_EQ(r.mesh->indices, mesh.indices);
    // Without UVs the mesh comes back without them.
    MeshData bare = mesh;
    bare.uvs.clear();
    const MeshLoadResult b =
        decodeMeshWire(throughPipe([&](int fd) { writeMeshWire(fd, bare); }), "/t.obj");
    ASSERT_TRUE(b.ok()) << b.error;
    EXPECT_TRUE(b.mesh->uvs.empty());
}

TEST(MeshUvWire, UVCountNotPerVertex_IsMalformed) {
    const std::string bytes = throughPipe([&](int fd) { writeMeshWire(fd, texturedTriangle()); });
    // Header: 8 magic bytes, marker, then positions, normals, indices, dropped, uvs.
    auto withUvCount = [&](std::uint64_t value) {
        std::string lie = bytes;
        std::memcpy(&lie[8 + 8 * 5], &value, sizeof value);
        return decodeMeshWire(lie, "");
    };
    const MeshLoadResult two = withUvCount(2);
    EXPECT_FALSE(two.ok());
    EXPECT_NE(two.error.find("texture coordinates that are not per vertex"), std::string::npos)
        << two.error;
    EXPECT_EQ(withUvCount(~std::uint64_t(0)).error.find("malformed"), 0u);
    // Every cut of a mesh with UVs is malformed too.
    for (std::size_t n = 0; n < bytes.size(); ++n)
        EXPECT_EQ(decodeMeshWire(bytes.substr(0, n), "").error.find("malformed"), 0u) << n;
}

// --- Import and render -----------------------------------------------------------------------

class MeshUvFiles : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "raystudio-mesh-uv-XXXXXX").string();
        ASSERT_NE(mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string writeText(const std::string& name, const std::string& text) {
        const std::string file = (dir_ / name).string();
        std::ofstream(file) << text;
        return file;
    }
    /// The quad [0, 2] x [0, 2] at z = 0 facing +Z, (u, v) = (x / 2, y / 2) at its corners.
    std::string quadObj() {
        return writeText("quad.obj",
                         "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\n"
                         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                         "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    }
    /// A 2 x 2 8-bit PNG, top row first: red, green / blue, white (codes 0 and 255 only, so
    /// sRGB decoding gives exactly 0 and 1).
    std::string checkerPng() {
        const std::string file = (dir_ / "four.png").string();
        const uint8_t pixels[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
        auto out = OIIO::ImageOutput::create(file);
        EXPECT_TRUE(out) << OIIO::geterror();
        if (!out) return file;
        const OIIO::ImageSpec spec(2, 2, 3, OIIO::TypeDesc::UINT8);
        EXPECT_TRUE(out->open(file, spec)) << out->geterror();
        EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels)) << out->geterror();
        EXPECT_TRUE(out->close());
        return file;
    }
    fs::path dir_;
};

TEST_F(MeshUvFiles, ObjTextureCoordinates_AreImportedOnePerVertex) {
    for (bool smooth : {false, true}) {
        const MeshLoadResult r = loadMesh(quadObj(), smooth);
        ASSERT_TRUE(r.ok()) << r.error;
        ASSERT_EQ(r.mesh->uvs.size(), r.mesh->positions.size()) << smooth;
        EXPECT_EQ(r.mesh->positions.size(), 4u);
        for (std::size_t i = 0; i < r.mesh->positions.size(); ++i) {
            const Vec3& p = r.mesh->positions[i];
            EXPECT_NEAR(r.mesh->uvs[i].x, p.x / 2.0, 1e-6) << i;
            EXPECT_NEAR(r.mesh->uvs[i].y, p.y / 2.0, 1e-6) << i;
        }
    }
    // A file without vt lines has no channel.
    const MeshLoadResult bare =
        loadMesh(writeText("bare.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), true);
    ASSERT_TRUE(bare.ok()) << bare.error;
    EXPECT_TRUE(bare.mesh->uvs.empty());
}

TEST_F(MeshUvFiles, TexturedQuadShowsEachTexelWhereItsUVsSay_OnBothEngines) {
    const MeshLoadResult loaded = loadMesh(quadObj(), true);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    SceneDocument doc;
    doc.render.ambient = Color(1.0f);  // No light: the texel's colour.
    addMaterial(doc, "map", Color(0.8f), 1.0f);
    ImageTexture t;
    t.image.file = checkerPng();
    doc.materials.back().pattern = t;
    Object o;
    o.name = "quad";
    o.material = "map";
    MeshGeometry g;
    g.file = "quad.obj";
    g.data = loaded.mesh;
    o.geometry = g;
    o.transform.translate = Vec3(10, -3, 0);  // The UVs move with the object.
    doc.addObject(o);
    // (u, v) = ((x - 10) / 2, (y + 3) / 2); v = 1 is the image's top row.
    struct Probe {
        float x, y;
        Color expected;
    };
    const Probe probes[] = {{10.5f, -1.5f, Color(1, 0, 0)},  // u, v = 1/4, 3/4: top left
                            {11.5f, -1.5f, Color(0, 1, 0)},  // 3/4, 3/4: top right
                            {10.5f, -2.5f, Color(0, 0, 1)},  // 1/4, 1/4: bottom left
                            {11.5f, -2.5f, Color(1, 1, 1)}};
    for (EngineKind engine : {EngineKind::Embree, EngineKind::Builtin}) {
        const CompiledScene scene(doc, nullptr, engine);
        EXPECT_TRUE(scene.problems().empty());
        const WhittedIntegrator integrator(scene);
        for (const Probe& p : probes) {
            TraceCounters counters;
            const Ray ray = Ray::make(Vec3(p.x, p.y, 5.0f), Vec3(0, 0, -1));
            expectColorNear(integrator.traceCamera(ray, 11u, counters), p.expected, 1.5e-3f,
                            std::string(engineName(engine)) + " at " + std::to_string(p.x) + ", " +
                                std::to_string(p.y));
        }
    }
}

}  // namespace
}  // namespace rs
