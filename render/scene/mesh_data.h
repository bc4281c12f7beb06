// Triangle mesh data as loaded from a file: object-space positions, optional normals and
// texture coordinates, indices.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "core/math.h"

namespace rs {

/// A run of a mesh's triangles that share one material of the file they came from.
struct MeshPart {
    uint32_t firstTriangle = 0;
    uint32_t triangleCount = 0;
    uint32_t material = 0;  ///< The file's material index (assimp's, in the file's order).
    bool operator==(const MeshPart&) const = default;
};

/// An indexed triangle mesh in object space. Immutable once loaded; shared between snapshots.
struct MeshData {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  ///< Per-vertex normals, same size as positions, or empty.
    /// The file's first texture-coordinate channel (u, v), one per vertex, or empty when the
    /// file has none (textures then see (0, 0) everywhere).
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;  ///< Three per triangle.
    /// The triangles grouped by the file's material, in increasing material order, covering
    /// every triangle once; empty when the file says nothing about materials.
    std::vector<MeshPart> parts;
    std::size_t droppedDegenerate = 0;  ///< Zero-area triangles removed while loading.
    std::string sourcePath;             ///< The file it came from (absolute), for messages.

    std::size_t triangleCount() const { return indices.size() / 3; }
    /// Object-space bounds of all vertices: worked out on the first call, then kept (the
    /// designer asks on every mouse move, and a 1M-triangle mesh took milliseconds a time).
    /// Fill the positions before the first call; a copy works its bounds out again.
    Aabb bounds() const {
        return boundsCache_.get([this] {
            Aabb b;
            for (const Vec3& p : positions) b.expand(p);
            return b;
        });
    }

private:
    /// A box computed once by whichever thread asks first; copies start without it.
    class BoundsCache {
    public:
        BoundsCache() = default;
        BoundsCache(const BoundsCache&) {}
        BoundsCache& operator=(const BoundsCache&) {
            known_.store(false, std::memory_order_release);
            return *this;
        }
        template <class Compute>
        Aabb get(Compute compute) const {
            if (known_.load(std::memory_order_acquire)) return box_;
            std::lock_guard lock(mutex_);
            if (!known_.load(std::memory_order_relaxed)) {
                box_ = compute();
                known_.store(true, std::memory_order_release);
            }
            return box_;
        }

    private:
        mutable std::mutex mutex_;
        mutable std::atomic<bool> known_{false};
        mutable Aabb box_;
    };
    BoundsCache boundsCache_;
};

}  // namespace rs
