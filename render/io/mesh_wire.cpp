// Mesh wire format: fixed header, then raw arrays; every count checked before it is used.
#include "io/mesh_wire.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <type_traits>

#include "io/asset_content.h"
#include "io/child_process.h"

namespace rs {

namespace {
constexpr char kMagic[8] = {'R', 'S', 'M', 'E', 'S', 'H', '3', '\n'};
constexpr std::uint64_t kMeshMarker = 0;
constexpr std::uint64_t kErrorMarker = 1;
/// Longest error message accepted back: far more than any message, far less than memory.
constexpr std::uint64_t kMaxErrorBytes = 1 << 16;

static_assert(sizeof(Vec3) == 3 * sizeof(float) && std::is_trivially_copyable_v<Vec3>);
static_assert(sizeof(MeshPart) == 3 * sizeof(std::uint32_t) &&
              std::is_trivially_copyable_v<MeshPart>);
static_assert(sizeof(glm::vec2) == 2 * sizeof(float) && std::is_trivially_copyable_v<glm::vec2>);

void putCount(std::string& out, std::uint64_t value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <typename T>
bool writeArray(int fd, const std::vector<T>& values) {
    return writeAllTo(fd, values.data(), values.size() * sizeof(T));
}

/// Reads the bytes in order; every read first checks that they are there.
class WireReader {
public:
    explicit WireReader(const std::string& bytes) : bytes_(bytes) {}
    std::size_t left() const { return bytes_.size() - at_; }
    bool count(std::uint64_t& value) {
        if (left() < sizeof value) return false;
        std::memcpy(&value, bytes_.data() + at_, sizeof value);
        at_ += sizeof value;
        return true;
    }
    template <typename T>
    bool array(std::uint64_t n, std::vector<T>& values) {
        if (n > left() / sizeof(T)) return false;
        values.resize(std::size_t(n));
        if (n == 0) return true;  // An empty vector's data() may be null, even for memcpy.
        std::memcpy(values.data(), bytes_.data() + at_, std::size_t(n) * sizeof(T));
        at_ += std::size_t(n) * sizeof(T);
        return true;
    }
    bool text(std::uint64_t n, std::string& value) {
        if (n > left()) return false;
        value.assign(bytes_, at_, std::size_t(n));
        at_ += std::size_t(n);
        return true;
    }
    bool magic() {
        if (left() < sizeof kMagic || std::memcmp(bytes_.data(), kMagic, sizeof kMagic) != 0)
            return false;
        at_ += sizeof kMagic;
        return true;
    }

private:
    const std::string& bytes_;
    std::size_t at_ = 0;
};

MeshLoadResult malformed(const std::string& why) {
    MeshLoadResult result;
    result.error = "malformed result from the import process: " + why;
    return result;
}

/// True when the parts cover the triangles in order, once each, in increasing material order.
bool partsCover(const std::vector<MeshPart>& parts, std::uint64_t triangles) {
    std::uint64_t next = 0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (parts[i].firstTriangle != next || parts[i].triangleCount == 0) return false;
        if (i > 0 && parts[i].material <= parts[i - 1].material) return false;
        next += parts[i].triangleCount;
    }
    return parts.empty() || next == triangles;
}
}  // namespace

bool writeMeshWire(int fd, const MeshData& mesh, const AssetContent& asset,
                   const std::string& assetDir) {
    std::string header(kMagic, sizeof kMagic);
    putCount(header, kMeshMarker);
    putCount(header, mesh.positions.size());
    putCount(header, mesh.normals.size());
    putCount(header, mesh.indices.size());
    putCount(header, mesh.droppedDegenerate);
    putCount(header, mesh.uvs.size());
    putCount(header, mesh.parts.size());
    if (!writeAllTo(fd, header.data(), header.size()) || !writeArray(fd, mesh.positions) ||
        !writeArray(fd, mesh.normals) || !writeArray(fd, mesh.indices) ||
        !writeArray(fd, mesh.uvs) || !writeArray(fd, mesh.parts))
        return false;
    // The looks, then each embedded image's bytes.
    std::string looks;
    const std::string text = encodeAssetLooks(asset, assetDir);
    putCount(looks, text.size());
    looks += text;
    putCount(looks, asset.images.size());
    if (!writeAllTo(fd, looks.data(), looks.size())) return false;
    for (const AssetImage& image : asset.images) {
        std::string size;
        putCount(size, image.bytes.size());
        if (!writeAllTo(fd, size.data(), size.size()) ||
            !writeAllTo(fd, image.bytes.data(), image.bytes.size()))
            return false;
    }
    return true;
}

bool writeMeshWireError(int fd, const std::string& error) {
    std::string out(kMagic, sizeof kMagic);
    putCount(out, kErrorMarker);
    const std::string text = error.substr(0, kMaxErrorBytes);
    putCount(out, text.size());
    out += text;
    return writeAllTo(fd, out.data(), out.size());
}

MeshLoadResult decodeMeshWire(const std::string& bytes, const std::string& sourcePath) {
    WireReader in(bytes);
    std::uint64_t marker = 0;
    if (!in.magic() || !in.count(marker)) return malformed("no header");
    MeshLoadResult result;
    if (marker == kErrorMarker) {
        std::uint64_t length = 0;
        if (!in.count(length) || length > kMaxErrorBytes || !in.text(length, result.error) ||
            in.left() != 0)
            return malformed("a cut or oversized message");
        if (result.error.empty()) return malformed("an empty message");
        return result;
    }
    if (marker != kMeshMarker) return malformed("an unknown kind of result");
    std::uint64_t positions = 0, normals = 0, indices = 0, dropped = 0, uvs = 0, parts = 0;
    if (!in.count(positions) || !in.count(normals) || !in.count(indices) || !in.count(dropped) ||
        !in.count(uvs) || !in.count(parts))
        return malformed("a cut header");
    if (normals != 0 && normals != positions) return malformed("normals that are not per vertex");
    if (uvs != 0 && uvs != positions)
        return malformed("texture coordinates that are not per vertex");
    if (indices == 0 || indices % 3 != 0) return malformed("no whole triangles");
    auto mesh = std::make_shared<MeshData>();
    if (!in.array(positions, mesh->positions) || !in.array(normals, mesh->normals) ||
        !in.array(indices, mesh->indices) || !in.array(uvs, mesh->uvs) ||
        !in.array(parts, mesh->parts))
        return malformed("counts that the bytes do not hold");
    for (std::uint32_t index : mesh->indices)
        if (index >= positions) return malformed("an index past the vertices");
    if (!partsCover(mesh->parts, indices / 3))
        return malformed("parts that do not cover the triangles in order");
    auto asset = std::make_shared<AssetContent>();
    std::uint64_t looksLength = 0, images = 0;
    std::string looks;
    if (!in.count(looksLength) || !in.text(looksLength, looks) || !in.count(images) ||
        images > in.left() / sizeof(std::uint64_t))
        return malformed("cut asset looks");
    asset->images.resize(std::size_t(images));
    for (AssetImage& image : asset->images) {
        std::uint64_t length = 0;
        if (!in.count(length) || length > kMaxAssetImageBytes || !in.text(length, image.bytes))
            return malformed("a cut embedded image");
    }
    if (in.left() != 0) return malformed("bytes after the mesh");
    const std::string assetDir = std::filesystem::path(sourcePath).parent_path().string();
    if (std::string why; !decodeAssetLooks(looks, assetDir, *asset, why)) return malformed(why);
    for (const AssetLook& look : asset->looks)
        if (std::none_of(mesh->parts.begin(), mesh->parts.end(),
                         [&](const MeshPart& p) { return p.material == look.index; }))
            return malformed("a look for a material no part uses");
    result.asset = std::move(asset);
    mesh->droppedDegenerate = std::size_t(dropped);
    mesh->sourcePath = sourcePath;
    result.mesh = std::move(mesh);
    return result;
}

}  // namespace rs
