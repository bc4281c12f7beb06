// Orbit, pan, dolly, frame and axis views on a camera (the viewport's view camera).
#pragma once

#include <limits>

#include "scene/document.h"

namespace rs::ui {

/// Turntable orbit of the whole camera (position, target, up) about `pivot`: yaw about
/// `worldUp`, pitch about the view's right axis, never tipping the view upside down.
void orbitAround(Camera& camera, const Vec3& pivot, const Vec3& worldUp, float yawDeg,
                 float pitchDeg);
/// Moves position and target together by fractions of the view height (right, up).
void pan(Camera& camera, float dx, float dy);
/// Moves the position towards the target by `factor` of the distance (negative: away).
void dolly(Camera& camera, float factor);
/// Aims at `center` from the current side and backs off so a sphere of `radius` fills the
/// view, but no further than `maxDistance` from the centre.
void frame(Camera& camera, const Vec3& center, float radius,
           float maxDistance = std::numeric_limits<float>::infinity());
/// Looks along `viewDir` with `up` at the current target from the current distance
/// (Blender's numpad views).
void alignView(Camera& camera, const Vec3& viewDir, const Vec3& up);

}  // namespace rs::ui
