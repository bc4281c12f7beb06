// The scene format's rules that relate fields.
#include "scene/field_rules.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace rs {

namespace {
// Relative: u and v of a rectangle rotated in the designer are orthogonal only to rounding.
constexpr double kOrthogonalTolerance = 1e-4;
// A normal this close to unit length is kept bit for bit, so save/load is exact.
constexpr double kUnitTolerance = 1e-6;
// Rounding of two decimal fractions (0.3 + 0.7) must not turn a valid sum into an error.
constexpr float kSumTolerance = 1e-6f;

glm::dvec3 toDouble(const Vec3& v) {
    return glm::dvec3(v.x, v.y, v.z);
}
}  // namespace

std::string floatText(float f) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, f).ptr;
    return std::string(text, end);
}

Vec3 planeNormal(const Vec3& normal) {
    glm::dvec3 n = toDouble(normal);
    const double length = glm::length(n);
    if (std::abs(length - 1.0) <= kUnitTolerance) return normal;
    n /= length;
    return Vec3(static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z));
}

FieldRuleError rectangleEdgesError(const RectangleGeometry& g) {
    const glm::dvec3 u = toDouble(g.u), v = toDouble(g.v);
    const double cosine = glm::dot(u, v) / (glm::length(u) * glm::length(v));
    if (std::abs(cosine) <= kOrthogonalTolerance) return {};
    const double degrees = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / 3.14159265358979;
    return {"v", "u and v must be orthogonal, they are " +
                     floatText(float(std::round(degrees * 100) / 100)) + " degrees apart"};
}

FieldRuleError boxCornersError(const BoxGeometry& g, int* axis) {
    static const char* const names[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
        if (g.min[a] < g.max[a]) continue;
        if (axis) *axis = a;
        return {"max", std::string("box max must be greater than min in every component (") +
                           names[a] + ": min " + floatText(g.min[a]) + ", max " +
                           floatText(g.max[a]) + ")"};
    }
    return {};
}

FieldRuleError materialWeightsError(const Material& m) {
    if (m.reflectivity + m.transparency <= 1.0f + kSumTolerance) return {};
    return {"transparency", "reflectivity + transparency must be <= 1, got " +
                                floatText(m.reflectivity) + " + " + floatText(m.transparency)};
}

FieldRuleError cameraLookError(const Camera& camera) {
    // In double: two distinct floats always differ, however close they are.
    const glm::dvec3 dir = toDouble(camera.target) - toDouble(camera.position);
    if (dir == glm::dvec3(0.0)) return {"target", "camera target must differ from its position"};
    const glm::dvec3 up = toDouble(camera.up);
    const double crossLength = glm::length(glm::cross(up, dir));
    if (crossLength <= 1e-6 * glm::length(up) * glm::length(dir))
        return {"up", "up must not be parallel to the view direction"};
    return {};
}

FieldRuleError spotConeError(const Light& l) {
    if (l.type != LightType::Spot) return {};
    if (toDouble(l.target) == toDouble(l.position))
        return {"target", "spot light target must differ from its position"};
    return {};
}

FieldRuleError textureScaleError(const ImageTexture& t) {
    if (t.scaleU == 0.0f) return {"scale_u", "texture scale must be non-zero"};
    if (t.scaleV == 0.0f) return {"scale_v", "texture scale must be non-zero"};
    return {};
}

}  // namespace rs
