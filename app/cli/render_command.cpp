// `raystudio-cli render`: one scene to one image file (or one part of it), with optional JSON
// stats.
#include <tbb/info.h>

#include <cctype>
#include <cstdio>
#include <filesystem>

#include "arguments.h"
#include "commands.h"
#include "image/image_part.h"
#include "image/part_file.h"
#include "integrator/cost_estimate.h"
#include "integrator/render_to_file.h"
#include "integrator/renderer.h"
#include "io/render_fingerprint.h"
#include "progress_bar.h"

namespace rs::cli {

namespace {

bool exrPath(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".exr";
}

/// What part `part` of `doc`'s image says about itself in its file.
PartHeader partHeader(const SceneDocument& doc, EngineKind engine, const ImagePart& part) {
    PartHeader header;
    header.part = part;
    header.fullWidth = doc.render.width;
    header.fullHeight = doc.render.height;
    header.rows = partRows(part, doc.render.height);
    header.fingerprint = renderFingerprint(doc, engine);
    header.tonemap = doc.render.tonemap;
    header.exposure = doc.render.exposure;
    return header;
}

/// "--view close: scene.json has no view named that (its views: "a", "b")".
std::string noSuchView(const SceneDocument& doc, const std::string& scene,
                       const std::string& view) {
    std::string out = "--view " + view + ": " + scene + " has no view named that";
    if (doc.views.empty()) return out + " (it has no views)";
    out += " (its views: ";
    for (std::size_t i = 0; i < doc.views.size(); ++i)
        out.append(i ? ", \"" : "\"").append(doc.views[i].name) += '"';
    return out + ")";
}

}  // namespace

int runRender(int argc, char** argv) {
    OptionSpec spec;
    spec.valued = {"--output",        "--width",      "--height",
                   "--max-depth",     "--min-weight", "--shadow-samples",
                   "--supersampling", "--threads",    "--engine"};
    spec.valued.insert("--tile");
    spec.valued.insert("--view");
    spec.flags = {"--stats", "--force", "--ids"};
    spec.aliases = {{"-o", "--output"}};
    Arguments args(argc, argv, 2, spec);
    if (args.positional().size() != 1)
        throw UsageError{"expects exactly one scene file (render SCENE -o OUT)"};
    auto output = args.value("--output");
    if (!output || output->empty()) throw UsageError{"missing -o OUT (the image to write)"};
    RenderOptions options;
    options.threads = args.intValue("--threads", 1, 1024).value_or(0);
    options.ids = false;  // only the image is written

    if (args.has("--ids") && !args.has("--tile"))
        throw UsageError{"--ids is for parts (render --tile I/N --ids -o PART.exr)"};
    ImagePart part;
    if (auto tile = args.value("--tile")) {
        std::string error;
        if (!parseImagePart(*tile, part, error)) throw UsageError{"--tile " + error};
        if (!exrPath(*output))
            throw UsageError{"a part is written as linear EXR: -o must name a .exr file, got '" +
                             *output + "'"};
    }

    SceneDocument doc;
    if (!loadSceneOrReport(args.positional()[0], doc)) return 2;
    if (auto view = args.value("--view")) {
        const ViewBookmark* named = doc.findView(*view);
        if (!named) throw UsageError{noSuchView(doc, args.positional()[0], *view)};
        doc.camera = named->camera;
    }
    applyRenderOverrides(args, doc.render);
    if (args.has("--tile")) {
        if (const std::string bad = partError(part, doc.render.height); !bad.empty())
            throw UsageError{"--tile " + bad};
        const RowRange rows = partRows(part, doc.render.height);
        options.firstRow = rows.begin;
        options.endRow = rows.end;
        options.ids = args.has("--ids");
    }
    // Before compiling or allocating anything: a typo'd depth or sample count should cost a
    // message, not an afternoon. A part is held to its own share of the work.
    SceneDocument costed = doc;
    if (options.endRow >= 0) costed.render.height = options.endRow - options.firstRow;
    if (const std::string over = budgetExceeded(estimateCost(costed));
        !over.empty() && !args.has("--force")) {
        std::fprintf(stderr, "raystudio-cli render: %s; pass --force to render it anyway\n",
                     over.c_str());
        return 2;
    }

    ProgressBar bar;
    options.progress = [&bar](int done, int total) { bar.update(done, total); };
    const EngineKind engine = engineOption(args);
    RenderResult result;
    std::string error;
    bool written = false;
    if (args.has("--tile")) {
        result = renderImage(CompiledScene(doc, nullptr, engine), options);
        written =
            writePart(*output, partHeader(doc, engine, part), result.image, result.ids, error);
    } else {
        written = renderToFile(doc, engine, *output, options, error, &result);
    }
    if (!written) {
        std::fprintf(stderr, "raystudio-cli render: %s\n", error.c_str());
        return 2;
    }
    if (args.has("--stats")) {
        const double mrays = result.ms > 0.0 ? double(result.rays) / (result.ms * 1000.0) : 0.0;
        std::printf(
            "{\"ms\": %.3f, \"width\": %d, \"height\": %d, \"rays\": %llu, "
            "\"mrays_per_s\": %.3f}\n",
            result.ms, doc.render.width, doc.render.height,
            static_cast<unsigned long long>(result.rays), mrays);
    }
    return 0;
}

}  // namespace rs::cli
