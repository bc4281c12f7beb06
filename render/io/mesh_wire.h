// The checked byte format a mesh import child sends its result back to the parent in.
#pragma once

#include <string>

#include "io/asset_content.h"
#include "io/mesh_io.h"

namespace rs {

/// Writes a loaded mesh to `fd`: a magic line, a marker, six 64-bit counts (positions,
/// normals, indices, dropped triangles, texture coordinates, parts) and the five arrays straight
/// from the mesh (no copy of it is made), in this machine's byte order (both ends are one
/// program on one machine); then the asset's looks as text (encodeAssetLooks against
/// `assetDir`) after its length, the number of embedded images and each image's length and
/// bytes. False when a write fails.
bool writeMeshWire(int fd, const MeshData& mesh, const AssetContent& asset = {},
                   const std::string& assetDir = "");

/// Writes a failed load to `fd`: the magic line, a marker, a length and the message.
bool writeMeshWireError(int fd, const std::string& error);

/// Reads what writeMeshWire or writeMeshWireError wrote, checking every count against the
/// bytes there are, that normals and texture coordinates are absent or one per vertex, that
/// every index names a vertex, that the parts cover the triangles in order and that the looks
/// read back as a scene's materials (relative texture paths against `sourcePath`'s folder). The
/// result holds the mesh (its sourcePath set to `sourcePath`) or the child's message; bytes that
/// are none of these give an error starting with "malformed".
MeshLoadResult decodeMeshWire(const std::string& bytes, const std::string& sourcePath);

}  // namespace rs
