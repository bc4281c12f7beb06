// A document rendered to an image file: the command line's render and the designer's render
// queue both write their images through it.
#pragma once

#include <string>

#include "accel/ray_engine.h"
#include "integrator/renderer.h"
#include "scene/document.h"

namespace rs {

/// Renders `doc` at its render settings on `engine` with `options` (whole image, no ids) and
/// writes the image to `path` with writeImage (the format follows the extension; 8-bit
/// formats tone-mapped with the document's operator and exposure). True when written.
/// False with `error` naming the problem when the image size is invalid or the file cannot
/// be written; false with `error` empty when the render was cancelled (options.cancel set,
/// even after the last tile): nothing is written then. `result`, when given, gets the
/// render's image and statistics. Throws what compiling the scene or rendering throws.
bool renderToFile(const SceneDocument& doc, EngineKind engine, const std::string& path,
                  RenderOptions options, std::string& error, RenderResult* result = nullptr);

}  // namespace rs
