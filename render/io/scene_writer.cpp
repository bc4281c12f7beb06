// Writing scene files: key order, omitted defaults, extras, mesh paths and atomic saving.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <random>
#include <string_view>
#include <system_error>

#include "io/scene_io.h"
#include "io/scene_json.h"
#include "scene/parameters.h"

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace rs {

namespace {
namespace fs = std::filesystem;

Json number(float f) {
    return Json(jsonNumberForFloat(f));
}
Json vector(const Vec3& v) {
    return Json::array({number(v.x), number(v.y), number(v.z)});
}

void putExtras(Json& j, const Extras& extras) {
    for (const auto& [key, text] : extras) {
        // Anything else would make the file unreadable (unknown or repeated key).
        if (key.rfind("x-", 0) != 0 || j.contains(key)) continue;
        Json value = Json::parse(text, nullptr, /*allow_exceptions=*/false);
        // Text that is not JSON came from code, not a file; keep it as a string, not lose it.
        j[key] = value.is_discarded() ? Json(text) : std::move(value);
    }
}

Json parameterJson(const ParamDescriptor& d, const ParamValue& v) {
    switch (d.type) {
        case ParamType::Float:
            return number(std::get<float>(v));
        case ParamType::Int:
            return Json(std::get<int>(v));
        case ParamType::Bool:
            return Json(std::get<bool>(v));
        case ParamType::Vec3:
        case ParamType::Color:
            return vector(std::get<Vec3>(v));
        case ParamType::Enum:
            return Json(d.enumNames.at(std::size_t(std::get<int>(v))));
        case ParamType::Text:
        case ParamType::File:
            return Json(std::get<std::string>(v));
    }
    return Json();
}

/// Writes every field the descriptors of `kind` name, except `skip`, in their order: a
/// required or always-written field always, any other only when it differs from its default.
template <class T>
void putFields(Json& j, ParamKind kind, const T& target,
               std::initializer_list<std::string_view> skip = {}) {
    for (const ParamDescriptor& d : parameters(kind)) {
        if (std::find(skip.begin(), skip.end(), d.key) != skip.end()) continue;
        const std::optional<ParamValue> v = getField(target, d.key);
        if (v && (d.required || d.alwaysWritten || *v != d.defaultValue))
            j[d.key] = parameterJson(d, *v);
    }
}

Json cameraJson(const Camera& c) {
    const Camera d;
    Json j = Json::object();
    putFields(j, ParamKind::Camera, c, {"fov_y", "ortho_height"});
    // The lens of the projection in use is always stated; the other one when it was changed.
    if (c.projection == Projection::Perspective || c.fovY != d.fovY) j["fov_y"] = number(c.fovY);
    if (c.projection == Projection::Orthographic || c.orthoHeight != d.orthoHeight)
        j["ortho_height"] = number(c.orthoHeight);
    putExtras(j, c.extras);
    return j;
}

Json viewJson(const ViewBookmark& v) {
    Json j = Json::object();
    j["name"] = v.name;
    j["camera"] = cameraJson(v.camera);
    putExtras(j, v.extras);
    return j;
}

Json renderJson(const RenderSettings& r) {
    Json j = Json::object();
    putFields(j, ParamKind::Render, r);
    putExtras(j, r.extras);
    return j;
}

// Relative when the file lies below `baseDir`, so a project folder can move as a whole.
std::string fileFor(const std::string& file, const std::string& resolvedPath,
                    const std::string& baseDir) {
    fs::path absolute;
    if (!resolvedPath.empty())
        absolute = resolvedPath;
    else if (fs::path(file).is_absolute())
        absolute = file;
    if (absolute.empty() || baseDir.empty()) return file;  // nothing to re-anchor against
    std::error_code ec;
    fs::path base = fs::absolute(fs::path(baseDir), ec).lexically_normal();
    if (ec) return file;
    if (base.filename().empty()) base = base.parent_path();  // "/a/b/" -> "/a/b"
    absolute = absolute.lexically_normal();
    fs::path relative = absolute.lexically_relative(base);
    if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
    return absolute.generic_string();
}

/// Two fields of `kind` written as one array `[a, b]` (a checker's colours, a texture's
/// scale or offset): written when either differs from its default.
template <class T>
void putPair(Json& j, ParamKind kind, const T& target, const char* key, const char* first,
             const char* second, bool always = false) {
    const ParamDescriptor &a = *findParameter(kind, first), &b = *findParameter(kind, second);
    const ParamValue va = *getField(target, first), vb = *getField(target, second);
    if (always || va != a.defaultValue || vb != b.defaultValue)
        j[key] = Json::array({parameterJson(a, va), parameterJson(b, vb)});
}

Json colorJson(const Material& m, const std::string& baseDir) {
    if (const auto* c = std::get_if<CheckerPattern>(&m.pattern)) {
        Json j = Json::object();
        putPair(j, ParamKind::Checker, *c, "checker", "even", "odd", true);
        putFields(j, ParamKind::Checker, *c, {"even", "odd"});
        return j;
    }
    if (const auto* t = std::get_if<ImageTexture>(&m.pattern)) {
        Json j = Json::object();
        j["texture"] = fileFor(t->image.file, t->image.resolvedPath, baseDir);
        putPair(j, ParamKind::ImageTexture, *t, "scale", "scale_u", "scale_v");
        putPair(j, ParamKind::ImageTexture, *t, "offset", "offset_u", "offset_v");
        return j;
    }
    return parameterJson(*findParameter(ParamKind::Material, "color"), m.color);
}

Json materialJson(const Material& m, const std::string& baseDir) {
    Json j = Json::object();
    j["name"] = m.name;
    putFields(j, ParamKind::Material, m);
    j["color"] = colorJson(m, baseDir);
    putExtras(j, m.extras);
    return j;
}

Json environmentJson(const Environment& e, const std::string& baseDir) {
    Json j = Json::object();
    putFields(j, ParamKind::Environment, e);
    j["file"] = fileFor(e.image.file, e.image.resolvedPath, baseDir);
    putExtras(j, e.extras);
    return j;
}

Json lightJson(const Light& l) {
    Json j = Json::object();
    j["name"] = l.name;
    // A point light's fields have no radius: the format forbids the key there.
    putFields(j, lightKind(l), l);
    putExtras(j, l.extras);
    return j;
}

void putGeometry(Json& j, const Geometry& geometry, const std::string& baseDir) {
    std::visit(
        [&](const auto& g) {
            using G = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<G, MeshGeometry>) {
                j["file"] = fileFor(g.file, g.resolvedPath, baseDir);
                putFields(j, ParamKind::Mesh, g, {"file"});
                if (!g.partMaterials.empty()) {
                    Json parts = Json::array();
                    for (const std::string& name : g.partMaterials)
                        parts.push_back(name.empty() ? Json() : Json(name));
                    j["part_materials"] = std::move(parts);
                }
            } else {
                putFields(j, geometryKind(geometry), g);
            }
        },
        geometry);
}

void putTransform(Json& j, const Transform& t) {
    putFields(j, ParamKind::Transform, t, {"scale"});
    if (t.scale == Vec3(1.0f)) return;
    bool uniform = t.scale.x == t.scale.y && t.scale.y == t.scale.z;
    j["scale"] = t.scaleWrittenAsNumber && uniform ? number(t.scale.x) : vector(t.scale);
}

Json objectJson(const Object& o, const std::string& baseDir) {
    Json j = Json::object();
    j["name"] = o.name;
    j["type"] = geometryTypeName(o.geometry);
    if (!o.material.empty()) j["material"] = o.material;
    if (!o.visible) j["visible"] = false;
    putGeometry(j, o.geometry, baseDir);
    // Planes take no transform: the format rejects the keys, so none are written.
    if (!std::holds_alternative<PlaneGeometry>(o.geometry)) putTransform(j, o.transform);
    putExtras(j, o.extras);
    return j;
}

std::string osError(int err) {
    return std::generic_category().message(err);
}

// Unique enough among concurrent savers; "x" mode below refuses to reuse an existing name.
std::string randomSuffix() {
    static thread_local std::mt19937_64 rng(std::random_device{}());
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(rng()));
    return buf;
}

bool writeAll(std::FILE* f, const std::string& text) {
    if (std::fwrite(text.data(), 1, text.size(), f) != text.size()) return false;
    if (std::fflush(f) != 0) return false;
#if defined(__unix__) || defined(__APPLE__)
    // Without this a crash right after rename can leave an empty file on some filesystems.
    if (::fsync(fileno(f)) != 0) return false;
#endif
    return true;
}
}  // namespace

std::string serializeScene(const SceneDocument& doc, const std::string& baseDir) {
    Json j = Json::object();
    j["format"] = "raystudio-scene";
    // Version 1 whenever it can say it all, so older builds keep reading what they can.
    j["version"] = version2Uses(doc).empty() ? 1 : kSceneFormatVersion;
    j["camera"] = cameraJson(doc.camera);
    if (!doc.views.empty()) {
        j["views"] = Json::array();
        for (const ViewBookmark& v : doc.views) j["views"].push_back(viewJson(v));
    }
    j["render"] = renderJson(doc.render);
    if (doc.environment.present()) j["environment"] = environmentJson(doc.environment, baseDir);
    j["materials"] = Json::array();
    for (const Material& m : doc.materials) j["materials"].push_back(materialJson(m, baseDir));
    j["lights"] = Json::array();
    for (const Light& l : doc.lights) j["lights"].push_back(lightJson(l));
    j["objects"] = Json::array();
    for (const Object& o : doc.objects) j["objects"].push_back(objectJson(o, baseDir));
    putExtras(j, doc.extras);
    return dumpJson(j, 2) + "\n";
}

bool saveScene(const std::string& path, const SceneDocument& doc, std::string& error) {
    std::error_code ec;
    fs::path target = fs::absolute(fs::path(path), ec);
    if (ec) target = path;
    if (fs::is_directory(target, ec)) {
        error = "cannot save \"" + path + "\": " + osError(EISDIR);
        return false;
    }
    const std::string text = serializeScene(doc, target.parent_path().string());

    fs::path temp;
    std::FILE* f = nullptr;
    for (int attempt = 0; attempt < 16 && !f; ++attempt) {
        std::string name = ".";  // hidden, so a crash's leftover does not clutter the folder
        name.append(target.filename().string()).append(".tmp-").append(randomSuffix());
        temp = target.parent_path() / name;
        f = std::fopen(temp.c_str(), "wbx");
        if (!f && errno != EEXIST) break;
    }
    if (!f) {
        error = "cannot save \"" + path + "\": " + osError(errno);
        return false;
    }
    bool written = writeAll(f, text);
    int writeErrno = errno;
    if (std::fclose(f) != 0 && written) {
        written = false;
        writeErrno = errno;
    }
    if (!written) {
        fs::remove(temp, ec);
        error = "cannot save \"" + path + "\": " + osError(writeErrno);
        return false;
    }
    // Keep the permissions of the file being replaced (e.g. a read-only group bit).
    fs::file_status old = fs::status(target, ec);
    if (!ec && fs::exists(old)) fs::permissions(temp, old.permissions(), ec);
    fs::rename(temp, target, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        error = "cannot save \"" + path + "\": " + ec.message();
        return false;
    }
    return true;
}

}  // namespace rs
