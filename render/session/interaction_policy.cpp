// Interaction policy: trace options while moving, and its JSON form.
#include "session/interaction_policy.h"

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>

namespace rs {

namespace {

template <class E, std::size_t N>
using Names = std::array<std::pair<E, const char*>, N>;

constexpr Names<MovingResolution, 3> kResolutions{{{MovingResolution::Full, "full"},
                                                   {MovingResolution::Half, "half"},
                                                   {MovingResolution::Quarter, "quarter"}}};
constexpr Names<RefractionMode, 3> kRefractions{
    {{RefractionMode::Full, "full"},
     {RefractionMode::Diffuse, "diffuse"},
     {RefractionMode::DiffuseExceptSelected, "diffuse_except_selected"}}};
constexpr Names<ReflectionMode, 2> kReflections{
    {{ReflectionMode::Full, "full"}, {ReflectionMode::Diffuse, "diffuse"}}};
constexpr Names<MovingShadows, 4> kShadows{{{MovingShadows::Full, "full"},
                                            {MovingShadows::HardOnly, "hard_only"},
                                            {MovingShadows::Off, "off"},
                                            {MovingShadows::Deferred, "deferred"}}};

template <class E, std::size_t N>
const char* nameOf(const Names<E, N>& names, E value) {
    for (const auto& [e, n] : names)
        if (e == value) return n;
    return names[0].second;
}

template <class E, std::size_t N>
bool parseEnum(const nlohmann::json& j, const char* key, const Names<E, N>& names, E& out,
               std::string& error) {
    if (!j.is_string()) {
        error = std::string("policy key '") + key + "' must be a string";
        return false;
    }
    for (const auto& [e, n] : names) {
        if (j.get<std::string>() == n) {
            out = e;
            return true;
        }
    }
    error = std::string("policy key '") + key + "' has unknown value '" + j.get<std::string>() +
            "' (one of:";
    for (const auto& [e, n] : names) error += std::string(" ") + n;
    error += ")";
    return false;
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

std::string policyToJson(const InteractionPolicy& p) {
    nlohmann::ordered_json j;
    j["resolution"] = nameOf(kResolutions, p.resolution);
    j["interleaved"] = p.interleaved;
    j["box_proxy"] = p.boxProxy;
    j["refraction"] = nameOf(kRefractions, p.refraction);
    j["reflection"] = nameOf(kReflections, p.reflection);
    j["max_depth_while_moving"] = p.maxDepthWhileMoving;
    j["shadows"] = nameOf(kShadows, p.shadows);
    j["supersample_while_moving"] = p.supersampleWhileMoving;
    j["dirty_regions"] = p.dirtyRegions;
    j["whole_frames_while_moving"] = p.wholeFramesWhileMoving;
    j["governor_target_ms"] = p.governorTargetMs;
    return j.dump(2);
}

bool policyFromJson(const std::string& text, InteractionPolicy& out, std::string& error) {
    nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        error = "policy must be a JSON object";
        return false;
    }
    InteractionPolicy p = out;
    // Not a structured binding: clang before 16 refuses to capture one in needBool below.
    for (const auto& item : j.items()) {
        const std::string& key = item.key();
        const nlohmann::json& value = item.value();
        auto needBool = [&](bool& field) {
            if (!value.is_boolean()) {
                error = "policy key '" + key + "' must be true or false";
                return false;
            }
            field = value.get<bool>();
            return true;
        };
        bool ok = true;
        if (key == "resolution")
            ok = parseEnum(value, "resolution", kResolutions, p.resolution, error);
        else if (key == "interleaved")
            ok = needBool(p.interleaved);
        else if (key == "box_proxy")
            ok = needBool(p.boxProxy);
        else if (key == "refraction")
            ok = parseEnum(value, "refraction", kRefractions, p.refraction, error);
        else if (key == "reflection")
            ok = parseEnum(value, "reflection", kReflections, p.reflection, error);
        else if (key == "shadows")
            ok = parseEnum(value, "shadows", kShadows, p.shadows, error);
        else if (key == "supersample_while_moving")
            ok = needBool(p.supersampleWhileMoving);
        else if (key == "dirty_regions")
            ok = needBool(p.dirtyRegions);
        else if (key == "whole_frames_while_moving")
            ok = needBool(p.wholeFramesWhileMoving);
        else if (key == "max_depth_while_moving") {
            if (!value.is_number_integer() || value.get<int>() < -1) {
                error = "policy key 'max_depth_while_moving' must be an integer >= -1";
                return false;
            }
            p.maxDepthWhileMoving = value.get<int>();
        } else if (key == "governor_target_ms") {
            if (!value.is_number() || value.get<double>() < 0.0) {
                error = "policy key 'governor_target_ms' must be a number >= 0";
                return false;
            }
            p.governorTargetMs = value.get<double>();
        } else {
            error = "unknown policy key '" + key + "'";
            return false;
        }
        if (!ok) return false;
    }
    out = p;
    return true;
}

}  // namespace rs
