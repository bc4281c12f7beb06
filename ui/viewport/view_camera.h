// The camera the viewport looks through: navigation moves it, never the document (Blender's
// model); while it is the scene camera it follows that camera's edits.
#pragma once

#include "scene/document.h"

namespace rs::ui {

/// The viewport's view camera. Through the scene camera (the default on open) it follows the
/// scene camera's edits; navigation and view bookmarks look through a camera of their own
/// until View -> Through Scene Camera or Scene Camera from View makes it the scene's again.
class ViewCamera {
public:
    /// The camera the viewport looks through.
    const Camera& camera() const { return camera_; }
    /// True while the view is the scene camera and follows its edits.
    bool throughScene() const { return throughScene_; }
    /// The world's up an orbit turns about: the scene camera's up when the document opened.
    const Vec3& worldUp() const { return worldUp_; }

    /// A document was opened or reset: the view is its scene camera, whose up is the world's.
    void reset(const Camera& scene);
    /// The scene camera is now `scene` (the property panel, an undo): the view follows it
    /// while it looks through it.
    void sceneEdited(const Camera& scene) {
        if (throughScene_) camera_ = scene;
    }
    /// View -> Through Scene Camera: looks through `scene` and follows its edits again.
    void lookThroughScene(const Camera& scene) {
        camera_ = scene;
        throughScene_ = true;
    }
    /// Navigation or a view bookmark: looks through `camera`, no longer the scene camera.
    void look(const Camera& camera) {
        camera_ = camera;
        throughScene_ = false;
    }
    /// Scene Camera from View: the scene camera takes this view's pose, so the view is the
    /// scene camera again.
    void adoptedByScene() { throughScene_ = true; }

private:
    Camera camera_;
    bool throughScene_ = true;
    Vec3 worldUp_{0.0f, 1.0f, 0.0f};
};

}  // namespace rs::ui
