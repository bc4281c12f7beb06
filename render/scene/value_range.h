// What a number or an [x, y, z] value of the scene format must satisfy: written once, read by
// the parameter descriptors, the scene reader and the editors alike.
#pragma once

#include <limits>
#include <string>

namespace rs {

/// An interval a number must lie in, with open or closed ends.
struct NumberRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minOpen = false;
    bool maxOpen = false;

    static NumberRange any() { return {}; }
    static NumberRange positive() { return {0.0, std::numeric_limits<double>::infinity(), true}; }
    static NumberRange nonNegative() { return {0.0, std::numeric_limits<double>::infinity()}; }
    static NumberRange fraction() { return {0.0, 1.0}; }
    /// [0, 1): a fraction that must stay below one (min_weight: 1 would stop every ray).
    static NumberRange fractionBelowOne() { return {0.0, 1.0, false, true}; }
    static NumberRange open(double lo, double hi) { return {lo, hi, true, true}; }
    static NumberRange closed(double lo, double hi) { return {lo, hi}; }
    bool contains(double v) const;
    /// "> 0", ">= 0", "in [0, 1]", "in (0, 180)"; "any number" when unbounded.
    std::string describe() const;
    bool operator==(const NumberRange&) const = default;
};

/// What an [x, y, z] value must satisfy beyond three finite numbers in its component range.
enum class VectorRule { Any, NonNegative, NonZero, NonZeroComponents };

/// Bounds in messages read "> 0", not "> 0.0".
std::string formatBound(double v);

}  // namespace rs
