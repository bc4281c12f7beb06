// Loading scenes for commands and applying the shared render-setting overrides.
#include <cstdio>

#include "arguments.h"
#include "commands.h"

namespace rs::cli {

bool loadSceneOrReport(const std::string& path, SceneDocument& doc, bool* warned) {
    SceneLoadResult result = loadScene(path);
    if (!result.ok()) {
        for (const SceneError& e : result.errors)
            std::fprintf(stderr, "%s\n", e.toString().c_str());
        return false;
    }
    // An image that cannot be read does not stop a render: it shows as the missing pattern.
    for (const SceneError& w : result.warnings)
        std::fprintf(stderr, "%s (warning)\n", w.toString().c_str());
    if (warned) *warned = !result.warnings.empty();
    doc = std::move(result.document);
    return true;
}

void applyRenderOverrides(const Arguments& args, RenderSettings& settings) {
    if (auto v = args.intValue("--width", 1, kMaxImageSide)) settings.width = *v;
    if (auto v = args.intValue("--height", 1, kMaxImageSide)) settings.height = *v;
    if (std::string area = imageSizeError(settings.width, settings.height); !area.empty())
        throw UsageError{area};
    if (auto v = args.intValue("--max-depth", 0, kMaxDepthLimit)) settings.maxDepth = *v;
    if (auto v = args.numberValue("--min-weight")) {
        // The scene file's rule for min_weight, applied to the float that is stored.
        const float weight = static_cast<float>(*v);
        if (!(weight >= 0.0f && weight < 1.0f))
            throw UsageError{"--min-weight must be in [0, 1), got " + *args.value("--min-weight")};
        settings.minWeight = weight;
    }
    if (auto v = args.intValue("--shadow-samples", 0, kMaxSampleCount)) settings.shadowSamples = *v;
    if (auto v = args.intValue("--supersampling", 1, kMaxSampleCount)) settings.supersampling = *v;
}

EngineKind engineOption(const Arguments& args) {
    EngineKind kind = EngineKind::Embree;
    if (auto v = args.value("--engine"); v && !parseEngineKind(*v, kind))
        throw UsageError{"--engine must be embree or builtin, got '" + *v + "'"};
    return kind;
}

}  // namespace rs::cli
