// Typed, range-checked reading of the keys of one JSON object of a scene file, with errors.
#include "io/scene_entry_reader.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace rs {

std::string describeJson(const Json& j) {
    std::string text = dumpJson(j);
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return text;
}

void SceneErrorSink::add(const std::string& pointer, TextPosition pos, std::string message) {
    SceneError e;
    e.file = fileName_;
    e.pointer = pointer;
    e.line = pos.line;
    e.column = pos.column;
    e.message = std::move(message);
    errors_.push_back(std::move(e));
}

void SceneErrorSink::atValue(const std::string& pointer, std::string message) {
    add(pointer, locator_.valuePosition(pointer), std::move(message));
}

void SceneErrorSink::atKey(const std::string& pointer, std::string message) {
    add(pointer, locator_.keyPosition(pointer), std::move(message));
}

const Json* EntryReader::get(const char* key) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
    auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
}

bool EntryReader::missing(const char* key) {
    sink_.atValue(pointerTo(key), std::string("missing required key \"") + key + "\"");
    return false;
}

bool EntryReader::numberValue(const Json& j, const std::string& pointer, const char* what,
                              double& out) {
    if (!j.is_number()) {
        sink_.atValue(pointer, std::string(what) + " must be a number, got " + describeJson(j));
        return false;
    }
    out = j.get<double>();
    // nlohmann rejects NaN/Inf literals and overflowing doubles, but a double can still be
    // too large for the float the document stores.
    if (!std::isfinite(out) || !std::isfinite(floatFromJson(out))) {
        sink_.atValue(pointer,
                      std::string(what) + " must be a finite number, got " + describeJson(j));
        return false;
    }
    return true;
}

bool EntryReader::numberIn(const Json& j, const std::string& pointer, const char* what,
                           NumberRange range, float& out) {
    double value = 0.0;
    if (!numberValue(j, pointer, what, value)) return false;
    // The range applies to the float that is stored: 1e-50 is > 0 but becomes 0.
    float f = floatFromJson(value);
    if (!range.contains(f)) {
        sink_.atValue(pointer, std::string(what) + " must be " + range.describe() + ", got " +
                                   describeJson(j));
        return false;
    }
    out = f;
    return true;
}

bool EntryReader::number(const char* key, float& out, NumberRange range, Need need) {
    const Json* j = get(key);
    if (!j) return need == Need::Optional || missing(key);
    return numberIn(*j, pointerTo(key), key, range, out);
}

bool EntryReader::integer(const char* key, int& out, int min, int max, Need need) {
    const Json* j = get(key);
    if (!j) return need == Need::Optional || missing(key);
    if (!j->is_number_integer()) {
        sink_.atValue(pointerTo(key),
                      std::string(key) + " must be an integer, got " + describeJson(*j));
        return false;
    }
    // Compare before narrowing: 1e12 must not wrap into range.
    int64_t value = 0;
    if (j->is_number_unsigned())
        value = static_cast<int64_t>(std::min<uint64_t>(j->get<uint64_t>(), INT64_MAX));
    else
        value = j->get<int64_t>();
    if (max == INT_MAX && value > max) {
        sink_.atValue(pointerTo(key), std::string(key) + " " + describeJson(*j) + " is too large");
        return false;
    }
    if (value < min || value > max) {
        std::string expected = ">= " + std::to_string(min);
        if (max != INT_MAX)
            expected = "in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
        sink_.atValue(pointerTo(key),
                      std::string(key) + " must be " + expected + ", got " + describeJson(*j));
        return false;
    }
    out = static_cast<int>(value);
    return true;
}

bool EntryReader::boolean(const char* key, bool& out) {
    const Json* j = get(key);
    if (!j) return true;
    if (!j->is_boolean()) {
        sink_.atValue(pointerTo(key),
                      std::string(key) + " must be true or false, got " + describeJson(*j));
        return false;
    }
    out = j->get<bool>();
    return true;
}

bool EntryReader::string(const char* key, std::string& out, Need need) {
    const Json* j = get(key);
    if (!j) return need == Need::Optional || missing(key);
    if (!j->is_string()) {
        sink_.atValue(pointerTo(key),
                      std::string(key) + " must be a string, got " + describeJson(*j));
        return false;
    }
    out = j->get<std::string>();
    return true;
}

bool EntryReader::vectorIn(const Json& j, const std::string& at, const char* what, VectorRule rule,
                           NumberRange range, Vec3& out) {
    if (!j.is_array() || j.size() != 3) {
        sink_.atValue(at, std::string(what) + " must be an array of 3 numbers [x, y, z], got " +
                              describeJson(j));
        return false;
    }
    Vec3 v;
    for (std::size_t i = 0; i < 3; ++i) {
        double d = 0.0;
        std::string element = appendPointer(at, i);
        if (!numberValue(j[i], element, what, d)) return false;
        v[static_cast<int>(i)] = floatFromJson(d);
        if (rule == VectorRule::NonNegative && v[static_cast<int>(i)] < 0.0f) {
            sink_.atValue(
                element, std::string(what) + " components must be >= 0, got " + describeJson(j[i]));
            return false;
        }
        if (rule == VectorRule::NonZeroComponents && v[static_cast<int>(i)] == 0.0f) {
            sink_.atValue(element, std::string(what) + " components must be non-zero");
            return false;
        }
        if (!range.contains(v[static_cast<int>(i)])) {
            sink_.atValue(element, std::string(what) + " components must be " + range.describe() +
                                       ", got " + describeJson(j[i]));
            return false;
        }
    }
    if (rule == VectorRule::NonZero && v == Vec3(0.0f)) {
        sink_.atValue(at, std::string(what) + " must be a non-zero vector");
        return false;
    }
    out = v;
    return true;
}

bool EntryReader::vector(const char* key, Vec3& out, VectorRule rule, Need need) {
    const Json* j = get(key);
    if (!j) return need == Need::Optional || missing(key);
    return vectorIn(*j, pointerTo(key), key, rule, NumberRange::any(), out);
}

EntryReader::Read EntryReader::element(const ParamDescriptor& d, const char* key, std::size_t index,
                                       std::size_t count, const char* shape, ParamValue& out) {
    const Json* j = get(key);
    if (!j) return d.required ? (missing(key), Read::Invalid) : Read::Absent;
    if (!j->is_array() || j->size() != count) {
        if (index == 0)
            sink_.atValue(pointerTo(key), std::string(key) + " must be an array of " + shape +
                                              ", got " + describeJson(*j));
        return Read::Invalid;
    }
    const std::string at = appendPointer(pointerTo(key), index);
    const std::string what = std::string(key) + "/" + std::to_string(index);
    if (d.type == ParamType::Float) {
        float f = 0.0f;
        if (!numberIn((*j)[index], at, what.c_str(), d.range, f)) return Read::Invalid;
        out = f;
        return Read::Ok;
    }
    Vec3 v(0.0f);
    if (!vectorIn((*j)[index], at, what.c_str(), d.vectorRule, d.range, v)) return Read::Invalid;
    out = v;
    return Read::Ok;
}

EntryReader::Read EntryReader::parameter(const ParamDescriptor& d, ParamValue& out) {
    const char* key = d.key.c_str();
    const Json* j = get(key);
    if (!j) return d.required ? (missing(key), Read::Invalid) : Read::Absent;
    bool ok = false;
    switch (d.type) {
        case ParamType::Float: {
            float f = 0.0f;
            if ((ok = number(key, f, d.range))) out = f;
            break;
        }
        case ParamType::Int: {
            int i = 0;
            if ((ok = integer(key, i, int(d.range.min), int(d.range.max)))) out = i;
            break;
        }
        case ParamType::Bool: {
            bool b = false;
            if ((ok = boolean(key, b))) out = b;
            break;
        }
        case ParamType::Vec3:
        case ParamType::Color: {
            Vec3 v(0.0f);
            if ((ok = vector(key, v, d.vectorRule))) out = v;
            break;
        }
        case ParamType::Enum: {
            std::string text;
            if (!string(key, text)) break;
            const auto& names = d.enumNames;
            const auto found = std::find(names.begin(), names.end(), text);
            if (found != names.end()) {
                out = int(found - names.begin());
                ok = true;
                break;
            }
            std::string expected;
            for (const auto& n : names) expected += (expected.empty() ? "\"" : ", \"") + n + '"';
            sink_.atValue(pointerTo(key),
                          d.key + " must be one of " + expected + ", got \"" + text + "\"");
            break;
        }
        case ParamType::Text:
        case ParamType::File: {
            std::string text;
            if ((ok = string(key, text))) out = text;
            break;
        }
    }
    return ok ? Read::Ok : Read::Invalid;
}

bool EntryReader::name(std::string& out) {
    std::string text;
    if (!string("name", text, Need::Required)) return false;
    if (text.empty()) {
        sink_.atValue(pointerTo("name"), "name must not be empty");
        return false;
    }
    out = text;
    return true;
}

void EntryReader::forbid(const char* key, const std::string& why) {
    if (has(key)) sink_.atKey(pointerTo(key), why);
}

Extras EntryReader::finish() {
    Extras extras;
    for (auto it = object_.begin(); it != object_.end(); ++it) {
        const std::string& key = it.key();
        if (key.rfind("x-", 0) == 0) {
            extras.emplace_back(key, dumpJson(it.value()));
        } else if (std::find(known_.begin(), known_.end(), key) == known_.end()) {
            sink_.atKey(pointerTo(key), "unknown key \"" + key + "\"");
        }
    }
    return extras;
}

}  // namespace rs
