// MeshFileAccess: assimp's file access behind checkInputFile.
#include "io/mesh_file_access.h"

#include "core/input_file.h"

namespace rs {

namespace {
bool allowed(const char* path) {
    return path && checkInputFile(path, kMaxMeshFileBytes).empty();
}
}  // namespace

// The default Exists() opens the file to see, which blocks on a FIFO.
bool MeshFileAccess::Exists(const char* path) const {
    return allowed(path);
}

Assimp::IOStream* MeshFileAccess::Open(const char* path, const char* mode) {
    return allowed(path) ? Assimp::DefaultIOSystem::Open(path, mode) : nullptr;
}

}  // namespace rs
