// What the session may turn down while the user drags, one setting per technique of the thesis.
#pragma once

#include <string>

#include "integrator/whitted.h"
#include "scene/document.h"
#include "scene/parameters.h"

namespace rs {

/// Resolution of interactive frames (undersampling, thesis 3.2).
enum class MovingResolution { Full, Half, Quarter };
/// Refraction while moving (thesis 4.2).
enum class RefractionMode { Full, Diffuse, DiffuseExceptSelected };
/// Reflection while moving (thesis 4.2).
enum class ReflectionMode { Full, Diffuse };
/// Shadows while moving (thesis 3.3, 4.2). Deferred keeps shading records and adds the
/// shadows after release without re-tracing camera or secondary rays.
enum class MovingShadows { Full, HardOnly, Off, Deferred };

/// The interaction policy set. Defaults keep the viewport exact except where the thesis shows
/// a cheap, reversible trade; everything is refined to full quality after release.
struct InteractionPolicy {
    MovingResolution resolution = MovingResolution::Full;
    bool interleaved = false;  ///< 2-pass interleaved: alternate pixels each frame.
    bool boxProxy = false;     ///< Trace the moving object as its bounding box.
    RefractionMode refraction = RefractionMode::Full;
    ReflectionMode reflection = ReflectionMode::Full;
    int maxDepthWhileMoving = -1;  ///< -1: the scene's max_depth.
    MovingShadows shadows = MovingShadows::Deferred;
    bool supersampleWhileMoving = false;
    bool dirtyRegions = true;  ///< Re-trace only what an edit can change.
    /// While the user drags or orbits, a governed pass runs to its end before the next edit
    /// (unless it is long over its time) and the display shows only whole frames, never a
    /// picture of two edits; off, every move cuts the pass and each tile shows as it comes.
    bool wholeFramesWhileMoving = true;
    /// > 0: per frame, the least-reduced policy level predicted to meet this frame time
    /// (0: always exactly the settings above). The default is the frame time of a 30 Hz
    /// refresh (Preferences asks for frames per second): more than a display of 30-60 Hz
    /// shows buys nothing, and quality drops only when the change is too large for it.
    double governorTargetMs = kDefaultGovernorTargetMs;
    /// 1000 ms / 30 frames.
    static constexpr double kDefaultGovernorTargetMs = 1000.0 / 30.0;

    bool operator==(const InteractionPolicy&) const = default;

    /// The policy with every technique off: interactive frames at full quality, full frame.
    static InteractionPolicy none();
    /// Pixel step of interactive frames (1, 2 or 4).
    int pixelStep() const;
    /// Trace options for interactive frames, given the scene's settings and the moving object.
    TraceOptions movingTraceOptions(const RenderSettings& settings, ObjectId moving) const;
};

/// The descriptors of the policy's settings, in the order Preferences shows them: the one
/// place their JSON keys, labels, ranges and defaults are written (the governor's target,
/// a time in milliseconds that Preferences offers as frames per second, stands apart).
const std::vector<ParamDescriptor>& policyParameters();
/// The value of a policy setting by key, or nullopt.
std::optional<ParamValue> getPolicyParameter(const InteractionPolicy& p, const std::string& key);
/// Validates and assigns a policy setting; empty on success, else the reason.
std::string setPolicyParameter(InteractionPolicy& p, const std::string& key,
                               const ParamValue& value);

/// JSON text of a policy (Preferences and `raystudio-cli drag --policy FILE` use it).
std::string policyToJson(const InteractionPolicy& policy);
/// Parses policy JSON; unknown keys and bad values are errors naming the key. Absent keys
/// keep their defaults.
bool policyFromJson(const std::string& text, InteractionPolicy& policy, std::string& error);

}  // namespace rs
