// Number ranges: membership and how a message states them.
#include "scene/value_range.h"

#include <charconv>
#include <cmath>

namespace rs {

std::string formatBound(double v) {
    if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, v).ptr;
    return std::string(text, end);
}

bool NumberRange::contains(double v) const {
    const bool aboveMin = minOpen ? v > min : v >= min;
    const bool belowMax = maxOpen ? v < max : v <= max;
    return aboveMin && belowMax;
}

std::string NumberRange::describe() const {
    if (std::isinf(min) && std::isinf(max)) return "any number";
    if (std::isinf(max)) return (minOpen ? "> " : ">= ") + formatBound(min);
    if (std::isinf(min)) return (maxOpen ? "< " : "<= ") + formatBound(max);
    return std::string("in ") + (minOpen ? "(" : "[") + formatBound(min) + ", " + formatBound(max) +
           (maxOpen ? ")" : "]");
}

}  // namespace rs
