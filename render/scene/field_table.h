// A table of fields of one struct: each a descriptor bound to the member it reads and writes.
// parameters.cpp builds the scene's tables with it and the interaction policy its own.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scene/parameters.h"

namespace rs::fields {

/// A descriptor plus how to read and write it on a T.
template <class T>
struct Field {
    ParamDescriptor desc;
    std::function<ParamValue(const T&)> get;
    std::function<void(T&, const ParamValue&)> set;
};

/// Starts a descriptor: the attributes every field has.
inline ParamDescriptor describe(const char* key, const char* label, ParamType type,
                                NumberRange range, double softMin, double softMax, double step) {
    ParamDescriptor d;
    d.key = key;
    d.label = label;
    d.type = type;
    d.range = range;
    d.softMin = softMin;
    d.softMax = softMax;
    d.step = step;
    return d;
}

template <class T, class M>
Field<T> bind(ParamDescriptor d, M T::*m) {
    d.defaultValue = ParamValue(T{}.*m);
    return {std::move(d), [m](const T& t) { return ParamValue(t.*m); },
            [m](T& t, const ParamValue& v) { t.*m = std::get<M>(v); }};
}

/// A float in `range`; editors offer [softMin, softMax].
template <class T>
Field<T> number(const char* key, const char* label, float T::*m, NumberRange range, double softMin,
                double softMax, double step) {
    return bind(describe(key, label, ParamType::Float, range, softMin, softMax, step), m);
}

/// An integer in [lo, hi]; editors offer [lo, softHi].
template <class T>
Field<T> integer(const char* key, const char* label, int T::*m, int lo, int hi, int softHi) {
    return bind(describe(key, label, ParamType::Int, NumberRange::closed(lo, hi), lo, softHi, 1),
                m);
}

template <class T>
Field<T> boolean(const char* key, const char* label, bool T::*m) {
    return bind(describe(key, label, ParamType::Bool, NumberRange::closed(0, 1), 0, 1, 1), m);
}

/// [x, y, z] with finite components satisfying `rule`; editors offer [softMin, softMax].
template <class T>
Field<T> vector(const char* key, const char* label, Vec3 T::*m, VectorRule rule = VectorRule::Any,
                double softMin = -1e6, double softMax = 1e6, double step = 0.1) {
    ParamDescriptor d =
        describe(key, label, ParamType::Vec3, NumberRange::any(), softMin, softMax, step);
    d.vectorRule = rule;
    return bind(std::move(d), m);
}

/// An HDR colour: components >= 0, editors offer values up to 100.
template <class T>
Field<T> color(const char* key, const char* label, Vec3 T::*m) {
    ParamDescriptor d =
        describe(key, label, ParamType::Color, NumberRange::nonNegative(), 0.0, 100.0, 0.05);
    d.vectorRule = VectorRule::NonNegative;
    return bind(std::move(d), m);
}

/// One of `names` (the format's spellings), shown as `labels` (empty: the names).
template <class T, class E>
Field<T> choice(const char* key, const char* label, E T::*m, std::vector<std::string> names,
                std::vector<std::string> labels = {}) {
    const double last = double(names.size() - 1);
    ParamDescriptor d =
        describe(key, label, ParamType::Enum, NumberRange::closed(0, last), 0, last, 1);
    d.enumNames = std::move(names);
    d.enumLabels = std::move(labels);
    d.defaultValue = int(T{}.*m);
    return {std::move(d), [m](const T& t) { return ParamValue(int(t.*m)); },
            [m](T& t, const ParamValue& v) { t.*m = E(std::get<int>(v)); }};
}

template <class T>
Field<T> text(const char* key, const char* label, std::string T::*m, ParamType type) {
    return bind(describe(key, label, type, NumberRange::any(), 0, 0, 0), m);
}

/// The field with `change` applied to its descriptor (required, always written, texts).
template <class T, class Change>
Field<T> with(Field<T> f, Change change) {
    change(f.desc);
    return f;
}

template <class T>
std::vector<ParamDescriptor> descriptorsOf(const std::vector<Field<T>>& fields) {
    std::vector<ParamDescriptor> out;
    for (const auto& f : fields) out.push_back(f.desc);
    return out;
}

template <class T>
std::optional<ParamValue> get(const std::vector<Field<T>>& fields, const T& t,
                              const std::string& key) {
    for (const auto& f : fields)
        if (f.desc.key == key) return f.get(t);
    return std::nullopt;
}

template <class T>
std::string set(const std::vector<Field<T>>& fields, T& t, const std::string& key,
                const ParamValue& value) {
    for (const auto& f : fields) {
        if (f.desc.key != key) continue;
        if (std::string e = validateParameter(f.desc, value); !e.empty()) return e;
        f.set(t, value);
        return {};
    }
    return "unknown parameter '" + key + "'";
}

}  // namespace rs::fields
