// The parts of a mesh (MeshData::parts) as meshes of their own, so each part can be traced
// with its own material while the engine sees only shapes.
#pragma once

#include <memory>
#include <vector>

#include "scene/mesh_data.h"

namespace rs {

/// The triangles of each part of `mesh`, in the order of mesh->parts, each a mesh with only
/// the vertices it uses. The same pointers come back while any of them is still held, so
/// snapshots rebuilt on every edit share the parts and their triangle BVHs.
std::vector<std::shared_ptr<const MeshData>> meshPartsOf(
    const std::shared_ptr<const MeshData>& mesh);

}  // namespace rs
