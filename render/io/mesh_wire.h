// The checked byte format a mesh import child sends its result back to the parent in.
#pragma once

#include <string>

#include "io/mesh_io.h"

namespace rs {

/// Writes a loaded mesh to `fd`: a magic line, a marker, five 64-bit counts (positions,
/// normals, indices, dropped triangles, texture coordinates) and the four arrays straight from the
/// mesh (no copy of it is made), in this machine's byte order (both ends are one program on one
/// machine). False when a write fails.
bool writeMeshWire(int fd, const MeshData& mesh);

/// Writes a failed load to `fd`: the magic line, a marker, a length and the message.
bool writeMeshWireError(int fd, const std::string& error);

/// Reads what encodeMeshWire or encodeMeshWireError wrote, checking every count against the
/// bytes there are, that normals and texture coordinates are absent or one per vertex and that
/// every index names a vertex. The result holds the mesh (its sourcePath set to `sourcePath`) or
/// the child's message; bytes that are none of these give an error starting with "malformed".
MeshLoadResult decodeMeshWire(const std::string& bytes, const std::string& sourcePath);

}  // namespace rs
