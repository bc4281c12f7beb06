// Splitting a mesh by part, once per mesh while its parts are in use.
#include "scene/mesh_parts.h"

#include <limits>
#include <map>
#include <mutex>

namespace rs {

namespace {
std::shared_ptr<const MeshData> partMesh(const MeshData& mesh, const MeshPart& part) {
    constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
    auto out = std::make_shared<MeshData>();
    out->sourcePath = mesh.sourcePath;
    std::vector<uint32_t> remap(mesh.positions.size(), kUnused);
    const std::size_t first = 3 * std::size_t(part.firstTriangle);
    const std::size_t end = first + 3 * std::size_t(part.triangleCount);
    out->indices.reserve(end - first);
    for (std::size_t k = first; k < end && k < mesh.indices.size(); ++k) {
        const uint32_t index = mesh.indices[k];
        if (remap[index] == kUnused) {
            remap[index] = static_cast<uint32_t>(out->positions.size());
            out->positions.push_back(mesh.positions[index]);
            if (!mesh.normals.empty()) out->normals.push_back(mesh.normals[index]);
            if (!mesh.uvs.empty()) out->uvs.push_back(mesh.uvs[index]);
        }
        out->indices.push_back(remap[index]);
    }
    out->parts.push_back({0, uint32_t(out->indices.size() / 3), part.material});
    return out;
}
}  // namespace

std::vector<std::shared_ptr<const MeshData>> meshPartsOf(
    const std::shared_ptr<const MeshData>& mesh) {
    struct Known {
        std::weak_ptr<const MeshData> whole;
        std::vector<std::weak_ptr<const MeshData>> parts;
    };
    static std::mutex mutex;
    static std::map<const MeshData*, Known> known;
    if (!mesh) return {};
    std::lock_guard lock(mutex);
    std::erase_if(known, [](const auto& entry) { return entry.second.whole.expired(); });
    Known& k = known[mesh.get()];
    std::vector<std::shared_ptr<const MeshData>> parts;
    if (k.whole.lock() == mesh && k.parts.size() == mesh->parts.size()) {
        for (const auto& weak : k.parts)
            if (auto part = weak.lock()) parts.push_back(std::move(part));
        if (parts.size() == mesh->parts.size()) return parts;
    }
    parts.clear();
    k.whole = mesh;
    k.parts.clear();
    for (const MeshPart& part : mesh->parts) {
        parts.push_back(partMesh(*mesh, part));
        k.parts.push_back(parts.back());
    }
    return parts;
}

}  // namespace rs
