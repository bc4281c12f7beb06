// Triangle mesh data as loaded from a file: object-space positions, optional normals, indices.
#pragma once

#include "core/math.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rs {

/// An indexed triangle mesh in object space. Immutable once loaded; shared between snapshots.
struct MeshData {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;       ///< Per-vertex normals, same size as positions, or empty.
    std::vector<uint32_t> indices;   ///< Three per triangle.
    std::size_t droppedDegenerate = 0;  ///< Zero-area triangles removed while loading.
    std::string sourcePath;          ///< The file it came from (absolute), for messages.

    std::size_t triangleCount() const { return indices.size() / 3; }
    /// Object-space bounds of all vertices.
    Aabb bounds() const {
        Aabb b;
        for (const Vec3& p : positions) b.expand(p);
        return b;
    }
};

}  // namespace rs
