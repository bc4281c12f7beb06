// The assimp import of one mesh file, in this process: what the import child runs.
#pragma once

#include <string>

#include "io/mesh_io.h"

namespace rs {

/// Reads `file` (an absolute path that passed loadMesh's guards) with assimp into one
/// triangle list (see loadMesh). The error, if any, is the reason alone, without the path.
/// Call it through loadMesh: assimp can abort the process or allocate without bound here.
MeshLoadResult importMeshWithAssimp(const std::string& file, bool smoothNormals);

}  // namespace rs
