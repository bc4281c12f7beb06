// Document bookkeeping: id assignment, look-ups, content comparison and the image size limits.
#include "scene/document.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <utility>

#include "core/id_search.h"

namespace rs {

Mat4 Transform::matrix() const {
    Mat4 m = glm::translate(Mat4(1.0f), translate);
    m = glm::rotate(m, glm::radians(rotate.z), Vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(rotate.y), Vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotate.x), Vec3(1, 0, 0));
    return glm::scale(m, scale);
}

ObjectId SceneDocument::addObject(Object o) {
    o.id = nextId++;
    objects.push_back(std::move(o));
    return objects.back().id;
}

ObjectId SceneDocument::addLight(Light l) {
    l.id = nextId++;
    lights.push_back(std::move(l));
    return lights.back().id;
}

namespace {
template <class List>
auto* findById(List& list, ObjectId id) {
    const std::ptrdiff_t i = indexById(std::as_const(list), id, [](const auto& e) { return e.id; });
    return i < 0 ? nullptr : &list[std::size_t(i)];
}
}  // namespace

Object* SceneDocument::findObject(ObjectId id) {
    return findById(objects, id);
}

const Object* SceneDocument::findObject(ObjectId id) const {
    return const_cast<SceneDocument*>(this)->findObject(id);
}

Light* SceneDocument::findLight(ObjectId id) {
    return findById(lights, id);
}

const Light* SceneDocument::findLight(ObjectId id) const {
    return const_cast<SceneDocument*>(this)->findLight(id);
}

const Material* SceneDocument::findMaterial(const std::string& name) const {
    for (const Material& m : materials)
        if (m.name == name) return &m;
    return nullptr;
}

const ViewBookmark* SceneDocument::findView(const std::string& name) const {
    for (const ViewBookmark& v : views)
        if (v.name == name) return &v;
    return nullptr;
}

namespace {
template <class T>
bool sameIgnoringId(const T& a, const T& b) {
    if (a.id == b.id) return a == b;
    T x = a;
    x.id = b.id;
    return x == b;
}
bool sameIgnoringIds(const std::vector<Light>& a, const std::vector<Light>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), sameIgnoringId<Light>);
}
bool sameIgnoringIds(const SharedList<Object>& a, const SharedList<Object>& b) {
    if (a.size() != b.size()) return false;
    // Shared chunks hold the same objects: only the chunks an edit wrote are compared.
    for (std::size_t c = 0; c < a.chunkCount(); ++c) {
        if (a.sharesChunk(b, c)) continue;
        const std::size_t first = c * SharedList<Object>::kChunk;
        const std::size_t last = std::min(a.size(), first + SharedList<Object>::kChunk);
        for (std::size_t i = first; i < last; ++i)
            if (!sameIgnoringId(a[i], b[i])) return false;
    }
    return true;
}
}  // namespace

bool SceneDocument::sameContent(const SceneDocument& o) const {
    return camera == o.camera && render == o.render && materials == o.materials &&
           environment == o.environment && views == o.views && extras == o.extras &&
           sameIgnoringIds(lights, o.lights) && sameIgnoringIds(objects, o.objects);
}

const char* geometryTypeName(const Geometry& g) {
    static const char* const names[] = {"sphere", "plane", "rectangle", "box", "mesh"};
    return names[g.index()];
}

std::string imageSizeError(int width, int height) {
    if (width < 1 || height < 1)
        return "image size " + std::to_string(width) + " x " + std::to_string(height) +
               " must be at least 1 x 1";
    if (width > kMaxImageSide || height > kMaxImageSide)
        return "image size " + std::to_string(width) + " x " + std::to_string(height) +
               " is too large (each side at most " + std::to_string(kMaxImageSide) + " pixels)";
    const long long area = (long long)width * height;
    if (area > kMaxImagePixels)
        return "image size " + std::to_string(width) + " x " + std::to_string(height) + " (" +
               std::to_string(area / (1024 * 1024)) + " Mpixels) is too large (at most " +
               std::to_string(kMaxImagePixels / (1024 * 1024)) + " Mpixels)";
    return {};
}

bool everyPartHasItsOwn(const Object& o) {
    const auto* mesh = std::get_if<MeshGeometry>(&o.geometry);
    if (!mesh || !mesh->data || mesh->data->parts.empty()) return false;
    return std::all_of(mesh->data->parts.begin(), mesh->data->parts.end(), [&](const MeshPart& p) {
        return &partMaterial(o, p.material) != &o.material;
    });
}

const std::string& shownMaterial(const Object& o) {
    const auto* mesh = std::get_if<MeshGeometry>(&o.geometry);
    return mesh && mesh->data && mesh->data->parts.size() == 1 && everyPartHasItsOwn(o)
               ? partMaterial(o, mesh->data->parts.front().material)
               : o.material;
}

}  // namespace rs
