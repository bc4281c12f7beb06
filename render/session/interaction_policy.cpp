// Interaction policy: trace options while moving, and its JSON form.
#include "session/interaction_policy.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "scene/field_table.h"

namespace rs {

namespace {

using fields::Field;
using P = InteractionPolicy;

template <class T>
Field<T> explained(Field<T> f, const char* toolTip) {
    f.desc.toolTip = toolTip;
    return f;
}

const std::vector<Field<P>>& policyFields() {
    static const std::vector<Field<P>> f{
        fields::choice("resolution", "Resolution while moving", &P::resolution,
                       {"full", "half", "quarter"}, {"Full", "Half", "Quarter"}),
        explained(fields::boolean("interleaved", "Interleaving", &P::interleaved),
                  "2-pass interleaved frames: each frame traces every other pixel"),
        explained(fields::boolean("box_proxy", "Box proxy", &P::boxProxy),
                  "Trace the moving object as its bounding box"),
        fields::choice("refraction", "Refraction while moving", &P::refraction,
                       {"full", "diffuse", "diffuse_except_selected"},
                       {"Full", "Diffuse", "Diffuse except selected"}),
        fields::choice("reflection", "Reflection while moving", &P::reflection, {"full", "diffuse"},
                       {"Full", "Diffuse"}),
        fields::with(fields::integer("max_depth_while_moving", "Depth while moving",
                                     &P::maxDepthWhileMoving, -1, kMaxDepthLimit, 64),
                     [](ParamDescriptor& d) {
                         d.specialValueText = "Scene's max depth";
                         d.toolTip = "-1: the scene's max_depth";
                     }),
        fields::choice("shadows", "Shadows while moving", &P::shadows,
                       {"full", "hard_only", "off", "deferred"},
                       {"Full", "Hard only", "Off", "Deferred (added after release)"}),
        explained(fields::boolean("supersample_while_moving", "Supersampling",
                                  &P::supersampleWhileMoving),
                  "Supersample while moving"),
        explained(fields::boolean("dirty_regions", "Dirty regions", &P::dirtyRegions),
                  "Re-trace only what an edit can change"),
        explained(
            fields::boolean("whole_frames_while_moving", "Whole frames",
                            &P::wholeFramesWhileMoving),
            "Each pass runs to its end and the view keeps the last complete picture until the "
            "next one is done. Off: every mouse move restarts the pass and tiles show as they "
            "come, fresher but mixed from several moves.")};
    return f;
}

constexpr const char* kGovernorKey = "governor_target_ms";

/// A JSON value as the descriptor's type, or the reason it is not one.
std::string fromJson(const ParamDescriptor& d, const nlohmann::json& j, ParamValue& out) {
    const std::string at = "policy key '" + d.key + "'";
    switch (d.type) {
        case ParamType::Bool:
            if (!j.is_boolean()) return at + " must be true or false";
            out = j.get<bool>();
            return {};
        case ParamType::Int:
            if (!j.is_number_integer() || !d.range.contains(double(j.get<long long>())))
                return at + " must be an integer " + d.range.describe();
            out = int(j.get<long long>());
            return {};
        case ParamType::Enum: {
            if (!j.is_string()) return at + " must be a string";
            const auto& names = d.enumNames;
            const auto found = std::find(names.begin(), names.end(), j.get<std::string>());
            if (found != names.end()) {
                out = int(found - names.begin());
                return {};
            }
            std::string e = at + " has unknown value '" + j.get<std::string>() + "' (one of:";
            for (const auto& n : names) e += " " + n;
            return e + ")";
        }
        default:
            return at + " has a type policies do not use";
    }
}

nlohmann::ordered_json toJson(const ParamDescriptor& d, const ParamValue& v) {
    switch (d.type) {
        case ParamType::Bool:
            return std::get<bool>(v);
        case ParamType::Int:
            return std::get<int>(v);
        case ParamType::Enum:
            return d.enumNames.at(std::size_t(std::get<int>(v)));
        default:
            return nullptr;
    }
}

}  // namespace

InteractionPolicy InteractionPolicy::none() {
    InteractionPolicy p;
    p.shadows = MovingShadows::Full;
    p.dirtyRegions = false;
    p.supersampleWhileMoving = true;
    p.governorTargetMs = 0.0;
    return p;
}

int InteractionPolicy::pixelStep() const {
    switch (resolution) {
        case MovingResolution::Half:
            return 2;
        case MovingResolution::Quarter:
            return 4;
        default:
            return 1;
    }
}

TraceOptions InteractionPolicy::movingTraceOptions(const RenderSettings& settings,
                                                   ObjectId moving) const {
    TraceOptions o = TraceOptions::fromSettings(settings);
    if (maxDepthWhileMoving >= 0) o.maxDepth = std::min(o.maxDepth, maxDepthWhileMoving);
    o.reflectionAsDiffuse = reflection == ReflectionMode::Diffuse;
    o.refractionAsDiffuse = refraction != RefractionMode::Full;
    if (refraction == RefractionMode::DiffuseExceptSelected) o.refractionExempt = moving;
    switch (shadows) {
        case MovingShadows::Full:
            o.shadows = ShadowQuality::Full;
            break;
        case MovingShadows::HardOnly:
            o.shadows = ShadowQuality::HardOnly;
            break;
        case MovingShadows::Off:
            o.shadows = ShadowQuality::Off;
            break;
        case MovingShadows::Deferred:
            o.shadows = ShadowQuality::Deferred;
            break;
    }
    return o;
}

const std::vector<ParamDescriptor>& policyParameters() {
    static const std::vector<ParamDescriptor> d = fields::descriptorsOf(policyFields());
    return d;
}

std::optional<ParamValue> getPolicyParameter(const InteractionPolicy& p, const std::string& key) {
    return fields::get(policyFields(), p, key);
}

std::string setPolicyParameter(InteractionPolicy& p, const std::string& key,
                               const ParamValue& value) {
    return fields::set(policyFields(), p, key, value);
}

std::string policyToJson(const InteractionPolicy& p) {
    nlohmann::ordered_json j;
    for (const auto& f : policyFields()) j[f.desc.key] = toJson(f.desc, f.get(p));
    j[kGovernorKey] = p.governorTargetMs;
    return j.dump(2);
}

bool policyFromJson(const std::string& text, InteractionPolicy& out, std::string& error) {
    nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        error = "policy must be a JSON object";
        return false;
    }
    InteractionPolicy p = out;
    for (const auto& item : j.items()) {
        const std::string& key = item.key();
        const nlohmann::json& value = item.value();
        if (key == kGovernorKey) {
            if (!value.is_number() || !(value.get<double>() >= 0.0)) {
                error = std::string("policy key '") + kGovernorKey + "' must be a number >= 0";
                return false;
            }
            p.governorTargetMs = value.get<double>();
            continue;
        }
        const auto& all = policyFields();
        const auto field =
            std::find_if(all.begin(), all.end(), [&](const auto& f) { return f.desc.key == key; });
        if (field == all.end()) {
            error = "unknown policy key '" + key + "'";
            return false;
        }
        ParamValue v;
        if (std::string e = fromJson(field->desc, value, v); !e.empty()) {
            error = e;
            return false;
        }
        field->set(p, v);
    }
    out = p;
    return true;
}

}  // namespace rs
