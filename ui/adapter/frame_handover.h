// Handing the session's deep frame to the display (display/display_frame.h): the adapter's,
// so that the display reads no session header.
#pragma once

#include <QRect>
#include <vector>

#include "display/display_frame.h"

namespace rs {
class RenderSession;
class DeepFrame;
}  // namespace rs

namespace rs::ui {

/// Copies the session's current frame (the whole frame under its lock: tests compare with
/// it). Tone map and exposure are the snapshot's, which edits that trace nothing may keep.
DisplayFrame wholeFrame(const RenderSession& session);

/// Copies `rects` of `f` into `d` (all of it when the sizes differ, or normals and costs are
/// wanted and missing) and records them as damage of a new serial; `flags` (1 byte a pixel,
/// changed by edits outside any tile) is copied whole when `allFlags`. Call with the frame
/// lock held.
void refreshFrame(DisplayFrame& d, const DeepFrame& f, const std::vector<QRect>& rects,
                  bool allFlags);

}  // namespace rs::ui
