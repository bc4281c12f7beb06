// The tone map and exposure of the document posted last. They trace nothing, so no tile
// carries them to the display: the adapter puts them on the displayed frame itself.
#pragma once

#include "display/display_frame.h"
#include "scene/document.h"

namespace rs::ui {

/// How the display maps the frame's radiance to the screen, as the document posted last says.
class PostedLook {
public:
    /// Takes `render`'s tone map and exposure; true when they differ from those taken last
    /// (the display must repaint: no tile will announce them).
    bool post(const RenderSettings& render);
    /// Puts them on `d`, as a new serial when they change it.
    void applyTo(DisplayFrame& d) const;

private:
    ToneMap tonemap_ = ToneMap::Clamp;
    float exposure_ = 0.0f;
};

}  // namespace rs::ui
