// `raystudio-cli bench`: the thesis's chapter 4.2 feature-cost experiments on one scene.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "arguments.h"
#include "commands.h"
#include "core/statistics.h"
#include "integrator/renderer.h"

namespace rs::cli {

namespace {

struct Experiment {
    const char* name;
    std::vector<int> values;
    void (*apply)(RenderSettings&, int);
};

struct Measurement {
    std::string experiment;
    int value;
    double medianMs;
    uint64_t rays;
};

}  // namespace

int runBench(int argc, char** argv) {
    OptionSpec spec;
    spec.valued = {"--repeat", "--threads", "--width", "--height", "--min-weight", "--engine"};
    spec.flags = {"--json", "--baseline-only"};
    Arguments args(argc, argv, 2, spec);
    const EngineKind engine = engineOption(args);
    if (args.positional().size() != 1) throw UsageError{"expects exactly one scene file"};
    const int repeat = args.intValue("--repeat", 1, 1000).value_or(5);
    RenderOptions options;
    options.threads = args.intValue("--threads", 1, 1024).value_or(0);

    SceneDocument doc;
    if (!loadSceneOrReport(args.positional()[0], doc)) return 2;
    applyRenderOverrides(args, doc.render);

    // The thesis's table: each experiment varies one setting, the rest stay as the scene has them.
    const std::vector<Experiment> experiments = {
        {"baseline", {0}, [](RenderSettings&, int) {}},
        {"shadow_samples", {0, 1, 27, 64}, [](RenderSettings& s, int v) { s.shadowSamples = v; }},
        {"max_depth", {0, 1, 2, 44}, [](RenderSettings& s, int v) { s.maxDepth = v; }},
        {"supersampling", {1, 2, 4, 8}, [](RenderSettings& s, int v) { s.supersampling = v; }},
    };
    std::vector<Measurement> results;
    const bool json = args.has("--json");
    if (!json)
        std::printf("%-16s %6s %12s %14s   (%dx%d, median of %d)\n", "experiment", "value",
                    "median ms", "rays", doc.render.width, doc.render.height, repeat);
    // --baseline-only: the scene as it is, nothing varied (for benchmarks comparing scenes).
    const std::size_t count = args.has("--baseline-only") ? 1 : experiments.size();
    for (std::size_t k = 0; k < count; ++k) {
        const Experiment& e = experiments[k];
        for (int value : e.values) {
            SceneDocument variant = doc;
            e.apply(variant.render, value);
            const CompiledScene scene(variant, nullptr, engine);
            std::vector<double> times;
            uint64_t rays = 0;
            for (int r = 0; r < repeat; ++r) {
                RenderResult result = renderImage(scene, options);
                times.push_back(result.ms);
                rays = result.rays;
            }
            results.push_back({e.name, value, median(times), rays});
            if (!json)
                std::printf("%-16s %6d %12.2f %14llu\n", e.name, value, results.back().medianMs,
                            static_cast<unsigned long long>(rays));
            std::fflush(stdout);
        }
    }
    if (json) {
        std::printf("[");
        for (std::size_t i = 0; i < results.size(); ++i) {
            const Measurement& m = results[i];
            std::printf(
                "%s{\"experiment\": \"%s\", \"value\": %d, \"median_ms\": %.3f, "
                "\"rays\": %llu}",
                i ? ", " : "", m.experiment.c_str(), m.value, m.medianMs,
                static_cast<unsigned long long>(m.rays));
        }
        std::printf("]\n");
    }
    return 0;
}

}  // namespace rs::cli
