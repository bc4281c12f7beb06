// Float formatting for scene files: the shortest decimal that reads back as the same float.
#include "io/scene_json.h"

#include <charconv>
#include <cmath>

namespace rs {

double jsonNumberForFloat(float f) {
    const double exact = static_cast<double>(f);
    if (!std::isfinite(exact)) return exact;
    // std::to_chars/from_chars, unlike printf/strtod, ignore the C locale (Qt sets it).
    char buf[64];
    for (int precision = 1; precision <= 9; ++precision) {
        auto [end, ec] =
            std::to_chars(buf, buf + sizeof buf, exact, std::chars_format::general, precision);
        if (ec != std::errc()) break;
        double candidate = 0.0;
        auto parsed = std::from_chars(buf, end, candidate);
        if (parsed.ec == std::errc() && floatFromJson(candidate) == f) return candidate;
    }
    return exact;
}

std::string dumpJson(const Json& j, int indent) {
    return j.dump(indent, ' ', false, Json::error_handler_t::replace);
}

}  // namespace rs
