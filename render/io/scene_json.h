// JSON conventions shared by the scene reader and writer: the DOM type and float <-> number.
#pragma once

#include <nlohmann/json.hpp>

namespace rs {

/// Order-preserving DOM, so `x-` keys keep their file order and written keys keep ours.
using Json = nlohmann::ordered_json;

/// The float a scene-file number denotes: the parsed double rounded to float.
inline float floatFromJson(double d) {
    return static_cast<float>(d);
}

/// The shortest decimal (as a double) that floatFromJson maps back to exactly `f`, so files
/// say 0.9 rather than 0.89999997615814209 and still round-trip bit for bit.
double jsonNumberForFloat(float f);

/// Dumps `j` for scene files: never throws, even on invalid UTF-8 in strings.
std::string dumpJson(const Json& j, int indent = -1);

}  // namespace rs
