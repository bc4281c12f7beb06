// Parameter tables: one field list per kind binds each descriptor to its document member.
// The ranges here are the scene format's (scenes/FORMAT.md); the soft ranges are what an
// editor offers by default.
#include "scene/parameters.h"

#include <cmath>
#include <sstream>

#include "scene/field_rules.h"
#include "scene/field_table.h"

namespace rs {

namespace {

using fields::Field;
constexpr double kBig = 1e6;

/// Marks a field the format requires (it has no default, so it is always written).
template <class T>
Field<T> required(Field<T> f) {
    f.desc.required = true;
    f.desc.alwaysWritten = true;
    return f;
}
/// Marks a field the writer states even at its default.
template <class T>
Field<T> stated(Field<T> f) {
    f.desc.alwaysWritten = true;
    return f;
}

const std::vector<Field<SphereGeometry>>& sphereFields() {
    using G = SphereGeometry;
    static const std::vector<Field<G>> f{
        required(fields::vector("center", "Centre", &G::center)),
        required(fields::number("radius", "Radius", &G::radius, NumberRange::positive(), 1e-4, kBig,
                                0.05))};
    return f;
}
const std::vector<Field<PlaneGeometry>>& planeFields() {
    using G = PlaneGeometry;
    static const std::vector<Field<G>> f{
        required(fields::vector("point", "Point", &G::point)),
        required(
            fields::vector("normal", "Normal", &G::normal, VectorRule::NonZero, -1.0, 1.0, 0.05))};
    return f;
}
const std::vector<Field<RectangleGeometry>>& rectangleFields() {
    using G = RectangleGeometry;
    static const std::vector<Field<G>> f{
        required(fields::vector("center", "Centre", &G::center)),
        required(fields::vector("u", "Half edge U", &G::u, VectorRule::NonZero)),
        required(fields::vector("v", "Half edge V", &G::v, VectorRule::NonZero))};
    return f;
}
const std::vector<Field<BoxGeometry>>& boxFields() {
    using G = BoxGeometry;
    static const std::vector<Field<G>> f{required(fields::vector("min", "Min", &G::min)),
                                         required(fields::vector("max", "Max", &G::max))};
    return f;
}
const std::vector<Field<MeshGeometry>>& meshFields() {
    using G = MeshGeometry;
    static const std::vector<Field<G>> f{
        required(fields::text("file", "File", &G::file, ParamType::File)),
        fields::boolean("smooth_normals", "Smooth normals", &G::smoothNormals)};
    return f;
}
const std::vector<Field<Transform>>& transformFields() {
    using T = Transform;
    static const std::vector<Field<T>> f{
        fields::vector("translate", "Translate", &T::translate),
        fields::vector("rotate", "Rotate (deg)", &T::rotate, VectorRule::Any, -360, 360, 5),
        fields::vector("scale", "Scale", &T::scale, VectorRule::NonZeroComponents, 1e-4, kBig,
                       0.05)};
    return f;
}
const std::vector<Field<Material>>& materialFields() {
    using M = Material;
    const NumberRange fraction = NumberRange::fraction();
    static const std::vector<Field<M>> f{
        stated(fields::color("color", "Colour", &M::color)),
        fields::number("diffuse", "Diffuse", &M::diffuse, fraction, 0, 1, 0.05),
        fields::number("specular", "Specular", &M::specular, fraction, 0, 1, 0.05),
        fields::number("shininess", "Shininess", &M::shininess, NumberRange::nonNegative(), 0,
                       10000, 1),
        fields::number("reflectivity", "Reflectivity", &M::reflectivity, fraction, 0, 1, 0.05),
        fields::number("transparency", "Transparency", &M::transparency, fraction, 0, 1, 0.05),
        fields::number("ior", "Index of refraction", &M::ior, NumberRange::positive(), 0.01, 10,
                       0.01)};
    return f;
}
const std::vector<Field<Light>>& lightFields(LightType type) {
    using L = Light;
    const auto typeField = required(
        fields::choice("type", "Type", &L::type, {"point", "sphere", "directional", "spot"},
                       {"Point", "Sphere", "Sun (directional)", "Spot"}));
    const auto position = required(fields::vector("position", "Position", &L::position));
    const auto shade =
        std::vector<Field<L>>{fields::color("color", "Colour", &L::color),
                              fields::number("intensity", "Intensity", &L::intensity,
                                             NumberRange::positive(), 1e-4, kBig, 0.1)};
    auto list = [&](std::vector<Field<L>> own) {
        std::vector<Field<L>> f{typeField};
        f.insert(f.end(), own.begin(), own.end());
        f.insert(f.end(), shade.begin(), shade.end());
        return f;
    };
    static const std::vector<std::vector<Field<L>>> byType{
        list({position}),
        list({position, required(fields::number("radius", "Radius", &L::radius,
                                                NumberRange::positive(), 1e-4, kBig, 0.05))}),
        list({required(fields::vector("direction", "Direction", &L::direction, VectorRule::NonZero,
                                      -1.0, 1.0, 0.05))}),
        list({position, required(fields::vector("target", "Target", &L::target)),
              fields::number("radius", "Cone radius (deg)", &L::coneRadius,
                             NumberRange::closed(0, 90), 0, 90, 1),
              fields::number("falloff", "Cone falloff (deg)", &L::coneFalloff,
                             NumberRange::closed(0, 90), 0, 90, 1)})};
    return byType.at(std::size_t(type));
}
const std::vector<Field<Camera>>& cameraFields() {
    using C = Camera;
    static const std::vector<Field<C>> f{
        fields::choice("projection", "Projection", &C::projection, {"perspective", "orthographic"},
                       {"Perspective", "Orthographic"}),
        stated(fields::vector("position", "Position", &C::position)),
        stated(fields::vector("target", "Target", &C::target)),
        stated(fields::vector("up", "Up", &C::up, VectorRule::NonZero)),
        fields::number("fov_y", "Field of view (deg)", &C::fovY, NumberRange::open(0, 180), 0.1,
                       179.9, 1),
        fields::number("ortho_height", "Ortho height", &C::orthoHeight, NumberRange::positive(),
                       1e-4, kBig, 0.1)};
    return f;
}
const std::vector<Field<RenderSettings>>& renderFields() {
    using R = RenderSettings;
    static const std::vector<Field<R>> f{
        stated(fields::integer("width", "Width", &R::width, 1, kMaxImageSide, kMaxImageSide)),
        stated(fields::integer("height", "Height", &R::height, 1, kMaxImageSide, kMaxImageSide)),
        // The format accepts recursion to kMaxDepthLimit; an editor offers what is useful.
        fields::integer("max_depth", "Max depth", &R::maxDepth, 0, kMaxDepthLimit, 64),
        // [0, 1): the largest float below 1 closes what an editor offers.
        fields::number("min_weight", "Min ray weight", &R::minWeight,
                       NumberRange::fractionBelowOne(), 0.0, double(std::nextafter(1.0f, 0.0f)),
                       0.001),
        fields::integer("shadow_samples", "Shadow samples", &R::shadowSamples, 0, kMaxSampleCount,
                        256),
        fields::integer("supersampling", "Supersampling", &R::supersampling, 1, kMaxSampleCount,
                        256),
        fields::boolean("adaptive_supersampling", "Adaptive supersampling",
                        &R::adaptiveSupersampling),
        fields::choice("tonemap", "Tone mapping", &R::tonemap,
                       {"clamp", "linear", "reinhard", "aces"},
                       {"Clamp", "Linear", "Reinhard", "ACES"}),
        fields::number("exposure", "Exposure (stops)", &R::exposure, NumberRange::any(), -20, 20,
                       0.1),
        fields::color("background", "Background", &R::background),
        fields::color("ambient", "Ambient", &R::ambient),
        fields::boolean("opaque_shadows", "Opaque shadows (version 1)", &R::opaqueShadows)};
    return f;
}
const std::vector<Field<CheckerPattern>>& checkerFields() {
    using C = CheckerPattern;
    static const std::vector<Field<C>> f{
        fields::color("even", "Colour 1", &C::even), fields::color("odd", "Colour 2", &C::odd),
        fields::number("scale", "Cell size", &C::scale, NumberRange::positive(), 1e-3, kBig, 0.05)};
    return f;
}
/// An image file's path as written in the scene file (`file` of an ImageFile member).
template <class T>
Field<T> imageFile(const char* key, const char* label, ImageFile T::*m) {
    ParamDescriptor d = fields::describe(key, label, ParamType::File, NumberRange::any(), 0, 0, 0);
    d.defaultValue = std::string();
    d.required = true;
    d.alwaysWritten = true;
    return {std::move(d), [m](const T& t) { return ParamValue((t.*m).file); },
            [m](T& t, const ParamValue& v) {
                // A new path: whoever resolved the old one resolves this one again.
                t.*m = ImageFile{std::get<std::string>(v), {}};
            }};
}
const std::vector<Field<ImageTexture>>& imageTextureFields() {
    using I = ImageTexture;
    // A negative scale mirrors the image; zero would collapse it to one texel.
    const NumberRange any = NumberRange::any();
    static const std::vector<Field<I>> f{
        imageFile("texture", "Image", &I::image),
        fields::number("scale_u", "Repeat U", &I::scaleU, any, -1000, 1000, 0.1),
        fields::number("scale_v", "Repeat V", &I::scaleV, any, -1000, 1000, 0.1),
        fields::number("offset_u", "Offset U", &I::offsetU, any, -1000, 1000, 0.05),
        fields::number("offset_v", "Offset V", &I::offsetV, any, -1000, 1000, 0.05)};
    return f;
}
const std::vector<Field<Environment>>& environmentFields() {
    using E = Environment;
    static const std::vector<Field<E>> f{imageFile("file", "Image", &E::image),
                                         fields::number("intensity", "Intensity", &E::intensity,
                                                        NumberRange::nonNegative(), 0, 100, 0.05),
                                         fields::number("rotation", "Rotation (deg)", &E::rotation,
                                                        NumberRange::any(), -360, 360, 5)};
    return f;
}

const std::vector<Field<SphereGeometry>>& fieldsFor(const SphereGeometry&) {
    return sphereFields();
}
const std::vector<Field<PlaneGeometry>>& fieldsFor(const PlaneGeometry&) {
    return planeFields();
}
const std::vector<Field<RectangleGeometry>>& fieldsFor(const RectangleGeometry&) {
    return rectangleFields();
}
const std::vector<Field<BoxGeometry>>& fieldsFor(const BoxGeometry&) {
    return boxFields();
}
const std::vector<Field<MeshGeometry>>& fieldsFor(const MeshGeometry&) {
    return meshFields();
}
const std::vector<Field<Transform>>& fieldsFor(const Transform&) {
    return transformFields();
}
const std::vector<Field<Material>>& fieldsFor(const Material&) {
    return materialFields();
}
const std::vector<Field<Light>>& fieldsFor(const Light& l) {
    return lightFields(l.type);
}
const std::vector<Field<CheckerPattern>>& fieldsFor(const CheckerPattern&) {
    return checkerFields();
}
const std::vector<Field<ImageTexture>>& fieldsFor(const ImageTexture&) {
    return imageTextureFields();
}
const std::vector<Field<Environment>>& fieldsFor(const Environment&) {
    return environmentFields();
}
const std::vector<Field<Camera>>& fieldsFor(const Camera&) {
    return cameraFields();
}
const std::vector<Field<RenderSettings>>& fieldsFor(const RenderSettings&) {
    return renderFields();
}

std::string numberText(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
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

std::string checkVector(const ParamDescriptor& d, const Vec3& v) {
    for (int i = 0; i < 3; ++i) {
        if (d.vectorRule == VectorRule::NonZeroComponents && v[i] == 0.0f)
            return d.key + " components must be non-zero";
        if (d.vectorRule == VectorRule::NonNegative && v[i] < 0.0f)
            return d.key + " components must be >= 0, got " + numberText(v[i]);
    }
    if (d.vectorRule == VectorRule::NonZero && v == Vec3(0.0f))
        return d.key + " must be a non-zero vector";
    return {};
}

}  // namespace

const std::string& ParamDescriptor::enumLabel(int i) const {
    const auto& from = enumLabels.empty() ? enumNames : enumLabels;
    return from.at(std::size_t(i));
}

const std::vector<ParamDescriptor>& parameters(ParamKind kind) {
    using fields::descriptorsOf;
    static const std::vector<std::vector<ParamDescriptor>> all{
        descriptorsOf(sphereFields()),
        descriptorsOf(planeFields()),
        descriptorsOf(rectangleFields()),
        descriptorsOf(boxFields()),
        descriptorsOf(meshFields()),
        descriptorsOf(transformFields()),
        descriptorsOf(materialFields()),
        descriptorsOf(lightFields(LightType::Point)),
        descriptorsOf(lightFields(LightType::Sphere)),
        descriptorsOf(cameraFields()),
        descriptorsOf(renderFields()),
        descriptorsOf(lightFields(LightType::Directional)),
        descriptorsOf(lightFields(LightType::Spot)),
        descriptorsOf(checkerFields()),
        descriptorsOf(imageTextureFields()),
        descriptorsOf(environmentFields())};
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
    switch (light.type) {
        case LightType::Sphere:
            return ParamKind::SphereLight;
        case LightType::Directional:
            return ParamKind::DirectionalLight;
        case LightType::Spot:
            return ParamKind::SpotLight;
        case LightType::Point:
            break;
    }
    return ParamKind::PointLight;
}

const char* kindLabel(ParamKind kind) {
    static const char* const labels[] = {
        "Sphere",       "Plane",     "Rectangle",       "Box",
        "Mesh",         "Transform", "Material",        "Point light",
        "Sphere light", "Camera",    "Render settings", "Sun light",
        "Spot light",   "Checker",   "Image texture",   "Environment"};
    return labels[std::size_t(kind)];
}

const std::string& toneMapName(ToneMap tonemap) {
    return findParameter(ParamKind::Render, "tonemap")->enumNames.at(std::size_t(tonemap));
}

std::string validateParameter(const ParamDescriptor& d, const ParamValue& value) {
    if (!holdsFor(d.type, value)) return d.key + ": wrong value type";
    auto checkNumber = [&](double v) -> std::string {
        if (!std::isfinite(v)) return d.key + " must be finite";
        if (!d.range.contains(v))
            return d.key + " must be " + d.range.describe() + ", got " + numberText(v);
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
            return checkVector(d, v);
        }
        default:
            return {};
    }
}

template <class T>
std::string setField(T& target, const std::string& key, const ParamValue& value) {
    return fields::set(fieldsFor(target), target, key, value);
}
template std::string setField(SphereGeometry&, const std::string&, const ParamValue&);
template std::string setField(PlaneGeometry&, const std::string&, const ParamValue&);
template std::string setField(RectangleGeometry&, const std::string&, const ParamValue&);
template std::string setField(BoxGeometry&, const std::string&, const ParamValue&);
template std::string setField(MeshGeometry&, const std::string&, const ParamValue&);
template std::string setField(Transform&, const std::string&, const ParamValue&);
template std::string setField(Material&, const std::string&, const ParamValue&);
template std::string setField(Light&, const std::string&, const ParamValue&);
template std::string setField(Camera&, const std::string&, const ParamValue&);
template std::string setField(RenderSettings&, const std::string&, const ParamValue&);
template std::string setField(CheckerPattern&, const std::string&, const ParamValue&);
template std::string setField(ImageTexture&, const std::string&, const ParamValue&);
template std::string setField(Environment&, const std::string&, const ParamValue&);

template <class T>
std::optional<ParamValue> getField(const T& target, const std::string& key) {
    return fields::get(fieldsFor(target), target, key);
}
template std::optional<ParamValue> getField(const SphereGeometry&, const std::string&);
template std::optional<ParamValue> getField(const PlaneGeometry&, const std::string&);
template std::optional<ParamValue> getField(const RectangleGeometry&, const std::string&);
template std::optional<ParamValue> getField(const BoxGeometry&, const std::string&);
template std::optional<ParamValue> getField(const MeshGeometry&, const std::string&);
template std::optional<ParamValue> getField(const Transform&, const std::string&);
template std::optional<ParamValue> getField(const Material&, const std::string&);
template std::optional<ParamValue> getField(const Light&, const std::string&);
template std::optional<ParamValue> getField(const Camera&, const std::string&);
template std::optional<ParamValue> getField(const RenderSettings&, const std::string&);
template std::optional<ParamValue> getField(const CheckerPattern&, const std::string&);
template std::optional<ParamValue> getField(const ImageTexture&, const std::string&);
template std::optional<ParamValue> getField(const Environment&, const std::string&);

std::optional<ParamValue> getParameter(const Geometry& g, const std::string& key) {
    return std::visit([&](const auto& s) { return fields::get(fieldsFor(s), s, key); }, g);
}

std::string setParameter(Geometry& g, const std::string& key, const ParamValue& value) {
    return std::visit(
        [&](auto& s) -> std::string {
            using S = std::decay_t<decltype(s)>;
            S copy = s;
            if (std::string e = setField(copy, key, value); !e.empty()) return e;
            if constexpr (std::is_same_v<S, PlaneGeometry>) copy.normal = planeNormal(copy.normal);
            if constexpr (std::is_same_v<S, RectangleGeometry>) {
                if (auto e = rectangleEdgesError(copy)) return e.message;
            }
            if constexpr (std::is_same_v<S, BoxGeometry>) {
                if (auto e = boxCornersError(copy)) return e.message;
            }
            s = std::move(copy);
            return {};
        },
        g);
}

std::optional<ParamValue> getParameter(const Transform& t, const std::string& key) {
    return fields::get(transformFields(), t, key);
}
std::string setParameter(Transform& t, const std::string& key, const ParamValue& value) {
    return setField(t, key, value);
}
std::optional<ParamValue> getParameter(const Material& m, const std::string& key) {
    return fields::get(materialFields(), m, key);
}
std::string setParameter(Material& m, const std::string& key, const ParamValue& value) {
    Material copy = m;
    if (std::string e = setField(copy, key, value); !e.empty()) return e;
    if (auto e = materialWeightsError(copy)) return e.message;
    m = std::move(copy);
    return {};
}
std::optional<ParamValue> getParameter(const Light& l, const std::string& key) {
    return fields::get(fieldsFor(l), l, key);
}
std::string setParameter(Light& l, const std::string& key, const ParamValue& value) {
    Light copy = l;
    if (std::string e = setField(copy, key, value); !e.empty()) return e;
    if (auto e = spotConeError(copy)) return e.message;
    l = std::move(copy);
    return {};
}
std::optional<ParamValue> getParameter(const Camera& c, const std::string& key) {
    return fields::get(cameraFields(), c, key);
}
std::string setParameter(Camera& c, const std::string& key, const ParamValue& value) {
    Camera copy = c;
    if (std::string e = setField(copy, key, value); !e.empty()) return e;
    if (auto e = cameraLookError(copy)) return e.message;
    c = std::move(copy);
    return {};
}
std::optional<ParamValue> getParameter(const RenderSettings& r, const std::string& key) {
    return fields::get(renderFields(), r, key);
}
std::string setParameter(RenderSettings& r, const std::string& key, const ParamValue& value) {
    RenderSettings copy = r;
    if (std::string e = setField(copy, key, value); !e.empty()) return e;
    if (std::string e = imageSizeError(copy.width, copy.height); !e.empty()) return e;
    r = std::move(copy);
    return {};
}

std::optional<ParamValue> getParameter(const CheckerPattern& c, const std::string& key) {
    return getField(c, key);
}
std::optional<ParamValue> getParameter(const ImageTexture& t, const std::string& key) {
    return getField(t, key);
}
std::optional<ParamValue> getParameter(const Environment& e, const std::string& key) {
    return getField(e, key);
}
std::string setParameter(CheckerPattern& c, const std::string& key, const ParamValue& value) {
    return setField(c, key, value);
}
std::string setParameter(ImageTexture& t, const std::string& key, const ParamValue& value) {
    ImageTexture copy = t;
    if (std::string e = setField(copy, key, value); !e.empty()) return e;
    if (auto e = textureScaleError(copy)) return e.message;
    t = std::move(copy);
    return {};
}
std::string setParameter(Environment& e, const std::string& key, const ParamValue& value) {
    return setField(e, key, value);
}

}  // namespace rs
