// Writing scene files: key order, omitted defaults, extras, mesh paths and atomic saving.
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <random>
#include <system_error>

#include "io/scene_io.h"
#include "io/scene_json.h"

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

Json cameraJson(const Camera& c) {
    const Camera d;
    Json j = Json::object();
    if (c.projection == Projection::Orthographic) j["projection"] = "orthographic";
    j["position"] = vector(c.position);
    j["target"] = vector(c.target);
    j["up"] = vector(c.up);
    if (c.projection == Projection::Perspective || c.fovY != d.fovY) j["fov_y"] = number(c.fovY);
    if (c.projection == Projection::Orthographic || c.orthoHeight != d.orthoHeight)
        j["ortho_height"] = number(c.orthoHeight);
    putExtras(j, c.extras);
    return j;
}

Json renderJson(const RenderSettings& r) {
    static const char* const tonemaps[] = {"clamp", "linear", "reinhard", "aces"};
    const RenderSettings d;
    Json j = Json::object();
    j["width"] = r.width;
    j["height"] = r.height;
    if (r.maxDepth != d.maxDepth) j["max_depth"] = r.maxDepth;
    if (r.minWeight != d.minWeight) j["min_weight"] = number(r.minWeight);
    if (r.shadowSamples != d.shadowSamples) j["shadow_samples"] = r.shadowSamples;
    if (r.supersampling != d.supersampling) j["supersampling"] = r.supersampling;
    if (r.adaptiveSupersampling != d.adaptiveSupersampling)
        j["adaptive_supersampling"] = r.adaptiveSupersampling;
    if (r.tonemap != d.tonemap) j["tonemap"] = tonemaps[static_cast<int>(r.tonemap)];
    if (r.exposure != d.exposure) j["exposure"] = number(r.exposure);
    if (r.background != d.background) j["background"] = vector(r.background);
    if (r.ambient != d.ambient) j["ambient"] = vector(r.ambient);
    putExtras(j, r.extras);
    return j;
}

Json materialJson(const Material& m) {
    const Material d;
    Json j = Json::object();
    j["name"] = m.name;
    j["color"] = vector(m.color);
    if (m.diffuse != d.diffuse) j["diffuse"] = number(m.diffuse);
    if (m.specular != d.specular) j["specular"] = number(m.specular);
    if (m.shininess != d.shininess) j["shininess"] = number(m.shininess);
    if (m.reflectivity != d.reflectivity) j["reflectivity"] = number(m.reflectivity);
    if (m.transparency != d.transparency) j["transparency"] = number(m.transparency);
    if (m.ior != d.ior) j["ior"] = number(m.ior);
    putExtras(j, m.extras);
    return j;
}

Json lightJson(const Light& l) {
    const Light d;
    Json j = Json::object();
    j["name"] = l.name;
    j["type"] = l.type == LightType::Sphere ? "sphere" : "point";
    j["position"] = vector(l.position);
    // A point light's radius has no meaning and the format forbids the key.
    if (l.type == LightType::Sphere) j["radius"] = number(l.radius);
    if (l.color != d.color) j["color"] = vector(l.color);
    if (l.intensity != d.intensity) j["intensity"] = number(l.intensity);
    putExtras(j, l.extras);
    return j;
}

// Relative when the mesh lies below `baseDir`, so a project folder can move as a whole.
std::string meshFileFor(const MeshGeometry& g, const std::string& baseDir) {
    fs::path absolute;
    if (!g.resolvedPath.empty())
        absolute = g.resolvedPath;
    else if (fs::path(g.file).is_absolute())
        absolute = g.file;
    if (absolute.empty() || baseDir.empty()) return g.file;  // nothing to re-anchor against
    std::error_code ec;
    fs::path base = fs::absolute(fs::path(baseDir), ec).lexically_normal();
    if (ec) return g.file;
    if (base.filename().empty()) base = base.parent_path();  // "/a/b/" -> "/a/b"
    absolute = absolute.lexically_normal();
    fs::path relative = absolute.lexically_relative(base);
    if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
    return absolute.generic_string();
}

void putGeometry(Json& j, const Geometry& geometry, const std::string& baseDir) {
    if (const auto* s = std::get_if<SphereGeometry>(&geometry)) {
        j["center"] = vector(s->center);
        j["radius"] = number(s->radius);
    } else if (const auto* p = std::get_if<PlaneGeometry>(&geometry)) {
        j["point"] = vector(p->point);
        j["normal"] = vector(p->normal);
    } else if (const auto* r = std::get_if<RectangleGeometry>(&geometry)) {
        j["center"] = vector(r->center);
        j["u"] = vector(r->u);
        j["v"] = vector(r->v);
    } else if (const auto* b = std::get_if<BoxGeometry>(&geometry)) {
        j["min"] = vector(b->min);
        j["max"] = vector(b->max);
    } else if (const auto* m = std::get_if<MeshGeometry>(&geometry)) {
        j["file"] = meshFileFor(*m, baseDir);
        if (!m->smoothNormals) j["smooth_normals"] = false;
    }
}

void putTransform(Json& j, const Transform& t) {
    if (t.translate != Vec3(0.0f)) j["translate"] = vector(t.translate);
    if (t.rotate != Vec3(0.0f)) j["rotate"] = vector(t.rotate);
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
    j["version"] = 1;
    j["camera"] = cameraJson(doc.camera);
    j["render"] = renderJson(doc.render);
    j["materials"] = Json::array();
    for (const Material& m : doc.materials) j["materials"].push_back(materialJson(m));
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
