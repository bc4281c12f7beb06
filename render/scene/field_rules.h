// The rules of the scene format that relate two or more fields, each written once: the
// setters (the property panel) and the scene reader both apply them, so whatever one accepts
// the other does too.
#pragma once

#include <string>

#include "scene/document.h"

namespace rs {

/// A broken rule: the key a reader places it at and the message; `key` empty when none.
struct FieldRuleError {
    std::string key;
    std::string message;
    explicit operator bool() const { return !message.empty(); }
};

/// A plane's normal as stored: kept bit for bit when within 1e-6 of unit length (so saving
/// and loading is exact), else normalised in double precision. `n` must be non-zero.
Vec3 planeNormal(const Vec3& n);
/// A rectangle's half edges must be orthogonal (to a relative tolerance of 1e-4, so edges
/// rotated in the designer pass); placed at "v".
FieldRuleError rectangleEdgesError(const RectangleGeometry& g);
/// A box's max must exceed its min in every component; placed at "max", `axis` set to the
/// first component that does not (0, 1, 2).
FieldRuleError boxCornersError(const BoxGeometry& g, int* axis = nullptr);
/// reflectivity + transparency <= 1 (to 1e-6: 0.3 + 0.7 passes); placed at "transparency".
FieldRuleError materialWeightsError(const Material& m);
/// The camera must look somewhere: target != position ("target"), up not parallel to the
/// view ("up").
FieldRuleError cameraLookError(const Camera& c);

/// A spot light must aim somewhere: target != position ("target"). Other lights always pass.
/// (A falloff below the radius is allowed: the cone then ends in a hard edge at the radius.)
FieldRuleError spotConeError(const Light& l);
/// An image texture's scale is non-zero in both directions ("scale_u", "scale_v").
FieldRuleError textureScaleError(const ImageTexture& t);

/// A float as the shortest decimal that reads back as the same float ("0.9", "1e+20").
std::string floatText(float f);

}  // namespace rs
