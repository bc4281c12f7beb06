// What the mesh importer may open: the same guards as the mesh file itself, for every file a
// mesh names (an OBJ's mtllib, a glTF's buffers, ...).
#pragma once

#include <assimp/DefaultIOSystem.h>

namespace rs {

/// assimp's default file access, limited to regular files within the mesh size limit: a side
/// file that is a FIFO, a device or a directory is reported missing instead of being opened
/// (a FIFO would block the import forever, a device would be read without end).
class MeshFileAccess : public Assimp::DefaultIOSystem {
public:
    bool Exists(const char* path) const override;
    Assimp::IOStream* Open(const char* path, const char* mode = "rb") override;
};

}  // namespace rs
