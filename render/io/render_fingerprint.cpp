// FNV-1a over the canonical scene text and the mesh data it refers to.
#include "io/render_fingerprint.h"

#include <cstdint>
#include <cstdio>
#include <variant>

#include "io/scene_io.h"

namespace rs {

namespace {

/// 64-bit FNV-1a, fed in pieces.
struct Fnv1a {
    uint64_t state = 0xcbf29ce484222325ull;
    void add(const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) state = (state ^ bytes[i]) * 0x100000001b3ull;
    }
    template <class T>
    void addVector(const std::vector<T>& v) {
        const uint64_t n = v.size();
        add(&n, sizeof n);
        add(v.data(), v.size() * sizeof(T));
    }
};

}  // namespace

std::string renderFingerprint(const SceneDocument& doc, EngineKind engine) {
    Fnv1a hash;
    // "/" as the base folder writes every mesh path the same way wherever the scene lies;
    // the triangles themselves are hashed below, so a changed mesh file changes the result.
    const std::string text = serializeScene(doc, "/");
    hash.add(text.data(), text.size());
    for (const Object& object : doc.objects) {
        const auto* mesh = std::get_if<MeshGeometry>(&object.geometry);
        if (!mesh || !mesh->data) continue;
        hash.addVector(mesh->data->positions);
        hash.addVector(mesh->data->normals);
        hash.addVector(mesh->data->indices);
    }
    const std::string name = engineName(engine);
    hash.add(name.data(), name.size());
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash.state));
    return hex;
}

}  // namespace rs
