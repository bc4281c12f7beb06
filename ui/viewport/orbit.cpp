// Orbit: the turntable orbit's own camera, clipped to the first surface behind the view.
#include "viewport/orbit.h"

#include "viewport/camera_navigation.h"

namespace rs::ui {

Camera Orbit::turn(const QPoint& delta, const Vec3& worldUp, const Room& room) {
    orbitAround(free_, pivot_, worldUp, delta.x() * 0.4f, delta.y() * 0.4f);
    Camera c = free_;
    const Vec3 out = c.position - pivot_;
    const float dist = glm::length(out);
    if (dist > 1e-6f) {
        const float free = room(pivot_, out / dist, ignore_);
        if (free < dist) {
            const Vec3 in = out * (free / dist - 1.0f);
            c.position += in;
            c.target += in;
        }
    }
    return c;
}

}  // namespace rs::ui
