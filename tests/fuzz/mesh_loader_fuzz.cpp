// libFuzzer target for the mesh loader on small files: the first byte picks the format (the
// importer goes by the file name's extension) and the normals, the rest is the file. Any
// bytes load to a mesh or to an error, never a crash, a sanitizer report or an allocation for
// a lying header. assimp runs in loadMesh's child process, so its crashes are errors here; a
// sanitizer report from the child (our code in it is instrumented) reaches the error
// message, and is a finding. libFuzzer sees the coverage of this process only (the guards,
// the header check, the wire decoding). The bytes are also the folder's "mesh.mtl", so an OBJ
// that names it (`mtllib mesh.mtl`) reads its own lines as materials: the parts and the looks
// that come back with them are fuzzed too.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "io/asset_content.h"
#include "io/mesh_io.h"

namespace {
constexpr std::array<const char*, 4> kExtensions = {".obj", ".off", ".ply", ".stl"};

/// One folder per fuzzing process (libFuzzer's -fork and -jobs run several).
const std::string& scratchDir() {
    static const std::string dir = [] {
        std::string pattern = "/tmp/raystudio-mesh-fuzz-XXXXXX";
        if (!mkdtemp(pattern.data())) std::abort();
        static std::string removeAtExit = pattern;
        // The folder holds the last input's "mesh.mtl" (each input's mesh file goes with it).
        std::atexit([] {
            std::remove((removeAtExit + "/mesh.mtl").c_str());
            rmdir(removeAtExit.c_str());
        });
        return pattern;
    }();
    return dir;
}

[[noreturn]] void broken(const char* what, const std::string& detail = "") {
    std::fprintf(stderr, "mesh_loader_fuzz: %s %s\n", what, detail.c_str());
    std::abort();
}

/// Under libFuzzer's own per-input limit (-timeout=10 in setup.sh) and far under its memory
/// limit, so a slow or greedy import is the child's error, not a fuzzer timeout.
rs::MeshImportOptions budget() {
    rs::MeshImportOptions options;
    options.memoryBytes = std::uintmax_t(512) << 20;
    options.wallTime = std::chrono::seconds(5);
    return options;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const std::string path = scratchDir() + "/mesh" + kExtensions[data[0] % kExtensions.size()];
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
        if (!out) broken("cannot write the scratch file");
        std::ofstream(scratchDir() + "/mesh.mtl", std::ios::binary | std::ios::trunc)
            .write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    }
    // One import an input (each is a fork of this large process): the next bit of the first
    // byte picks smooth or flat normals.
    const bool smooth = (data[0] / kExtensions.size()) % 2 == 1;
    const rs::MeshLoadResult result = rs::loadMesh(path, smooth, budget());
    std::remove(path.c_str());
    if (!result.ok()) {
        if (result.error.empty()) broken("a failed load without a message");
        // Only a child that crashed or failed can have printed a sanitizer's report, and only
        // its own stderr is read: a refusal may quote the file's bytes, and the fuzzer learns
        // the words searched for (a CI fuzz run once took an OFF count followed by "runtime
        // error", echoed by the header check, for a finding). The child hitting its memory budget
        // is the budget at work, not a finding: a header that lies in a way the header check
        // does not read (assimp allocating for it) ends there, as in a release build, where
        // the allocation fails and the load is refused.
        const std::string& child = result.childMessages;
        const bool budget = child.find("allocator is out of memory") != std::string::npos ||
                            child.find("exceeds maximum supported size") != std::string::npos;
        if (!budget && (child.find("Sanitizer") != std::string::npos ||
                        child.find("runtime error") != std::string::npos))
            broken("a sanitizer report in the import child:", result.error);
        return 0;
    }
    // What loadMesh promises (mesh_io.h): triangles over existing, finite vertices.
    const rs::MeshData& mesh = *result.mesh;
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) broken("not a triangle list");
    for (uint32_t i : mesh.indices)
        if (i >= mesh.positions.size()) broken("an index past the vertices");
    for (const rs::Vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            broken("a vertex that is not finite");
    if (smooth && mesh.normals.size() != mesh.positions.size()) broken("normals missing");
    // Parts cover the triangles in order; each look belongs to a part.
    std::size_t covered = 0;
    for (const rs::MeshPart& part : mesh.parts) {
        if (part.firstTriangle != covered) broken("parts that leave a gap");
        covered += part.triangleCount;
    }
    if (!mesh.parts.empty() && covered != mesh.triangleCount()) broken("parts that miss triangles");
    if (!result.asset) broken("a mesh without its looks");
    for (const rs::AssetLook& look : result.asset->looks)
        if (std::none_of(mesh.parts.begin(), mesh.parts.end(),
                         [&](const rs::MeshPart& p) { return p.material == look.index; }))
            broken("a look no part uses");
    return 0;
}
