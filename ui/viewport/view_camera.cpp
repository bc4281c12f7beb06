// ViewCamera: the viewport's own camera and whether it is the scene camera.
#include "viewport/view_camera.h"

namespace rs::ui {

void ViewCamera::reset(const Camera& scene) {
    camera_ = scene;
    throughScene_ = true;
    const float len = glm::length(camera_.up);
    worldUp_ = len > 1e-6f ? camera_.up / len : Vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace rs::ui
