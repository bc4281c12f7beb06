// Orbit, pan, dolly and frame-selection on the document camera.
#pragma once

#include "scene/document.h"

namespace rs::ui {

/// Orbits the position around the target by yaw/pitch in degrees.
void orbit(Camera& camera, float yawDeg, float pitchDeg);
/// Moves position and target together by fractions of the view height (right, up).
void pan(Camera& camera, float dx, float dy);
/// Moves the position towards the target by `factor` of the distance (negative: away).
void dolly(Camera& camera, float factor);
/// Aims at `center` and backs off so a sphere of `radius` fills the view.
void frame(Camera& camera, const Vec3& center, float radius);

}  // namespace rs::ui
