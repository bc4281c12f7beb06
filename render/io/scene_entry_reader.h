// Typed, range-checked reading of the keys of one JSON object of a scene file, with errors.
#pragma once

#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/math.h"
#include "io/json_location.h"
#include "io/scene_io.h"
#include "io/scene_json.h"
#include "scene/parameters.h"
#include "scene/value_range.h"

namespace rs {

/// Collects the errors of one scene text, placing each by JSON pointer and line/column.
class SceneErrorSink {
public:
    SceneErrorSink(std::string fileName, const JsonLocator& locator,
                   std::vector<SceneError>& errors)
        : fileName_(std::move(fileName)), locator_(locator), errors_(errors) {}

    /// An error about the value at `pointer` (a missing key: placed at its enclosing object).
    void atValue(const std::string& pointer, std::string message);
    /// An error about a member's key itself (unknown or repeated keys).
    void atKey(const std::string& pointer, std::string message);
    /// An error at a position the caller knows better than the pointer does.
    void at(const std::string& pointer, TextPosition position, std::string message) {
        add(pointer, position, std::move(message));
    }
    /// Errors so far, to tell whether a step added any.
    std::size_t count() const { return errors_.size(); }

private:
    void add(const std::string& pointer, TextPosition pos, std::string message);

    std::string fileName_;
    const JsonLocator& locator_;
    std::vector<SceneError>& errors_;
};

enum class Need { Optional, Required };

/// Reads the members of one JSON object. Remembers which keys were asked about so that
/// finish() can report the rest as unknown (a typo must not silently lose a setting).
/// Accessors report their own errors and return false; `out` is left alone on error or
/// when an optional key is absent, so defaults come from the document model.
class EntryReader {
public:
    EntryReader(SceneErrorSink& sink, const Json& object, std::string pointer)
        : sink_(sink), object_(object), pointer_(std::move(pointer)) {}

    const std::string& pointer() const { return pointer_; }
    std::string pointerTo(std::string_view key) const { return appendPointer(pointer_, key); }
    SceneErrorSink& sink() { return sink_; }
    /// The member `key`, marked as known; nullptr when absent.
    const Json* get(const char* key);
    /// True when `key` is present (and marks it known).
    bool has(const char* key) { return get(key) != nullptr; }
    /// True when no accessor of this reader has reported an error.
    bool ok() const { return sink_.count() == errorsAtStart_; }

    bool number(const char* key, float& out, NumberRange range, Need need = Need::Optional);
    bool integer(const char* key, int& out, int min, int max, Need need = Need::Optional);
    bool boolean(const char* key, bool& out);
    bool string(const char* key, std::string& out, Need need = Need::Optional);
    bool vector(const char* key, Vec3& out, VectorRule rule, Need need = Need::Optional);
    /// What reading one described field gave.
    enum class Read { Absent, Ok, Invalid };
    /// Reads the field `d` describes (scene/parameters.h): its type, range and vector rule,
    /// required or not; an enum by its spellings. `out` is set only when Ok.
    Read parameter(const ParamDescriptor& d, ParamValue& out);
    /// Reads element `index` of `key`, an array of `count` values each of the type `d`
    /// describes (Float, Vec3 or Color), checked against `d` and reported at
    /// `/key/index` under the name `key`. `shape` names the array in the error when
    /// `key` is not such an array ("2 colours [r, g, b]"); that error is reported once.
    Read element(const ParamDescriptor& d, const char* key, std::size_t index, std::size_t count,
                 const char* shape, ParamValue& out);
    /// The required, non-empty `name`.
    bool name(std::string& out);

    /// A string from a closed set of spellings.
    template <class E>
    bool enumeration(const char* key, E& out,
                     std::initializer_list<std::pair<const char*, E>> choices,
                     Need need = Need::Optional) {
        std::string text;
        const Json* j = get(key);
        if (!j) return need == Need::Optional || missing(key);
        if (!string(key, text)) return false;
        for (const auto& [spelling, value] : choices) {
            if (text == spelling) {
                out = value;
                return true;
            }
        }
        std::string expected;
        for (const auto& c : choices)
            expected += std::string(expected.empty() ? "\"" : ", \"") + c.first + '"';
        sink_.atValue(pointerTo(key),
                      std::string(key) + " must be one of " + expected + ", got \"" + text + "\"");
        return false;
    }

    /// Reports `key`, when present, as not allowed here, saying why.
    void forbid(const char* key, const std::string& why);
    /// Reports every key not asked about, except `x-` keys; returns those in file order.
    Extras finish();
    /// Reports the required `key` as missing; returns false.
    bool missing(const char* key);

private:
    bool numberIn(const Json& j, const std::string& pointer, const char* what, NumberRange range,
                  float& out);
    bool vectorIn(const Json& j, const std::string& pointer, const char* what, VectorRule rule,
                  NumberRange range, Vec3& out);
    bool numberValue(const Json& j, const std::string& pointer, const char* what, double& out);

    SceneErrorSink& sink_;
    const Json& object_;
    std::string pointer_;
    std::vector<std::string> known_;
    std::size_t errorsAtStart_ = sink_.count();
};

/// A JSON value as shown in messages, shortened when long.
std::string describeJson(const Json& j);

}  // namespace rs
