// An imported asset's materials and embedded images into a document.
#include "io/asset_looks.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace rs {

namespace {
namespace fs = std::filesystem;

/// The file an embedded image goes to: "<asset>-<n>.<format>" in `dir`, or the first
/// "<asset>-<n>-<k>.<format>" that is free or already holds these bytes.
fs::path imagePath(const fs::path& dir, const std::string& assetName, std::size_t n,
                   const AssetImage& image) {
    // Appended piecewise: "literal" + std::string trips GCC 12's -Wrestrict false positive.
    std::string stem = fs::path(assetName).stem().string();
    stem += '-';
    stem += std::to_string(n);
    std::string extension = ".";
    extension += image.formatHint.empty() ? std::string("img") : image.formatHint;
    for (int k = 0;; ++k) {
        std::string name = stem;
        if (k) name.append("-").append(std::to_string(k));
        name += extension;
        const fs::path path = dir / name;
        std::error_code ec;
        if (!fs::exists(path, ec)) return path;
        std::ifstream in(path, std::ios::binary);
        const std::string held{std::istreambuf_iterator<char>(in), {}};
        if (held == image.bytes) return path;
    }
}

/// Writes `image` under `dir`; the path, or "" with `why` set.
std::string writeImage(const fs::path& dir, const std::string& assetName, std::size_t n,
                       const AssetImage& image, std::string& why) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        why = "cannot create folder \"" + dir.string() + "\": " + ec.message();
        return {};
    }
    const fs::path path = imagePath(dir, assetName, n, image);
    if (fs::exists(path, ec)) return path.string();  // The same bytes, written before.
    std::ofstream out(path, std::ios::binary);
    out.write(image.bytes.data(), std::streamsize(image.bytes.size()));
    out.close();
    if (!out) {
        why = "cannot write \"" + path.string() + "\": " + std::strerror(errno);
        fs::remove(path, ec);
        return {};
    }
    return path.string();
}
}  // namespace

AdoptedLooks adoptAssetLooks(SceneDocument& doc, ObjectId id, const AssetContent& asset,
                             const std::string& assetName, const std::string& imageDir) {
    AdoptedLooks adopted;
    Object* o = doc.findObject(id);
    auto* mesh = o ? std::get_if<MeshGeometry>(&o->geometry) : nullptr;
    if (!mesh || asset.looks.empty()) return adopted;
    std::vector<std::string> written(asset.images.size());
    std::vector<std::string> parts;
    for (const AssetLook& look : asset.looks) {
        Material m = look.material;
        m.name = numberedName(
            m.name, [&](const std::string& name) { return doc.findMaterial(name) != nullptr; });
        const std::string where =
            "asset \"" + assetName + "\", part \"" + look.material.name + "\": ";
        for (const std::string& note : look.notes) adopted.notes.push_back(where + note);
        if (look.embeddedImage >= 0) {
            const auto n = std::size_t(look.embeddedImage);
            std::string why;
            if (written[n].empty())
                written[n] = writeImage(imageDir, assetName, n, asset.images[n], why);
            if (auto* t = std::get_if<ImageTexture>(&m.pattern); t && !written[n].empty()) {
                t->image.file = written[n];
                t->image.resolvedPath = written[n];
                if (adopted.images.empty() || adopted.images.back() != written[n])
                    adopted.images.push_back(written[n]);
            } else {
                m.pattern = std::monostate{};
                adopted.notes.push_back(where + "its embedded image " + std::to_string(n) + ": " +
                                        why + "; left untextured");
            }
        }
        if (parts.size() <= look.index) parts.resize(std::size_t(look.index) + 1);
        parts[look.index] = m.name;
        adopted.materials.push_back(m.name);
        doc.materials.push_back(std::move(m));
    }
    mesh->partMaterials = std::move(parts);
    return adopted;
}

std::vector<ObjectId> adoptAssetLights(SceneDocument& doc, ObjectId id, const AssetContent& asset) {
    std::vector<ObjectId> ids;
    const Object* o = doc.findObject(id);
    if (!o) return ids;
    const Mat4 m = o->transform.matrix();
    const Mat3 m3(m);
    const float scale = std::abs(o->transform.scale.x);
    auto taken = [&](const std::string& name) {
        return std::any_of(doc.objects.begin(), doc.objects.end(),
                           [&](const Object& x) { return x.name == name; }) ||
               std::any_of(doc.lights.begin(), doc.lights.end(),
                           [&](const Light& x) { return x.name == name; });
    };
    for (Light light : asset.lights) {
        light.name = numberedName(light.name, taken);
        light.position = Vec3(m * glm::vec4(light.position, 1.0f));
        light.target = Vec3(m * glm::vec4(light.target, 1.0f));
        if (const Vec3 d = m3 * light.direction; glm::length(d) > 0.0f)
            light.direction = glm::normalize(d);
        light.radius *= scale;
        ids.push_back(doc.addLight(std::move(light)));
    }
    return ids;
}

Camera placedAssetCamera(const AssetView& view, const Object& placed) {
    const Mat4 m = placed.transform.matrix();
    Camera c = view.camera;
    c.position = Vec3(m * glm::vec4(c.position, 1.0f));
    c.target = Vec3(m * glm::vec4(c.target, 1.0f));
    if (const Vec3 up = Mat3(m) * c.up; glm::length(up) > 0.0f) c.up = glm::normalize(up);
    c.orthoHeight *= std::abs(placed.transform.scale.y);
    return c;
}

std::vector<std::string> adoptAssetViews(SceneDocument& doc, ObjectId id,
                                         const AssetContent& asset) {
    std::vector<std::string> names;
    const Object* o = doc.findObject(id);
    if (!o) return names;
    auto taken = [&](const std::string& name) { return doc.findView(name) != nullptr; };
    for (const AssetView& view : asset.views) {
        ViewBookmark bookmark;
        bookmark.name = numberedName(view.name.empty() ? "Camera" : view.name, taken);
        bookmark.camera = placedAssetCamera(view, *o);
        names.push_back(bookmark.name);
        doc.views.push_back(std::move(bookmark));
    }
    return names;
}

}  // namespace rs
