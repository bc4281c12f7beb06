// Parameter descriptors for every editable kind: the render side describes its inputs, the UI
// generates its property panels from them (style.md, "the render side describes its inputs").
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scene/document.h"

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
    double min = -1e6;  ///< Smallest allowed value (per component for Vec3/Color).
    double max = 1e6;   ///< Largest allowed value (per component for Vec3/Color).
    double step = 0.1;  ///< Suggested spin-box step.
    ParamValue defaultValue = 0.0f;
    std::vector<std::string> enumNames;  ///< Enum only: the names, by index.
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
    Render
};

/// The descriptors of one kind, in display order.
const std::vector<ParamDescriptor>& parameters(ParamKind kind);
/// The descriptor of `key` in `kind`, or null.
const ParamDescriptor* findParameter(ParamKind kind, const std::string& key);
/// The kind of an object's geometry.
ParamKind geometryKind(const Geometry& geometry);
/// The kind of a light.
ParamKind lightKind(const Light& light);
/// Human name of a kind ("Sphere", "Render settings", ...).
const char* kindLabel(ParamKind kind);

/// Checks `value` against the descriptor's type and range; empty when fine, else the reason.
std::string validateParameter(const ParamDescriptor& desc, const ParamValue& value);

/// Typed getters: the value of `key`, or nullopt when the kind has no such key.
std::optional<ParamValue> getParameter(const Geometry& g, const std::string& key);
std::optional<ParamValue> getParameter(const Transform& t, const std::string& key);
std::optional<ParamValue> getParameter(const Material& m, const std::string& key);
std::optional<ParamValue> getParameter(const Light& l, const std::string& key);
std::optional<ParamValue> getParameter(const Camera& c, const std::string& key);
std::optional<ParamValue> getParameter(const RenderSettings& r, const std::string& key);

/// Typed setters: validate and assign. Return an empty string on success, else an error
/// naming the key and the problem (the target is then unchanged).
std::string setParameter(Geometry& g, const std::string& key, const ParamValue& value);
std::string setParameter(Transform& t, const std::string& key, const ParamValue& value);
std::string setParameter(Material& m, const std::string& key, const ParamValue& value);
std::string setParameter(Light& l, const std::string& key, const ParamValue& value);
std::string setParameter(Camera& c, const std::string& key, const ParamValue& value);
std::string setParameter(RenderSettings& r, const std::string& key, const ParamValue& value);

}  // namespace rs
