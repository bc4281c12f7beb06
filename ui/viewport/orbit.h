// One orbit of the view about a pivot (right or Alt+left drag), kept clear of the walls.
#pragma once

#include <QPoint>
#include <functional>

#include "scene/document.h"

namespace rs::ui {

/// A running orbit. It turns a camera of its own, unclipped, so the view comes back out to
/// its distance once the way is clear; what is shown stops short of the first surface between
/// the pivot and the camera (orbiting about a far wall would swing out through the side walls
/// of the room).
class Orbit {
public:
    /// How far from `from` along unit `dir` the view may stand, passing through `ignore`.
    using Room = std::function<float(const Vec3& from, const Vec3& dir, ObjectId ignore)>;

    /// Orbits `start` about `pivot`, which lies in or on `ignore` (kNoObject: none).
    Orbit(const Camera& start, const Vec3& pivot, ObjectId ignore)
        : pivot_(pivot), free_(start), ignore_(ignore) {}

    const Vec3& pivot() const { return pivot_; }
    /// The view after the mouse moved `delta` pixels, turning about `worldUp`, drawn in to
    /// the `room` it has.
    Camera turn(const QPoint& delta, const Vec3& worldUp, const Room& room);

private:
    Vec3 pivot_;
    Camera free_;      ///< The orbit's camera before clipping.
    ObjectId ignore_;  ///< The entity the pivot lies in or on.
};

}  // namespace rs::ui
