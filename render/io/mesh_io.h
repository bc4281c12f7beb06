// Loading triangle meshes through assimp (OBJ, PLY, STL, glTF/GLB, FBX, ...).
#pragma once

#include "scene/mesh_data.h"

#include <memory>
#include <string>

namespace rs {

/// Outcome of a mesh load: data, or an error naming the path and the problem.
struct MeshLoadResult {
    std::shared_ptr<const MeshData> mesh;
    std::string error;
    bool ok() const { return mesh != nullptr; }
};

/// Loads every mesh of a file into one triangle list in object space (node transforms applied).
/// Degenerate triangles are dropped and counted; NaN/Inf vertices or no triangles are errors.
/// `smoothNormals` keeps or generates per-vertex normals; otherwise normals stay empty (flat).
MeshLoadResult loadMesh(const std::string& path, bool smoothNormals);

}  // namespace rs
