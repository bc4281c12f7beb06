// Mesh imports in a child process: a crashing importer, the triangles that come back, the
// budgets, and the wire format that carries them.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "io/child_process.h"
#include "io/mesh_import.h"
#include "io/mesh_io.h"
#include "io/mesh_wire.h"

namespace rs {
namespace {

namespace fs = std::filesystem;

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / "mesh_import_child";
    fs::create_directories(dir);
    return dir / name;
}

/// Fuzz corpus input `input` (tests/fuzz/corpus/mesh_loader/) as the fuzzer hands it to the
/// loader: its first byte picks the extension (mesh_loader_fuzz.cpp), the file is the rest,
/// written as `name` in the scratch folder. "" when the input is missing.
std::string corpusFile(const std::string& input, const std::string& name) {
    const std::string bytes =
        readBytes(std::string(RAYSTUDIO_TEST_DATA) + "/../fuzz/corpus/mesh_loader/" + input);
    if (bytes.size() < 2) return "";
    const std::string path = scratch(name).string();
    std::ofstream(path, std::ios::binary) << bytes.substr(1);
    return path;
}

// The malformed binary PLY the mesh loader fuzzer found (tests/fuzz/corpus/mesh_loader/):
// Debian's assimp 5.2 fails an assertion in its triangulation on it and aborts.
TEST(MeshImportChild, AssimpAbortingOnAFile_IsAnErrorNamingItAndThisProcessGoesOn) {
    const std::string path = corpusFile("assimp-triangulate-assert.ply", "triangulate-assert.ply");
    ASSERT_NE(path, "");
    for (bool smooth : {false, true}) {
        const MeshLoadResult r = loadMesh(path, smooth);
        EXPECT_FALSE(r.ok());
        EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
        EXPECT_NE(r.error.find("assimp crashed while reading"), std::string::npos) << r.error;
        EXPECT_NE(r.error.find("signal 6"), std::string::npos) << r.error;
        // The child's own stderr comes with it whole; the error quotes its first line.
        const std::size_t quote = r.error.find("): ");
        ASSERT_NE(quote, std::string::npos) << r.error;
        EXPECT_NE(r.childMessages.find(r.error.substr(quote + 3)), std::string::npos)
            << r.childMessages;
    }
    // Still here, and the loader still works.
    EXPECT_TRUE(loadMesh(std::string(RAYSTUDIO_TEST_DATA) + "/meshes/cube.obj", true).ok());
}

// The fuzzer's input whose refusal quoted "runtime error" from the file, which a CI fuzz run
// took for a sanitizer's report: a refusal before any child runs carries no child messages,
// whatever its error quotes.
TEST(MeshImportChild, ARefusalQuotingTheFile_CarriesNoChildMessages) {
    const std::string path = corpusFile("harness-echoed-runtime-error", "echoed-runtime-error.off");
    ASSERT_NE(path, "");
    const MeshLoadResult r = loadMesh(path, false);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("runtime error"), std::string::npos) << r.error;
    EXPECT_EQ(r.childMessages, "") << r.error;
}

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    // (An empty vector's data() may be null, which memcmp must not be given.)
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

TEST(MeshImportChild, GoodMeshes_ComeBackBitForBitAsAnImportInThisProcess) {
    const std::string data = std::string(RAYSTUDIO_TEST_DATA) + "/meshes/";
    for (const std::string& file :
         {data + "cube.obj", data + "tetra.ply", data + "tetra.off", data + "tetra.stl",
          data + "quad_translated.gltf", data + "cube.glb", data + "cube.fbx",
          data + "degenerate.obj", std::string(RAYSTUDIO_SCENES_DIR) + "/meshes/torus.obj"}) {
        for (bool smooth : {false, true}) {
            SCOPED_TRACE(file + (smooth ? " smooth" : " flat"));
            const MeshLoadResult child = loadMesh(file, smooth);
            const MeshLoadResult here = importMeshWithAssimp(file, smooth);
            ASSERT_TRUE(child.ok()) << child.error;
            ASSERT_TRUE(here.ok()) << here.error;
            EXPECT_TRUE(sameBits(child.mesh->positions, here.mesh->positions));
            EXPECT_TRUE(sameBits(child.mesh->normals, here.mesh->normals));
            EXPECT_TRUE(sameBits(child.mesh->indices, here.mesh->indices));
            EXPECT_EQ(child.mesh->normals.empty(), !smooth);
            EXPECT_EQ(child.mesh->droppedDegenerate, here.mesh->droppedDegenerate);
            EXPECT_EQ(child.mesh->sourcePath, fs::path(file).lexically_normal().string());
        }
    }
}

/// A flat grid of `n` x `n` quads as an OBJ: a few megabytes that take assimp a while.
std::string writeGrid(const std::string& name, int n) {
    const std::string path = scratch(name).string();
    std::ofstream out(path);
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) out << "v " << x << ' ' << y << " 0\n";
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int a = y * (n + 1) + x + 1;
            out << "f " << a << ' ' << a + 1 << ' ' << a + n + 2 << ' ' << a + n + 1 << '\n';
        }
    return path;
}

// The budget is injected: a millisecond for a 5 MB import, which no machine does that fast.
TEST(MeshImportChild, TimeBudget_StopsTheImportWithAnErrorNamingTheFile) {
    const std::string path = writeGrid("grid-time.obj", 300);
    MeshImportOptions options;
    options.wallTime = std::chrono::milliseconds(1);
    const MeshLoadResult r = loadMesh(path, true, options);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("took longer than its 0.001 s budget"), std::string::npos) << r.error;
    // With time to spare the same file loads (an hour: no machine's load makes it miss that).
    options.wallTime = std::chrono::hours(1);
    const MeshLoadResult whole = loadMesh(path, false, options);
    ASSERT_TRUE(whole.ok()) << whole.error;
    EXPECT_EQ(whole.mesh->triangleCount(), 2u * 300 * 300);
}

TEST(MeshImportChild, MemoryBudget_StopsTheImportWithAnErrorNamingTheFile) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "a sanitizer's allocator reserves its address space up front and dies "
                    "(a crash, also an error) when a fresh mapping fails";
#endif
    const std::string path = writeGrid("grid-memory.obj", 300);
    MeshImportOptions options;
    options.memoryBytes = std::uintmax_t(4) << 20;  // The vertices alone need more.
    const MeshLoadResult r = loadMesh(path, true, options);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("more than its 4 MiB memory budget"), std::string::npos) << r.error;
}

TEST(MeshImportChild, Cancel_StopsTheImport) {
    std::atomic<bool> cancel{true};
    MeshImportOptions options;
    options.cancel = &cancel;
    const MeshLoadResult r =
        loadMesh(std::string(RAYSTUDIO_TEST_DATA) + "/meshes/cube.obj", true, options);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("cancelled"), std::string::npos) << r.error;
}

// What the parent reads back is checked: bytes written by writeMeshWire through a pipe, then
// every cut and a few lies.
class MeshWire : public testing::Test {
protected:
    static std::string throughPipe(const std::function<void(int)>& write) {
        ChildLimits limits;
        limits.wallTime = std::chrono::milliseconds(60000);
        return runInChildProcess(write, limits).output;
    }
    static MeshData tetra() {
        MeshData mesh;
        mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
        mesh.normals = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
        mesh.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
        mesh.droppedDegenerate = 5;
        return mesh;
    }
};

TEST_F(MeshWire, AMesh_RoundTrips) {
    const MeshData mesh = tetra();
    const std::string bytes = throughPipe([&](int fd) { writeMeshWire(fd, mesh); });
    const MeshLoadResult r = decodeMeshWire(bytes, "/m.obj");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(sameBits(r.mesh->positions, mesh.positions));
    EXPECT_TRUE(sameBits(r.mesh->normals, mesh.normals));
    EXPECT_EQ(r.mesh->indices, mesh.indices);
    EXPECT_EQ(r.mesh->droppedDegenerate, 5u);
    EXPECT_EQ(r.mesh->sourcePath, "/m.obj");
}

TEST_F(MeshWire, AnError_RoundTrips) {
    const std::string bytes = throughPipe([](int fd) { writeMeshWireError(fd, "no triangles"); });
    const MeshLoadResult r = decodeMeshWire(bytes, "/m.obj");
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.error, "no triangles");
}

TEST_F(MeshWire, EveryCutAndTrailingBytes_AreMalformed) {
    const MeshData mesh = tetra();
    const std::string bytes = throughPipe([&](int fd) { writeMeshWire(fd, mesh); });
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        const MeshLoadResult r = decodeMeshWire(bytes.substr(0, n), "");
        EXPECT_FALSE(r.ok()) << n;
        EXPECT_EQ(r.error.find("malformed"), 0u) << r.error;
    }
    EXPECT_FALSE(decodeMeshWire(bytes + "x", "").ok());
    const std::string error = throughPipe([](int fd) { writeMeshWireError(fd, "bad"); });
    for (std::size_t n = 0; n < error.size(); ++n)
        EXPECT_EQ(decodeMeshWire(error.substr(0, n), "").error.find("malformed"), 0u) << n;
}

TEST_F(MeshWire, LyingCountsAndIndices_AreMalformed) {
    MeshData mesh = tetra();
    std::string bytes = throughPipe([&](int fd) { writeMeshWire(fd, mesh); });
    // Header: 8 magic bytes, marker, then the counts of positions, normals, indices, dropped.
    auto withCount = [&](int field, std::uint64_t value) {
        std::string lie = bytes;
        std::memcpy(&lie[8 + 8 * (1 + field)], &value, sizeof value);
        return decodeMeshWire(lie, "");
    };
    EXPECT_FALSE(withCount(0, ~std::uint64_t(0)).ok());
    EXPECT_FALSE(withCount(0, std::uint64_t(1) << 61).ok());
    EXPECT_FALSE(withCount(1, 3).ok());   // normals, not one per vertex
    EXPECT_FALSE(withCount(2, 11).ok());  // not whole triangles
    EXPECT_FALSE(withCount(2, 0).ok());   // no triangles
    mesh.indices[7] = 4;                  // one past the vertices
    bytes = throughPipe([&](int fd) { writeMeshWire(fd, mesh); });
    const MeshLoadResult r = decodeMeshWire(bytes, "");
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("index past the vertices"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace rs
