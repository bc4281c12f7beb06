// Parameter descriptors for every editable kind: the one place a field's name, type, range,
// default and label are written. The scene reader and writer, the property panel and the
// Preferences dialog are all driven by them.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scene/document.h"
#include "scene/value_range.h"

namespace rs {

/// Value types a parameter can have.
enum class ParamType { Float, Int, Bool, Vec3, Color, Enum, Text, File };

/// A parameter value. Float: float; Int and Enum: int (enum index); Bool: bool;
/// Vec3 and Color: Vec3; Text and File: std::string.
using ParamValue = std::variant<float, int, bool, Vec3, std::string>;

/// One editable input of a kind.
struct ParamDescriptor {
    std::string key;    ///< As in the scene format, e.g. "radius".
    std::string label;  ///< For humans, e.g. "Radius".
    ParamType type = ParamType::Float;
    /// What the format accepts (per component for Vec3/Color; always finite): the reader
    /// refuses anything outside it, and so does every setter.
    NumberRange range;
    /// Vec3 and Color: what the vector as a whole must satisfy.
    VectorRule vectorRule = VectorRule::Any;
    /// What an editor offers (slider and spin-box bounds), inside `range`. A value beyond it
    /// that a file holds is still shown and kept: the editor widens to it.
    double softMin = -1e6;
    double softMax = 1e6;
    double step = 0.1;  ///< Suggested spin-box step.
    ParamValue defaultValue = 0.0f;
    std::vector<std::string> enumNames;   ///< Enum only: the format's spellings, by index.
    std::vector<std::string> enumLabels;  ///< Enum only: for humans, by index (empty: names).
    bool required = false;                ///< A file must give it: the format has no default.
    /// The writer writes it even when it holds its default (required keys always are).
    bool alwaysWritten = false;
    /// Shown by an editor in place of its smallest value (e.g. "Off", "Scene's max depth").
    std::string specialValueText;
    std::string toolTip;  ///< A sentence for humans; may be empty.

    /// The human label of enum index `i`.
    const std::string& enumLabel(int i) const;
};

/// The kinds that publish parameters.
enum class ParamKind {
    Sphere,
    Plane,
    Rectangle,
    Box,
    Mesh,
    Transform,
    Material,
    PointLight,
    SphereLight,
    Camera,
    Render,
    DirectionalLight,
    SpotLight,
    Checker,       ///< A material colour's `{"checker": ...}` form.
    ImageTexture,  ///< A material colour's `{"texture": ...}` form.
    Environment
};
/// Every kind, in enum order (for tests and tools that walk the schema).
inline constexpr ParamKind kAllParamKinds[] = {
    ParamKind::Sphere,     ParamKind::Plane,      ParamKind::Rectangle,
    ParamKind::Box,        ParamKind::Mesh,       ParamKind::Transform,
    ParamKind::Material,   ParamKind::PointLight, ParamKind::SphereLight,
    ParamKind::Camera,     ParamKind::Render,     ParamKind::DirectionalLight,
    ParamKind::SpotLight,  ParamKind::Checker,    ParamKind::ImageTexture,
    ParamKind::Environment};

/// The descriptors of one kind, in display order (also the order keys are written in).
const std::vector<ParamDescriptor>& parameters(ParamKind kind);
/// The descriptor of `key` in `kind`, or null.
const ParamDescriptor* findParameter(ParamKind kind, const std::string& key);
/// The kind of an object's geometry.
ParamKind geometryKind(const Geometry& geometry);
/// The kind of a light.
ParamKind lightKind(const Light& light);
/// Human name of a kind ("Sphere", "Render settings", ...).
const char* kindLabel(ParamKind kind);
/// The format's spelling of a tone-map operator ("clamp", "linear", "reinhard", "aces").
const std::string& toneMapName(ToneMap tonemap);

/// Checks `value` against the descriptor's type, range and vector rule; empty when fine,
/// else the reason ("radius must be > 0, got 0").
std::string validateParameter(const ParamDescriptor& desc, const ParamValue& value);

/// Typed getters: the value of `key`, or nullopt when the kind has no such key.
std::optional<ParamValue> getParameter(const Geometry& g, const std::string& key);
std::optional<ParamValue> getParameter(const Transform& t, const std::string& key);
std::optional<ParamValue> getParameter(const Material& m, const std::string& key);
std::optional<ParamValue> getParameter(const Light& l, const std::string& key);
std::optional<ParamValue> getParameter(const Camera& c, const std::string& key);
std::optional<ParamValue> getParameter(const RenderSettings& r, const std::string& key);

/// Typed setters: validate (the field alone, then the rules that relate fields, such as
/// reflectivity + transparency <= 1) and assign. Return an empty string on success, else an
/// error naming the key and the problem (the target is then unchanged).
std::string setParameter(Geometry& g, const std::string& key, const ParamValue& value);
std::string setParameter(Transform& t, const std::string& key, const ParamValue& value);
std::string setParameter(Material& m, const std::string& key, const ParamValue& value);
std::string setParameter(Light& l, const std::string& key, const ParamValue& value);
std::string setParameter(Camera& c, const std::string& key, const ParamValue& value);
std::string setParameter(RenderSettings& r, const std::string& key, const ParamValue& value);
std::optional<ParamValue> getParameter(const CheckerPattern& c, const std::string& key);
std::optional<ParamValue> getParameter(const ImageTexture& t, const std::string& key);
std::optional<ParamValue> getParameter(const Environment& e, const std::string& key);
std::string setParameter(CheckerPattern& c, const std::string& key, const ParamValue& value);
std::string setParameter(ImageTexture& t, const std::string& key, const ParamValue& value);
std::string setParameter(Environment& e, const std::string& key, const ParamValue& value);

/// Validates and assigns one field alone, without the rules that relate fields: the scene
/// reader uses it and then checks those rules itself, naming positions in the file.
/// Defined for SphereGeometry, PlaneGeometry, RectangleGeometry, BoxGeometry, MeshGeometry,
/// Transform, Material, Light, Camera, RenderSettings, CheckerPattern, ImageTexture and
/// Environment.
template <class T>
std::string setField(T& target, const std::string& key, const ParamValue& value);
/// The value of one field by key (the same types as setField), or nullopt.
template <class T>
std::optional<ParamValue> getField(const T& target, const std::string& key);

}  // namespace rs
