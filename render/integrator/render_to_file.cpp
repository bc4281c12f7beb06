// Render, then write: one image file from one document.
#include "integrator/render_to_file.h"

#include <utility>

#include "image/image_io.h"
#include "snapshot/compiled_scene.h"

namespace rs {

bool renderToFile(const SceneDocument& doc, EngineKind engine, const std::string& path,
                  RenderOptions options, std::string& error, RenderResult* result) {
    error = imageSizeError(doc.render.width, doc.render.height);
    if (!error.empty()) return false;
    options.ids = false;  // Only the image is written.
    options.firstRow = 0;
    options.endRow = -1;
    const CompiledScene scene(doc, nullptr, engine);
    RenderResult rendered = renderImage(scene, options);
    // Checked once more so a cancel that lands after the last tile writes nothing.
    const bool cancelled = rendered.cancelled || (options.cancel && *options.cancel);
    const bool written = !cancelled && writeImage(path, rendered.image, doc.render.tonemap,
                                                  doc.render.exposure, error);
    if (result) *result = std::move(rendered);
    return written;
}

}  // namespace rs
