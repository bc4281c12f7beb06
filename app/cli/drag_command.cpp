// `raystudio-cli drag`: drags an object through the interactive session, then refines, and
// compares the refined frame with a from-scratch full render measured in the same run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sstream>
#include <thread>

#include "arguments.h"
#include "commands.h"
#include "core/input_file.h"
#include "core/statistics.h"
#include "integrator/renderer.h"
#include "session/render_session.h"

namespace rs::cli {

namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// Policy files are a dozen keys; anything this large is not one.
constexpr std::uintmax_t kMaxPolicyFileBytes = std::uintmax_t(1) << 20;

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

/// CPU time the process has used (all its threads), in milliseconds.
double cpuMs() {
    return 1000.0 * double(std::clock()) / double(CLOCKS_PER_SEC);
}

Vec3 parseVec3(const std::string& text) {
    Vec3 v;
    char c1 = 0, c2 = 0;
    std::istringstream in(text);
    if (!(in >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !in.eof() ||
        !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw UsageError{"--to expects X,Y,Z (three finite numbers), got '" + text + "'"};
    return v;
}

InteractionPolicy parsePolicy(const std::string& name) {
    if (name == "default") return InteractionPolicy{};
    if (name == "none") return InteractionPolicy::none();
    // Checked like scene files: a FIFO or a device named here must not block or never end.
    std::string text, error;
    if (!readInputFile(name, kMaxPolicyFileBytes, text, error))
        throw UsageError{"--policy: cannot read '" + name + "': " + error +
                         " (default, none or a JSON file)"};
    InteractionPolicy p;
    if (!policyFromJson(text, p, error)) throw UsageError{"--policy " + name + ": " + error};
    return p;
}

struct Step {
    double ms;
    std::size_t traced;
    int level;  ///< The governor's level for the step's pass (-1: off).
    /// Where the step went (0 for a step whose pass was not its own): CPU time of the process
    /// (all threads), the edit (diff, snapshot, marking), of it the marking, the planning and
    /// the pass (its tiles, first to last).
    double cpuMs = 0.0, editMs = 0.0, markMs = 0.0, planMs = 0.0, passMs = 0.0;
};

/// Medians of a step's phases; the rest (wall time outside them: waking the scheduler, the
/// hand-over to the waiting caller) is the step's median less the phases' medians.
struct Phases {
    double cpu, edit, mark, plan, pass;
};

Phases phaseMedians(const std::vector<Step>& log) {
    std::vector<double> cpu, edit, mark, plan, pass;
    for (const Step& s : log) {
        cpu.push_back(s.cpuMs);
        edit.push_back(s.editMs);
        mark.push_back(s.markMs);
        plan.push_back(s.planMs);
        pass.push_back(s.passMs);
    }
    return {median(cpu), median(edit), median(mark), median(plan), median(pass)};
}

}  // namespace

int runDrag(int argc, char** argv) {
    OptionSpec spec;
    spec.valued = {"--object",        "--to",     "--steps",     "--policy",     "--threads",
                   "--width",         "--height", "--max-depth", "--min-weight", "--shadow-samples",
                   "--supersampling", "--engine", "--frames"};
    spec.flags = {"--verify", "--json"};
    Arguments args(argc, argv, 2, spec);
    const EngineKind engine = engineOption(args);
    if (args.positional().size() != 1) throw UsageError{"expects exactly one scene file"};
    const auto objectName = args.value("--object");
    const auto to = args.value("--to");
    if (!objectName) throw UsageError{"missing --object NAME"};
    if (!to) throw UsageError{"missing --to X,Y,Z"};
    const Vec3 target = parseVec3(*to);
    const int steps = args.intValue("--steps", 1, 100000).value_or(30);
    const int frameRounds = args.intValue("--frames", 1, 1000).value_or(5);
    const int threads = args.intValue("--threads", 1, 1024).value_or(0);
    const InteractionPolicy policy = parsePolicy(args.value("--policy").value_or("default"));

    SceneDocument doc;
    if (!loadSceneOrReport(args.positional()[0], doc)) return 2;
    applyRenderOverrides(args, doc.render);
    Object* object = nullptr;
    for (Object& o : doc.objects.editable())
        if (o.name == *objectName) object = &o;
    if (!object) throw UsageError{"--object: the scene has no object named '" + *objectName + "'"};
    if (std::holds_alternative<PlaneGeometry>(object->geometry))
        throw UsageError{"--object: '" + *objectName +
                         "' is a plane; planes have no transform to drag"};
    const ObjectId id = object->id;
    const Aabb startBounds = CompiledScene(doc).objectBounds(id);
    if (startBounds.empty()) throw UsageError{"--object: '" + *objectName + "' is hidden or empty"};
    const Vec3 delta = (target - startBounds.center()) / float(steps);

    RenderSession session(threads);
    session.setPolicy(policy);
    session.setEngine(engine);
    session.update(doc);
    if (!session.waitUntilComplete(600s)) throw std::runtime_error("initial render timed out");

    std::vector<Step> log;
    session.beginInteraction(id);
    for (int s = 0; s < steps; ++s) {
        doc.findObject(id)->transform.translate += delta;
        const double cpuStart = cpuMs();
        const auto start = Clock::now();
        const uint64_t gen = session.update(doc);
        PassInfo info;
        if (!session.waitForPass(gen, 600s, &info)) throw std::runtime_error("drag step timed out");
        const double ms = msSince(start);
        const bool own = info.generation == gen;
        Step step{ms, own ? info.tracedPixels : 0, own ? info.governorLevel : -1};
        step.cpuMs = cpuMs() - cpuStart;
        if (own) {
            const SessionStats stats = session.stats();
            step.editMs = stats.lastUpdateMs;
            step.markMs = stats.lastMarkMs;
            step.planMs = info.planMs;
            step.passMs = info.ms;
        }
        log.push_back(step);
    }
    session.endInteraction();
    const auto refineStart = Clock::now();
    if (!session.waitUntilComplete(600s)) throw std::runtime_error("refinement timed out");
    const double refineMs = msSince(refineStart);

    RenderOptions options;
    options.threads = threads;
    const RenderResult full = renderImage(CompiledScene(doc, nullptr, engine), options);
    float maxDiff = 0.0f;
    session.withFrame([&](const DeepFrame& frame, const auto&) {
        for (std::size_t i = 0; i < frame.pixelCount(); ++i) {
            const Color d = glm::abs(frame.color()[i] - full.image.pixels[i]);
            maxDiff = std::max({maxDiff, d.x, d.y, d.z});
        }
    });

    // Cancellation latency: start a full re-render, interrupt it, time until workers stop.
    SceneDocument nudged = doc;
    nudged.camera.target.x += 1e-3f;
    session.update(nudged);
    std::this_thread::sleep_for(5ms);
    session.update(doc);
    session.waitUntilComplete(600s);
    const double cancelMs = session.stats().lastCancelLatencyMs;

    // A whole session frame (a camera nudge re-traces every pixel) against renderImage of the
    // same scene and size, interleaved so both see the same machine load; medians. Also the
    // CPU time each used (the process's, all threads): on a machine others load, what a
    // frame costs, where wall time also says how much of the machine it got.
    std::vector<double> sessionFrames, imageFrames, sessionCpu, imageCpu;
    for (int k = 0; k < frameRounds; ++k) {
        nudged.camera.target.x = doc.camera.target.x + (k % 2 ? -1e-3f : 1e-3f);
        const double sessionCpuStart = cpuMs();
        const auto frameStart = Clock::now();
        session.update(nudged);
        if (!session.waitUntilComplete(600s)) throw std::runtime_error("session frame timed out");
        sessionFrames.push_back(msSince(frameStart));
        sessionCpu.push_back(cpuMs() - sessionCpuStart);
        const CompiledScene imageScene(nudged, nullptr, engine);
        const double imageCpuStart = cpuMs();
        imageFrames.push_back(renderImage(imageScene, options).ms);
        imageCpu.push_back(cpuMs() - imageCpuStart);
    }
    const double sessionFrameMs = median(sessionFrames), imageFrameMs = median(imageFrames);
    const double sessionCpuMs = median(sessionCpu), imageCpuMs = median(imageCpu);

    const std::size_t total = std::size_t(doc.render.width) * std::size_t(doc.render.height);
    std::vector<double> times, fractions, levels;
    for (const Step& s : log) {
        times.push_back(s.ms);
        fractions.push_back(double(s.traced) / double(total));
        levels.push_back(double(s.level));
    }
    const double stepMedian = median(times), fractionMedian = median(fractions);
    const double levelMedian = median(levels);
    const Phases phases = phaseMedians(log);
    if (args.has("--json")) {
        std::printf("{\"steps\": [");
        for (std::size_t i = 0; i < log.size(); ++i)
            std::printf(
                "%s{\"ms\": %.3f, \"traced_pixels\": %zu, \"total_pixels\": %zu, "
                "\"governor_level\": %d}",
                i ? ", " : "", log[i].ms, log[i].traced, total, log[i].level);
        std::printf(
            "], \"step_ms_median\": %.3f, \"traced_fraction_median\": %.5f, "
            "\"refine_ms\": %.3f, \"full_frame_ms\": %.3f, \"final_max_abs_diff\": %.3g, "
            "\"cancel_latency_ms\": %.3f, \"session_frame_ms\": %.3f, "
            "\"render_image_ms\": %.3f, \"session_frame_cpu_ms\": %.3f, "
            "\"render_image_cpu_ms\": %.3f, \"session_frames\": %d, "
            "\"governor_level_median\": %.1f, "
            "\"step_cpu_ms_median\": %.3f, \"step_edit_ms_median\": %.3f, "
            "\"step_mark_ms_median\": %.3f, \"step_plan_ms_median\": %.3f, "
            "\"step_pass_ms_median\": %.3f}\n",
            stepMedian, fractionMedian, refineMs, full.ms, double(maxDiff), cancelMs,
            sessionFrameMs, imageFrameMs, sessionCpuMs, imageCpuMs, frameRounds, levelMedian,
            phases.cpu, phases.edit, phases.mark, phases.plan, phases.pass);
    } else {
        std::printf("dragged '%s' in %d steps (%dx%d)\n", objectName->c_str(), steps,
                    doc.render.width, doc.render.height);
        std::printf("  step time median      %10.2f ms\n", stepMedian);
        std::printf("  step CPU median       %10.2f ms  (all threads)\n", phases.cpu);
        std::printf(
            "  step phases, medians  edit %.2f ms (of which marking %.2f), planning %.2f, "
            "pass %.2f, the rest %.2f\n",
            phases.edit, phases.mark, phases.plan, phases.pass,
            stepMedian - phases.edit - phases.plan - phases.pass);
        std::printf("  traced fraction median %9.2f %%\n", 100.0 * fractionMedian);
        if (levelMedian >= 0.0)
            std::printf("  governor level median %10.1f  (%s)\n", levelMedian,
                        Governor::levelName(int(levelMedian)));
        std::printf("  refinement            %10.2f ms\n", refineMs);
        std::printf("  full frame            %10.2f ms  (ratio step/full %.3f)\n", full.ms,
                    full.ms > 0 ? stepMedian / full.ms : 0.0);
        std::printf("  cancel latency        %10.2f ms\n", cancelMs);
        std::printf(
            "  session frame         %10.2f ms  (renderImage %.2f ms, ratio %.3f; medians of %d)\n",
            sessionFrameMs, imageFrameMs, imageFrameMs > 0 ? sessionFrameMs / imageFrameMs : 0.0,
            frameRounds);
        std::printf(
            "  session frame CPU     %10.2f ms  (renderImage %.2f ms, ratio %.3f; medians of %d)\n",
            sessionCpuMs, imageCpuMs, imageCpuMs > 0 ? sessionCpuMs / imageCpuMs : 0.0,
            frameRounds);
        std::printf("  final max abs diff    %10.3g\n", double(maxDiff));
    }
    if (args.has("--verify") && maxDiff > 1e-5f) {
        std::fprintf(stderr, "raystudio-cli drag: refined frame differs from a full render by %g\n",
                     double(maxDiff));
        return 1;
    }
    return 0;
}

}  // namespace rs::cli
