// describeChange: the parts of two documents that differ, skipping the objects they share.
#include "scene/document_change.h"

#include <algorithm>

namespace rs {

DocumentChange DocumentChange::everything() {
    DocumentChange c;
    c.camera = c.render = c.materials = c.lights = c.environment = c.views = c.extras = true;
    c.objectsRestructured = true;
    return c;
}

uint8_t DocumentChange::objectFields() const {
    uint8_t f = 0;
    for (const ObjectEdit& e : objects) f |= e.fields;
    return f;
}

namespace {

uint8_t changedFields(const Object& a, const Object& b) {
    uint8_t f = 0;
    if (!(a.geometry == b.geometry) || !(a.transform == b.transform)) f |= DocumentChange::kShape;
    // A mesh reloaded from its file is the same path with other triangles.
    const auto* ma = std::get_if<MeshGeometry>(&a.geometry);
    const auto* mb = std::get_if<MeshGeometry>(&b.geometry);
    if (ma && mb && ma->data != mb->data) f |= DocumentChange::kShape;
    if (a.material != b.material) f |= DocumentChange::kMaterial;
    if (a.name != b.name) f |= DocumentChange::kName;
    if (a.visible != b.visible) f |= DocumentChange::kVisible;
    if (a.extras != b.extras) f |= DocumentChange::kExtras;
    return f;
}

}  // namespace

DocumentChange describeChange(const SceneDocument& before, const SceneDocument& after) {
    DocumentChange c;
    c.camera = !(before.camera == after.camera);
    c.render = !(before.render == after.render);
    c.materials = !(before.materials == after.materials);
    c.lights = !(before.lights == after.lights);
    c.environment = !(before.environment == after.environment);
    c.views = before.views != after.views;
    c.extras = before.extras != after.extras;

    const SharedList<Object>& a = before.objects;
    const SharedList<Object>& b = after.objects;
    if (a.size() != b.size()) {
        c.objectsRestructured = true;
        return c;
    }
    constexpr std::size_t kChunk = SharedList<Object>::kChunk;
    for (std::size_t chunk = 0; chunk < a.chunkCount(); ++chunk) {
        if (a.sharesChunk(b, chunk)) continue;
        const std::size_t last = std::min(a.size(), (chunk + 1) * kChunk);
        for (std::size_t i = chunk * kChunk; i < last; ++i) {
            if (a[i].id != b[i].id) {
                c.objectsRestructured = true;
                c.objects.clear();
                return c;
            }
            if (const uint8_t f = changedFields(a[i], b[i])) c.objects.push_back({b[i].id, i, f});
        }
    }
    return c;
}

}  // namespace rs
