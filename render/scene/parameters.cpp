// Parameter tables: one field list per kind binds each descriptor to its document member.
#include "scene/parameters.h"

#include <cmath>
#include <functional>
#include <sstream>

namespace rs {

namespace {

constexpr double kBig = 1e6;

/// A descriptor plus how to read and write it on a T.
template <class T>
struct Field {
    ParamDescriptor desc;
    std::function<ParamValue(const T&)> get;
    std::function<void(T&, const ParamValue&)> set;
};

template <class T>
Field<T> floatField(const char* key, const char* label, float T::*m, double lo, double hi,
                    double step) {
    return {{key, label, ParamType::Float, lo, hi, step, T{}.*m, {}},
            [m](const T& t) { return ParamValue(t.*m); },
            [m](T& t, const ParamValue& v) { t.*m = std::get<float>(v); }};
}

template <class T>
Field<T> intField(const char* key, const char* label, int T::*m, int lo, int hi) {
    return {{key, label, ParamType::Int, double(lo), double(hi), 1.0, T{}.*m, {}},
            [m](const T& t) { return ParamValue(t.*m); },
            [m](T& t, const ParamValue& v) { t.*m = std::get<int>(v); }};
}

template <class T>
Field<T> boolField(const char* key, const char* label, bool T::*m) {
    return {{key, label, ParamType::Bool, 0, 1, 1, T{}.*m, {}},
            [m](const T& t) { return ParamValue(t.*m); },
            [m](T& t, const ParamValue& v) { t.*m = std::get<bool>(v); }};
}

template <class T>
Field<T> vecField(const char* key, const char* label, Vec3 T::*m, ParamType type = ParamType::Vec3,
                  double lo = -kBig, double hi = kBig, double step = 0.1) {
    return {{key, label, type, lo, hi, step, T{}.*m, {}},
            [m](const T& t) { return ParamValue(t.*m); },
            [m](T& t, const ParamValue& v) { t.*m = std::get<Vec3>(v); }};
}

template <class T>
Field<T> colorField(const char* key, const char* label, Vec3 T::*m) {
    return vecField(key, label, m, ParamType::Color, 0.0, 100.0, 0.05);
}

template <class T, class E>
Field<T> enumField(const char* key, const char* label, E T::*m, std::vector<std::string> names) {
    return {{key, label, ParamType::Enum, 0, double(names.size() - 1), 1, int(T{}.*m), names},
            [m](const T& t) { return ParamValue(int(t.*m)); },
            [m](T& t, const ParamValue& v) { t.*m = E(std::get<int>(v)); }};
}

template <class T>
Field<T> textField(const char* key, const char* label, std::string T::*m, ParamType type) {
    return {{key, label, type, 0, 0, 0, T{}.*m, {}},
            [m](const T& t) { return ParamValue(t.*m); },
            [m](T& t, const ParamValue& v) { t.*m = std::get<std::string>(v); }};
}

const std::vector<Field<SphereGeometry>>& sphereFields() {
    static const std::vector<Field<SphereGeometry>> f{
        vecField("center", "Centre", &SphereGeometry::center),
        floatField("radius", "Radius", &SphereGeometry::radius, 1e-4, kBig, 0.05)};
    return f;
}
const std::vector<Field<PlaneGeometry>>& planeFields() {
    static const std::vector<Field<PlaneGeometry>> f{
        vecField("point", "Point", &PlaneGeometry::point),
        vecField("normal", "Normal", &PlaneGeometry::normal, ParamType::Vec3, -1.0, 1.0, 0.05)};
    return f;
}
const std::vector<Field<RectangleGeometry>>& rectangleFields() {
    static const std::vector<Field<RectangleGeometry>> f{
        vecField("center", "Centre", &RectangleGeometry::center),
        vecField("u", "Half edge U", &RectangleGeometry::u),
        vecField("v", "Half edge V", &RectangleGeometry::v)};
    return f;
}
const std::vector<Field<BoxGeometry>>& boxFields() {
    static const std::vector<Field<BoxGeometry>> f{vecField("min", "Min", &BoxGeometry::min),
                                                   vecField("max", "Max", &BoxGeometry::max)};
    return f;
}
const std::vector<Field<MeshGeometry>>& meshFields() {
    static const std::vector<Field<MeshGeometry>> f{
        textField("file", "File", &MeshGeometry::file, ParamType::File),
        boolField("smooth_normals", "Smooth normals", &MeshGeometry::smoothNormals)};
    return f;
}
const std::vector<Field<Transform>>& transformFields() {
    static const std::vector<Field<Transform>> f{
        vecField("translate", "Translate", &Transform::translate),
        vecField("rotate", "Rotate (deg)", &Transform::rotate, ParamType::Vec3, -360, 360, 5),
        vecField("scale", "Scale", &Transform::scale, ParamType::Vec3, 1e-4, kBig, 0.05)};
    return f;
}
const std::vector<Field<Material>>& materialFields() {
    static const std::vector<Field<Material>> f{
        colorField("color", "Colour", &Material::color),
        floatField("diffuse", "Diffuse", &Material::diffuse, 0, 1, 0.05),
        floatField("specular", "Specular", &Material::specular, 0, 1, 0.05),
        floatField("shininess", "Shininess", &Material::shininess, 0, 10000, 1),
        floatField("reflectivity", "Reflectivity", &Material::reflectivity, 0, 1, 0.05),
        floatField("transparency", "Transparency", &Material::transparency, 0, 1, 0.05),
        floatField("ior", "Index of refraction", &Material::ior, 0.01, 10, 0.01)};
    return f;
}
const std::vector<Field<Light>>& lightFields(bool sphere) {
    static const std::vector<Field<Light>> point{
        enumField("type", "Type", &Light::type, {"point", "sphere"}),
        vecField("position", "Position", &Light::position),
        colorField("color", "Colour", &Light::color),
        floatField("intensity", "Intensity", &Light::intensity, 1e-4, kBig, 0.1)};
    static const std::vector<Field<Light>> sphereLight = [] {
        auto f = point;
        f.insert(f.begin() + 2, floatField("radius", "Radius", &Light::radius, 1e-4, kBig, 0.05));
        return f;
    }();
    return sphere ? sphereLight : point;
}
const std::vector<Field<Camera>>& cameraFields() {
    static const std::vector<Field<Camera>> f{
        enumField("projection", "Projection", &Camera::projection, {"perspective", "orthographic"}),
        vecField("position", "Position", &Camera::position),
        vecField("target", "Target", &Camera::target),
        vecField("up", "Up", &Camera::up),
        floatField("fov_y", "Field of view (deg)", &Camera::fovY, 0.1, 179.9, 1),
        floatField("ortho_height", "Ortho height", &Camera::orthoHeight, 1e-4, kBig, 0.1)};
    return f;
}
const std::vector<Field<RenderSettings>>& renderFields() {
    static const std::vector<Field<RenderSettings>> f{
        intField("width", "Width", &RenderSettings::width, 1, 16384),
        intField("height", "Height", &RenderSettings::height, 1, 16384),
        intField("max_depth", "Max depth", &RenderSettings::maxDepth, 0, 64),
        // [0, 1) in the format: the largest float below 1 closes the descriptor's range.
        floatField("min_weight", "Min ray weight", &RenderSettings::minWeight, 0.0,
                   double(std::nextafter(1.0f, 0.0f)), 0.001),
        intField("shadow_samples", "Shadow samples", &RenderSettings::shadowSamples, 0, 256),
        intField("supersampling", "Supersampling", &RenderSettings::supersampling, 1, 256),
        boolField("adaptive_supersampling", "Adaptive supersampling",
                  &RenderSettings::adaptiveSupersampling),
        enumField("tonemap", "Tone mapping", &RenderSettings::tonemap,
                  {"clamp", "linear", "reinhard", "aces"}),
        floatField("exposure", "Exposure (stops)", &RenderSettings::exposure, -20, 20, 0.1),
        colorField("background", "Background", &RenderSettings::background),
        colorField("ambient", "Ambient", &RenderSettings::ambient)};
    return f;
}

template <class T>
std::vector<ParamDescriptor> descriptorsOf(const std::vector<Field<T>>& fields) {
    std::vector<ParamDescriptor> out;
    for (const auto& f : fields) out.push_back(f.desc);
    return out;
}

template <class T>
std::optional<ParamValue> getField(const std::vector<Field<T>>& fields, const T& t,
                                   const std::string& key) {
    for (const auto& f : fields)
        if (f.desc.key == key) return f.get(t);
    return std::nullopt;
}

template <class T>
std::string setField(const std::vector<Field<T>>& fields, T& t, const std::string& key,
                     const ParamValue& value) {
    for (const auto& f : fields) {
        if (f.desc.key != key) continue;
        if (std::string e = validateParameter(f.desc, value); !e.empty()) return e;
        f.set(t, value);
        return {};
    }
    return "unknown parameter '" + key + "'";
}

std::string numberText(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

std::string rangeError(const ParamDescriptor& d, double v) {
    return d.key + " must be in [" + numberText(d.min) + ", " + numberText(d.max) + "], got " +
           numberText(v);
}

bool holdsFor(ParamType type, const ParamValue& v) {
    switch (type) {
        case ParamType::Float:
            return std::holds_alternative<float>(v);
        case ParamType::Int:
        case ParamType::Enum:
            return std::holds_alternative<int>(v);
        case ParamType::Bool:
            return std::holds_alternative<bool>(v);
        case ParamType::Vec3:
        case ParamType::Color:
            return std::holds_alternative<Vec3>(v);
        case ParamType::Text:
        case ParamType::File:
            return std::holds_alternative<std::string>(v);
    }
    return false;
}

}  // namespace

const std::vector<ParamDescriptor>& parameters(ParamKind kind) {
    static const std::vector<std::vector<ParamDescriptor>> all{
        descriptorsOf(sphereFields()),    descriptorsOf(planeFields()),
        descriptorsOf(rectangleFields()), descriptorsOf(boxFields()),
        descriptorsOf(meshFields()),      descriptorsOf(transformFields()),
        descriptorsOf(materialFields()),  descriptorsOf(lightFields(false)),
        descriptorsOf(lightFields(true)), descriptorsOf(cameraFields()),
        descriptorsOf(renderFields())};
    return all[std::size_t(kind)];
}

const ParamDescriptor* findParameter(ParamKind kind, const std::string& key) {
    for (const auto& d : parameters(kind))
        if (d.key == key) return &d;
    return nullptr;
}

ParamKind geometryKind(const Geometry& geometry) {
    return ParamKind(geometry.index());  // Variant order matches the first five kinds.
}

ParamKind lightKind(const Light& light) {
    return light.type == LightType::Sphere ? ParamKind::SphereLight : ParamKind::PointLight;
}

const char* kindLabel(ParamKind kind) {
    static const char* const labels[] = {
        "Sphere",   "Plane",       "Rectangle",    "Box",    "Mesh",           "Transform",
        "Material", "Point light", "Sphere light", "Camera", "Render settings"};
    return labels[std::size_t(kind)];
}

std::string validateParameter(const ParamDescriptor& d, const ParamValue& value) {
    if (!holdsFor(d.type, value)) return d.key + ": wrong value type";
    auto checkNumber = [&](double v) -> std::string {
        if (!std::isfinite(v)) return d.key + " must be finite";
        if (v < d.min || v > d.max) return rangeError(d, v);
        return {};
    };
    switch (d.type) {
        case ParamType::Float:
            return checkNumber(std::get<float>(value));
        case ParamType::Int:
        case ParamType::Enum:
            return checkNumber(std::get<int>(value));
        case ParamType::Vec3:
        case ParamType::Color: {
            const Vec3 v = std::get<Vec3>(value);
            for (int i = 0; i < 3; ++i)
                if (std::string e = checkNumber(v[i]); !e.empty()) return e;
            return {};
        }
        default:
            return {};
    }
}

std::optional<ParamValue> getParameter(const Geometry& g, const std::string& key) {
    return std::visit(
        [&](const auto& s) -> std::optional<ParamValue> {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, SphereGeometry>)
                return getField(sphereFields(), s, key);
            if constexpr (std::is_same_v<S, PlaneGeometry>) return getField(planeFields(), s, key);
            if constexpr (std::is_same_v<S, RectangleGeometry>)
                return getField(rectangleFields(), s, key);
            if constexpr (std::is_same_v<S, BoxGeometry>) return getField(boxFields(), s, key);
            if constexpr (std::is_same_v<S, MeshGeometry>) return getField(meshFields(), s, key);
        },
        g);
}

std::string setParameter(Geometry& g, const std::string& key, const ParamValue& value) {
    return std::visit(
        [&](auto& s) -> std::string {
            using S = std::decay_t<decltype(s)>;
            S copy = s;
            std::string e;
            if constexpr (std::is_same_v<S, SphereGeometry>)
                e = setField(sphereFields(), copy, key, value);
            if constexpr (std::is_same_v<S, PlaneGeometry>) {
                e = setField(planeFields(), copy, key, value);
                if (e.empty() && key == "normal") {
                    if (glm::length(copy.normal) < 1e-6f) return "normal must not be zero";
                    copy.normal = glm::normalize(copy.normal);
                }
            }
            if constexpr (std::is_same_v<S, RectangleGeometry>) {
                e = setField(rectangleFields(), copy, key, value);
                if (e.empty() && glm::length(glm::cross(copy.u, copy.v)) < 1e-8f)
                    return "u and v must span a rectangle";
            }
            if constexpr (std::is_same_v<S, BoxGeometry>) {
                e = setField(boxFields(), copy, key, value);
                if (e.empty() &&
                    (copy.min.x > copy.max.x || copy.min.y > copy.max.y || copy.min.z > copy.max.z))
                    return "box min must not exceed max";
            }
            if constexpr (std::is_same_v<S, MeshGeometry>)
                e = setField(meshFields(), copy, key, value);
            if (e.empty()) s = std::move(copy);
            return e;
        },
        g);
}

std::optional<ParamValue> getParameter(const Transform& t, const std::string& key) {
    return getField(transformFields(), t, key);
}
std::string setParameter(Transform& t, const std::string& key, const ParamValue& value) {
    return setField(transformFields(), t, key, value);
}
std::optional<ParamValue> getParameter(const Material& m, const std::string& key) {
    return getField(materialFields(), m, key);
}
std::string setParameter(Material& m, const std::string& key, const ParamValue& value) {
    Material copy = m;
    if (std::string e = setField(materialFields(), copy, key, value); !e.empty()) return e;
    if (copy.reflectivity + copy.transparency > 1.0f + 1e-6f)
        return "reflectivity + transparency must not exceed 1";
    m = std::move(copy);
    return {};
}
std::optional<ParamValue> getParameter(const Light& l, const std::string& key) {
    return getField(lightFields(l.type == LightType::Sphere), l, key);
}
std::string setParameter(Light& l, const std::string& key, const ParamValue& value) {
    return setField(lightFields(l.type == LightType::Sphere), l, key, value);
}
std::optional<ParamValue> getParameter(const Camera& c, const std::string& key) {
    return getField(cameraFields(), c, key);
}
std::string setParameter(Camera& c, const std::string& key, const ParamValue& value) {
    Camera copy = c;
    if (std::string e = setField(cameraFields(), copy, key, value); !e.empty()) return e;
    const Vec3 forward = copy.target - copy.position;
    if (glm::length(forward) < 1e-6f) return "camera target must differ from its position";
    if (glm::length(glm::cross(forward, copy.up)) < 1e-8f)
        return "camera up must not be parallel to the view";
    c = std::move(copy);
    return {};
}
std::optional<ParamValue> getParameter(const RenderSettings& r, const std::string& key) {
    return getField(renderFields(), r, key);
}
std::string setParameter(RenderSettings& r, const std::string& key, const ParamValue& value) {
    return setField(renderFields(), r, key, value);
}

}  // namespace rs
