// Loading triangle meshes through assimp (OBJ, PLY, STL, glTF/GLB, FBX, ...).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "scene/mesh_data.h"

namespace rs {

struct AssetContent;

/// Outcome of a mesh load: data, or an error naming the path and the problem.
struct MeshLoadResult {
    std::shared_ptr<const MeshData> mesh;
    /// The materials and embedded images of the file's parts (io/asset_content.h), with the
    /// mesh; null for a mesh decoded without them.
    std::shared_ptr<const AssetContent> asset;
    std::string error;
    /// What the import's child process wrote on stderr when it crashed or exited with an
    /// error (a sanitizer's report, assimp's assertion), else "": `error` quotes only its
    /// first line, and a refusal's `error` may quote the file's own bytes.
    std::string childMessages;
    bool ok() const { return mesh != nullptr; }
};

/// The budget of one import's child process; what is not set comes from the file's size
/// (defaultMeshImportMemory, defaultMeshImportTime).
struct MeshImportOptions {
    std::optional<std::uintmax_t> memoryBytes;  ///< Address space on top of the parent's.
    /// Its CPU time, rounded up, and its wall-clock time too when set; unset, the CPU time is
    /// defaultMeshImportTime and the wall clock kMeshImportWallFactor times that.
    std::optional<std::chrono::milliseconds> wallTime;
    const std::atomic<bool>* cancel = nullptr;  ///< True stops the import.
};

/// 512 MiB + 64 bytes per byte of the file, at most the machine's physical memory.
std::uintmax_t defaultMeshImportMemory(std::uintmax_t fileBytes);
/// Processor time: 10 s + 1 s per 10 MiB of the file (assimp reads a 37.6 MB, 1M-triangle
/// OBJ in about 2.5 s of it on this project's machine).
std::chrono::milliseconds defaultMeshImportTime(std::uintmax_t fileBytes);
/// The default wall-clock limit is this many times the processor-time one.
constexpr int kMeshImportWallFactor = 4;

/// Loads every mesh of a file into one triangle list in object space (node transforms applied).
/// Degenerate triangles are dropped and counted; NaN/Inf vertices or no triangles are errors.
/// `smoothNormals` keeps or generates per-vertex normals; otherwise normals stay empty (flat).
/// The file is checked here (a regular file within kMaxMeshFileBytes whose header counts fit
/// its size); assimp then reads it in a child process under `options`' budget, so an importer
/// that crashes, aborts, runs too long or allocates too much is an error naming the file, and
/// this process goes on.
MeshLoadResult loadMesh(const std::string& path, bool smoothNormals,
                        const MeshImportOptions& options = {});

}  // namespace rs
