// `raystudio-cli render`: one scene to one image file, with optional JSON stats.
#include "arguments.h"
#include "commands.h"
#include "progress_bar.h"

#include "image/image_io.h"
#include "integrator/cost_estimate.h"
#include "integrator/renderer.h"

#include <cstdio>
#include <tbb/info.h>

namespace rs::cli {

int runRender(int argc, char** argv) {
    OptionSpec spec;
    spec.valued = {"--output",     "--width",          "--height",        "--max-depth",
                   "--min-weight", "--shadow-samples", "--supersampling", "--threads", "--engine"};
    spec.flags = {"--stats", "--force"};
    spec.aliases = {{"-o", "--output"}};
    Arguments args(argc, argv, 2, spec);
    if (args.positional().size() != 1)
        throw UsageError{"expects exactly one scene file (render SCENE -o OUT)"};
    auto output = args.value("--output");
    if (!output || output->empty()) throw UsageError{"missing -o OUT (the image to write)"};
    RenderOptions options;
    options.threads = args.intValue("--threads", 1, 1024).value_or(0);
    options.ids = false;  // only the image is written

    SceneDocument doc;
    if (!loadSceneOrReport(args.positional()[0], doc)) return 2;
    applyRenderOverrides(args, doc.render);
    // Before compiling or allocating anything: a typo'd depth or sample count should cost a
    // message, not an afternoon.
    if (const std::string over = budgetExceeded(estimateCost(doc)); !over.empty() && !args.has("--force")) {
        std::fprintf(stderr, "raystudio-cli render: %s; pass --force to render it anyway\n",
                     over.c_str());
        return 2;
    }

    const CompiledScene scene(doc, nullptr, engineOption(args));
    ProgressBar bar;
    options.progress = [&bar](int done, int total) { bar.update(done, total); };
    RenderResult result = renderImage(scene, options);

    std::string error;
    if (!writeImage(*output, result.image, doc.render.tonemap, doc.render.exposure, error)) {
        std::fprintf(stderr, "raystudio-cli render: %s\n", error.c_str());
        return 2;
    }
    if (args.has("--stats")) {
        const double mrays = result.ms > 0.0 ? double(result.rays) / (result.ms * 1000.0) : 0.0;
        std::printf("{\"ms\": %.3f, \"width\": %d, \"height\": %d, \"rays\": %llu, "
                    "\"mrays_per_s\": %.3f}\n",
                    result.ms, doc.render.width, doc.render.height,
                    static_cast<unsigned long long>(result.rays), mrays);
    }
    return 0;
}

}  // namespace rs::cli
