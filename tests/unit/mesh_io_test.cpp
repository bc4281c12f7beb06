// Mesh loading through assimp: formats, node transforms, degenerate triangles and bad files.
#include "io/mesh_io.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>

#include "core/input_file.h"

namespace rs {
namespace {

std::string meshPath(const char* name) {
    return std::string(RAYSTUDIO_TEST_DATA) + "/meshes/" + name;
}

struct FormatCase {
    const char* file;
    std::size_t triangles;
    Vec3 min;
    Vec3 max;
};

class MeshFormat : public testing::TestWithParam<FormatCase> {};

TEST_P(MeshFormat, LoadsWithTriangleCountAndBounds) {
    const FormatCase& c = GetParam();
    MeshLoadResult r = loadMesh(meshPath(c.file), true);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.mesh->triangleCount(), c.triangles);
    EXPECT_EQ(r.mesh->indices.size(), 3 * c.triangles);
    Aabb b = r.mesh->bounds();
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(b.min[a], c.min[a], 1e-5f) << "axis " << a;
        EXPECT_NEAR(b.max[a], c.max[a], 1e-5f) << "axis " << a;
    }
    EXPECT_EQ(r.mesh->droppedDegenerate, 0u);
    EXPECT_TRUE(std::filesystem::path(r.mesh->sourcePath).is_absolute());
    for (uint32_t i : r.mesh->indices) ASSERT_LT(i, r.mesh->positions.size());
}

INSTANTIATE_TEST_SUITE_P(
    Formats, MeshFormat,
    testing::Values(
        FormatCase{"cube.obj", 12, Vec3(0), Vec3(1)}, FormatCase{"tetra.ply", 4, Vec3(0), Vec3(1)},
        FormatCase{"tetra.off", 4, Vec3(0), Vec3(1)}, FormatCase{"tetra.stl", 4, Vec3(0), Vec3(1)},
        // The node translates the unit quad by +10 in x: transforms are applied.
        FormatCase{"quad_translated.gltf", 2, Vec3(10, 0, 0), Vec3(11, 1, 0)},
        FormatCase{"cube.glb", 12, Vec3(0), Vec3(1)}, FormatCase{"cube.fbx", 12, Vec3(0), Vec3(1)}),
    [](const testing::TestParamInfo<FormatCase>& info) {
        std::string name = info.param.file;
        for (char& ch : name)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return name;
    });

TEST(MeshIo, SmoothNormals_GivesOneUnitNormalPerVertex) {
    MeshLoadResult r = loadMesh(meshPath("cube.obj"), true);
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.mesh->normals.size(), r.mesh->positions.size());
    for (const Vec3& n : r.mesh->normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    // A cube corner's smooth normal points diagonally away from the centre.
    for (std::size_t i = 0; i < r.mesh->positions.size(); ++i) {
        Vec3 outward = r.mesh->positions[i] - Vec3(0.5f);
        EXPECT_GT(glm::dot(r.mesh->normals[i], outward), 0.0f);
    }
}

TEST(MeshIo, FlatShading_LeavesNormalsEmptyAndSharesVertices) {
    MeshLoadResult r = loadMesh(meshPath("tetra.stl"), false);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.mesh->normals.empty());
    // STL repeats corners per facet; joined, the tetrahedron has its 4 corners.
    EXPECT_EQ(r.mesh->positions.size(), 4u);
}

TEST(MeshIo, DegenerateTriangles_AreDroppedAndCounted) {
    MeshLoadResult r = loadMesh(meshPath("degenerate.obj"), false);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.mesh->triangleCount(), 2u);
    EXPECT_EQ(r.mesh->droppedDegenerate, 2u);
    // The vertex only a dropped triangle used (2, 0, 0) is gone from the bounds.
    EXPECT_EQ(r.mesh->bounds().max, Vec3(1, 1, 0));
}

TEST(MeshIo, NanVertex_IsAnErrorNamingThePath) {
    MeshLoadResult r = loadMesh(meshPath("nan_vertex.obj"), true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find(meshPath("nan_vertex.obj")), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("not a finite number"), std::string::npos) << r.error;
}

TEST(MeshIo, NoTriangles_IsAnError) {
    MeshLoadResult r = loadMesh(meshPath("lines_only.obj"), true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("no triangles"), std::string::npos) << r.error;
}

TEST(MeshIo, MissingFile_ErrorNamesThePath) {
    MeshLoadResult r = loadMesh(meshPath("missing.obj"), true);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.mesh, nullptr);
    EXPECT_NE(r.error.find(meshPath("missing.obj")), std::string::npos) << r.error;
}

TEST(MeshIo, FileAssimpCannotRead_IncludesAssimpsReason) {
    // A scene file is JSON, which no assimp importer accepts.
    std::string path = std::string(RAYSTUDIO_TEST_DATA) + "/scenes/example.scene.json";
    MeshLoadResult r = loadMesh(path, true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("assimp"), std::string::npos) << r.error;
}

TEST(MeshIo, Directory_IsAnError) {
    MeshLoadResult r = loadMesh(std::string(RAYSTUDIO_TEST_DATA) + "/meshes", true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("not a regular file"), std::string::npos) << r.error;
}

TEST(MeshIo, Device_IsRefusedWithoutReadingIt) {
    MeshLoadResult r = loadMesh("/dev/zero", true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("/dev/zero"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("device"), std::string::npos) << r.error;
}

// Hand-made mesh files in a fresh folder, removed afterwards.
class MeshFiles : public testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::path(testing::TempDir()) /
               ("mesh_io_" +
                std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& bytes) {
        const std::string p = (dir_ / name).string();
        std::ofstream(p, std::ios::binary) << bytes;
        return p;
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::filesystem::path dir_;
};

// The unit tetrahedron's four vertices, then (when `withFaces`) its four faces, as the body
// of a little-endian binary PLY (this test runs on little-endian machines only).
std::string binaryTetraBody(bool withFaces = true) {
    std::string body;
    auto put = [&](const void* p, std::size_t n) { body.append(static_cast<const char*>(p), n); };
    const float corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& c : corners) put(c, sizeof c);
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& f : faces) {
        if (!withFaces) break;
        const unsigned char three = 3;
        put(&three, 1);
        put(f, sizeof f);
    }
    return body;
}

std::string binaryPlyHeader(const char* vertexCount, const char* faceCount = "4") {
    return std::string("ply\nformat binary_little_endian 1.0\nelement vertex ") + vertexCount +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + faceCount +
           "\nproperty list uchar int vertex_indices\nend_header\n";
}

// Loads `path`, expecting a refusal within a second whose message names the file.
// "Quickly" means the header check refused the file before any importer read it: the error
// names the check's finding (a timed assertion would race the clock on a loaded CI machine,
// and a message from the check cannot come from an import that ran to its end).
void expectRefusedQuickly(const std::string& path, const char* part) {
    MeshLoadResult r = loadMesh(path, true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
    EXPECT_NE(r.error.find(part), std::string::npos) << r.error;
}

TEST_F(MeshFiles, BinaryPly_Loads) {
    MeshLoadResult r = loadMesh(write("t.ply", binaryPlyHeader("4") + binaryTetraBody()), true);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.mesh->triangleCount(), 4u);
}

TEST_F(MeshFiles, OffClaimingMoreVerticesThanTheFileHolds_IsRefusedQuickly) {
    const std::string path = write("lie.off",
                                   "OFF\n1350000000 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                   "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    expectRefusedQuickly(path, "OFF header declares 1350000000 vertices");
}

TEST_F(MeshFiles, OffVertexCountBeyondAnyInteger_IsRefused) {
    expectRefusedQuickly(write("huge.off", "OFF\n99999999999999999999999 1 0\n0 0 0\n"),
                         "too large");
}

// Found by tests/fuzz/mesh_loader_fuzz (corpus/mesh_loader/off-face-count-garbage.off): the
// importer reads a count's leading digits, so a face count with garbage after its digits
// must not make the check give up on the vertex count.
TEST_F(MeshFiles, OffLieWithGarbageAfterACount_IsRefusedQuickly) {
    const std::string garbage("OFF\n1350000000 1\x01\0\0\0 0\n0 0 0\n3 0 0 0\n", 37);
    expectRefusedQuickly(write("lie.off", garbage), "OFF header declares 1350000000 vertices");
    // Garbage glued to the vertex count is where the importer reads the face count: 0 faces,
    // which it refuses before allocating anything, so the check leaves it to the importer.
    MeshLoadResult glued =
        loadMesh(write("lie2.off", "OFF\n1350000000abc 1 0\n0 0 0\n3 0 0 0\n"), true);
    EXPECT_FALSE(glued.ok());
    EXPECT_NE(glued.error.find("no valid faces"), std::string::npos) << glued.error;
}

// Found by tests/fuzz/mesh_loader_fuzz (corpus/mesh_loader/off-headerless-lie.off, whose
// first byte picks the extension): a file named *.off whose first line is no OFF keyword is
// still read as OFF, its counts from the first token on; 675 million vertices in a few bytes
// made the importer allocate 8 GB.
TEST_F(MeshFiles, OffWithoutItsKeywordClaimingMoreThanTheFileHolds_IsRefusedQuickly) {
    expectRefusedQuickly(write("lie.off", "# not a keyword OFF\n0675000000 1 0\n0 0 0\n3 0 0 0\n"),
                         "OFF header declares 675000000 vertices");
    expectRefusedQuickly(write("bare.OFF", "1350000000 1 0\n0 0 0\n3 0 0 0\n"),
                         "OFF header declares 1350000000 vertices");
    // corpus/mesh_loader/off-glued-keyword-lie.off: the importer takes "NOFF" as a prefix.
    expectRefusedQuickly(write("glued.off", "NOFF1350000000 1 0\n0 0 0\n3 0 0 0\n"),
                         "OFF header declares 1350000000 vertices");
    // Other formats are not read as OFF: an OBJ's numbers are no counts.
    MeshLoadResult obj =
        loadMesh(write("t.obj", "# 900000000 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), true);
    EXPECT_TRUE(obj.ok()) << obj.error;
}

// The check reads the header as assimp 5.2's OFF importer does (mesh_header_check.cpp), so
// the shapes of header the importer allocates for are the shapes the check refuses.
TEST_F(MeshFiles, OffHeaderReadAsTheImporterReadsIt) {
    // Prefix letters are taken one after another even where no keyword follows: "C" then
    // the counts (vertex colours allocated too).
    expectRefusedQuickly(write("c.off", "C0675000000 1 0\n0 0 0\n3 0 0 0\n"),
                         "OFF header declares 675000000 vertices");
    // A UTF-8 byte order mark is dropped before parsing.
    expectRefusedQuickly(write("bom.off", "\xEF\xBB\xBFOFF\n1350000000 1 0\n0 0 0\n3 0 0 0\n"),
                         "OFF header declares 1350000000 vertices");
    // A NUL ends the importer's text: the lines after it do not count.
    std::string nul("OFF\n4 4 0\n\0", 11);
    nul += std::string(4000, ' ') +
           "\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    expectRefusedQuickly(write("nul.off", nul), "NUL byte at offset 10");
    // A file another name's importer takes is not checked as OFF unless it starts as one.
    MeshLoadResult obj =
        loadMesh(write("off.obj", "# OFF 900000000 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), true);
    EXPECT_TRUE(obj.ok()) << obj.error;
    // What the importer refuses by itself ("OFF: Header is invalid") is left to it: the
    // check does not invent counts from a later token.
    MeshLoadResult bang =
        loadMesh(write("bang.off", "! not a keyword\n0675000000 1 0\n0 0 0\n3 0 0 0\n"), true);
    EXPECT_FALSE(bang.ok());
    EXPECT_EQ(bang.error.find("OFF header declares"), std::string::npos) << bang.error;
    // The importer takes a line for each vertex and face, a byte and a line end at the least
    // (the last needs no end): lines that just hold the counts pass the check, one line
    // fewer does not.
    MeshLoadResult tight = loadMesh(write("tight.off", "OFF 3 1 0\n0\n1\n2\n3"), true);
    EXPECT_EQ(tight.error.find("OFF header declares"), std::string::npos) << tight.error;
    expectRefusedQuickly(write("short.off", "OFF 3 2 0\n0\n1\n2\n3"),
                         "OFF header declares 3 vertices, 2 faces");
}

TEST_F(MeshFiles, AsciiPlyClaimingMoreVerticesThanTheFileHolds_IsRefusedQuickly) {
    std::ifstream in(meshPath("tetra.ply"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("element vertex 4"), 16, "element vertex 2000000000");
    expectRefusedQuickly(write("lie.ply", text), "PLY header declares 2000000000 vertex");
}

TEST_F(MeshFiles, BinaryPlyClaimingMoreVerticesThanTheFileHolds_IsRefusedQuickly) {
    expectRefusedQuickly(write("lie.ply", binaryPlyHeader("2000000000") + binaryTetraBody()),
                         "PLY header declares 2000000000 vertex");
}

// Found by tests/fuzz/mesh_loader_fuzz (corpus/mesh_loader/ply-unknown-type-lie.ply): a
// property type the check did not know made it give up, and assimp read on for minutes.
TEST_F(MeshFiles, PlyWithAnUnknownPropertyTypeClaimingManyVertices_IsRefusedQuickly) {
    std::ifstream in(meshPath("tetra.ply"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("element vertex 4"), 16, "element vertex 2000000000");
    text.replace(text.find("property float x"), 16, "property floa\x94 x");
    expectRefusedQuickly(write("lie.ply", text), "PLY header declares 2000000000 vertex");
    std::string binary = binaryPlyHeader("2000000000");
    binary.replace(binary.find("float y"), 5, "quad ");
    expectRefusedQuickly(write("lie-binary.ply", binary + binaryTetraBody()),
                         "PLY header declares 2000000000 vertex");
}

// Found by tests/fuzz/mesh_loader_fuzz (corpus/mesh_loader/ply-no-end-header.ply): assimp
// never returns from a PLY header without end_header, whatever follows its magic number.
TEST_F(MeshFiles, PlyHeaderWithoutEndHeader_IsRefusedQuickly) {
    expectRefusedQuickly(write("cut.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"),
                         "no end_header");
    expectRefusedQuickly(write("cut2.ply", "ply2\nformat ascii 1.0\n"), "no end_header");
}

// Found by tests/fuzz/mesh_loader_fuzz (corpus/mesh_loader/ply-property-list-without-types.ply):
// a "property list" line with no types made the header check read past its words (ASan).
TEST_F(MeshFiles, PlyPropertyListWithoutTypes_IsCheckedWithinItsWords) {
    std::string binary = binaryPlyHeader("4", "2000000000");
    const std::size_t list = binary.find("property list");
    ASSERT_NE(list, std::string::npos);
    binary.replace(list, binary.find('\n', list) - list, "property list");
    expectRefusedQuickly(write("list.ply", binary + binaryTetraBody()), "2000000000 face elements");
}

TEST_F(MeshFiles, BinaryPlyOneVertexShort_IsRefused) {
    // Without faces, a binary vertex list is exactly 12 bytes a vertex: one more is a lie.
    expectRefusedQuickly(write("short.ply", binaryPlyHeader("5", "0") + binaryTetraBody(false)),
                         "5 vertex");
}

TEST_F(MeshFiles, Fifo_IsRefusedWithoutBlocking) {
    const std::string fifo = path("pipe.obj");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
    expectRefusedQuickly(fifo, "FIFO");
}

// The importer opens the files a mesh names too: an OBJ whose material library is a FIFO
// must not block (the library is left out, as a missing one is).
TEST_F(MeshFiles, ObjWhoseMaterialLibraryIsAFifo_LoadsWithoutBlocking) {
    const std::string fifo = path("materials.mtl");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
    const std::string obj =
        write("t.obj", "mtllib materials.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    auto load = std::async(std::launch::async, [&] { return loadMesh(obj, false); });
    if (load.wait_for(std::chrono::seconds(10)) != std::future_status::ready) {
        // Blocked in open(): a writer that closes at once lets it go on, then fail.
        ::close(::open(fifo.c_str(), O_WRONLY));
        load.wait();
        FAIL() << "loading blocked on the FIFO";
    }
    const MeshLoadResult r = load.get();
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.mesh->triangleCount(), 1u);
}

TEST_F(MeshFiles, FileAboveTheSizeLimit_IsRefusedBeforeReading) {
    // A sparse file: its size is over the limit, its blocks are not on disk.
    const std::string big = write("big.stl", "solid x\n");
    std::filesystem::resize_file(big, kMaxMeshFileBytes + 1);
    expectRefusedQuickly(big, "limit");
}

// A binary STL of `triangles` separate facets on a grid (no corner shared): 50 bytes each, the
// densest of the formats for assimp's memory (about 40 bytes of its heap per byte of file).
std::string binaryStl(std::uint32_t triangles) {
    std::string bytes(80, ' ');
    bytes.append(reinterpret_cast<const char*>(&triangles), 4);
    for (std::uint32_t i = 0; i < triangles; ++i) {
        const float x = 3.0f * float(i % 1000), y = 3.0f * float(i / 1000);
        const float facet[12] = {0, 0, 1, x, y, 0, x + 1, y, 0, x, y + 1, 0};
        bytes.append(reinterpret_cast<const char*>(facet), sizeof facet);
        bytes.append(2, '\0');
    }
    return bytes;
}

// The default budget is for real meshes: a 250,000-triangle binary STL (12.5 MB) needs about
// 500 MiB of assimp's heap, which the earlier 256 MiB + 16 bytes a byte (456 MiB) refused,
// and with it the benchmarks' 1M-triangle OBJ.
TEST_F(MeshFiles, LargeBinaryStl_LoadsWithinTheDefaultBudget) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "a sanitizer's allocator needs several times assimp's own memory";
#endif
    const std::string stl = write("large.stl", binaryStl(250000));
    MeshLoadResult r = loadMesh(stl, true);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.mesh->triangleCount(), 250000u);
}

}  // namespace
}  // namespace rs
