// `raystudio-cli farm submit|status`: final renders on a Slurm cluster. Slurm schedules,
// retries and accounts; we only write the two batch scripts and call sbatch, squeue, sacct.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "arguments.h"
#include "child_process.h"
#include "commands.h"
#include "farm_scripts.h"
#include "image/image_io.h"
#include "image/image_part.h"
#include "integrator/cost_estimate.h"

namespace rs::cli {

namespace {

namespace fs = std::filesystem;

constexpr int kSchedulerTimeoutS = 60;  ///< sbatch, squeue, sacct must answer within this.

/// The render options farm submit accepts and forwards to every part.
const std::vector<std::string> kForwarded = {"--width",      "--height",         "--max-depth",
                                             "--min-weight", "--shadow-samples", "--supersampling",
                                             "--engine"};

/// An absolute path Slurm's #SBATCH lines and the scripts can carry unquoted.
fs::path jobPath(const std::string& option, const std::string& text) {
    const fs::path p = fs::absolute(text).lexically_normal();
    for (char c : p.string())
        if (c == ' ' || c == '\'' || c == '"' || c == '\\' || c == '%' || c == '\n' || c == '\t')
            throw UsageError{option + " path '" + text +
                             "' has a space, quote, backslash or '%' (not allowed in a job path)"};
    return p;
}

/// The job id sbatch --parsable printed ("123" or "123;cluster"), or "" when it failed.
std::string parsedJobId(const ChildResult& r) {
    if (r.exitCode != 0) return {};
    std::string id = r.output.substr(0, r.output.find_first_of(";\n"));
    for (char c : id)
        if (c < '0' || c > '9') return {};
    return id;
}

std::string schedulerFailure(const std::string& what, const ChildResult& r) {
    std::string out = r.output;
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    if (r.timedOut)
        return what + " did not answer within " + std::to_string(kSchedulerTimeoutS) + " s";
    return what + " failed (exit " + std::to_string(r.exitCode) + ")" +
           (out.empty() ? "" : ": " + out);
}

int runSubmit(int argc, char** argv) {
    OptionSpec spec;
    spec.valued = {"--output", "--parts", "--partition", "--time", "--cpus-per-task"};
    spec.valued.insert(kForwarded.begin(), kForwarded.end());
    spec.flags = {"--dry-run", "--force"};
    spec.aliases = {{"-o", "--output"}};
    Arguments args(argc, argv, 3, spec);
    if (args.positional().size() != 1)
        throw UsageError{"expects exactly one scene file (farm submit SCENE -o OUT --parts N)"};
    auto output = args.value("--output");
    if (!output || output->empty()) throw UsageError{"missing -o OUT (the merged image)"};
    if (std::string bad = imageFormatError(*output); !bad.empty()) throw UsageError{bad};
    const auto parts = args.intValue("--parts", 1, kMaxImageParts);
    if (!parts) throw UsageError{"missing --parts N (how many tasks render the image)"};

    FarmJob job;
    job.parts = *parts;
    job.cpusPerTask = args.intValue("--cpus-per-task", 1, 1024).value_or(1);
    job.scene = jobPath("SCENE", args.positional()[0]).string();
    job.output = jobPath("-o", *output).string();
    job.partsDir = job.output + ".parts";
    if (auto p = args.value("--partition")) {
        if (std::string bad = partitionError(*p); !bad.empty()) throw UsageError{bad};
        job.partition = *p;
    }
    if (auto t = args.value("--time")) {
        if (std::string bad = timeLimitError(*t); !bad.empty()) throw UsageError{bad};
        job.time = *t;
    }
    for (const std::string& name : kForwarded)
        if (auto v = args.value(name)) job.renderArgs.insert(job.renderArgs.end(), {name, *v});
    if (args.has("--force")) job.renderArgs.push_back("--force");

    // Everything a task would refuse is refused here, before anything reaches the queue.
    SceneDocument doc;
    if (!loadSceneOrReport(job.scene, doc)) return 2;
    applyRenderOverrides(args, doc.render);
    (void)engineOption(args);
    if (std::string bad = partError({0, job.parts}, doc.render.height); !bad.empty())
        throw UsageError{"--parts: " + bad};
    if (const std::string over = budgetExceeded(estimateCost(doc));
        !over.empty() && !args.has("--force")) {
        std::fprintf(stderr, "raystudio-cli farm submit: %s; pass --force to render it anyway\n",
                     over.c_str());
        return 2;
    }
    std::error_code ec;
    job.cli = fs::read_symlink("/proc/self/exe", ec).string();
    if (ec) {
        std::fprintf(stderr, "raystudio-cli farm submit: cannot find this program's path: %s\n",
                     ec.message().c_str());
        return 1;
    }

    const std::string render = renderScript(job), merge = mergeScript(job);
    if (args.has("--dry-run")) {
        std::printf("# ---- %s/render.sbatch (sbatch --parsable)\n%s", job.partsDir.c_str(),
                    render.c_str());
        std::printf(
            "# ---- %s/merge.sbatch (sbatch --parsable --dependency=afterok:RENDER_JOB)\n%s",
            job.partsDir.c_str(), merge.c_str());
        return 0;
    }
    if (!onPath("sbatch")) {
        std::fprintf(
            stderr,
            "raystudio-cli farm submit: sbatch is not on PATH (install Slurm's "
            "client, slurm-client, or run on a login node); --dry-run prints the scripts\n");
        return 1;
    }
    fs::create_directories(fs::path(job.partsDir) / "logs", ec);
    const fs::path renderFile = fs::path(job.partsDir) / "render.sbatch";
    const fs::path mergeFile = fs::path(job.partsDir) / "merge.sbatch";
    if (!ec) std::ofstream(renderFile) << render;
    if (!ec) std::ofstream(mergeFile) << merge;
    if (ec || !fs::is_regular_file(renderFile) || !fs::is_regular_file(mergeFile)) {
        std::fprintf(stderr,
                     "raystudio-cli farm submit: cannot write the job scripts in '%s'%s%s\n",
                     job.partsDir.c_str(), ec ? ": " : "", ec ? ec.message().c_str() : "");
        return 2;
    }
    const ChildResult r1 =
        runChild({"sbatch", "--parsable", renderFile.string()}, kSchedulerTimeoutS);
    const std::string renderId = parsedJobId(r1);
    if (renderId.empty()) {
        std::fprintf(stderr, "raystudio-cli farm submit: %s\n",
                     schedulerFailure("sbatch " + renderFile.string(), r1).c_str());
        return 1;
    }
    const ChildResult r2 =
        runChild({"sbatch", "--parsable", "--dependency=afterok:" + renderId, mergeFile.string()},
                 kSchedulerTimeoutS);
    const std::string mergeId = parsedJobId(r2);
    if (mergeId.empty()) {
        std::fprintf(stderr,
                     "raystudio-cli farm submit: %s (render job %s stays queued; scancel %s "
                     "to drop it)\n",
                     schedulerFailure("sbatch " + mergeFile.string(), r2).c_str(), renderId.c_str(),
                     renderId.c_str());
        return 1;
    }
    std::printf("render job %s: %d parts into %s\n", renderId.c_str(), job.parts,
                job.partsDir.c_str());
    std::printf("merge job %s: writes %s after every part succeeded\n", mergeId.c_str(),
                job.output.c_str());
    return 0;
}

int runStatus(int argc, char** argv) {
    Arguments args(argc, argv, 3, OptionSpec{});
    if (args.positional().size() != 1) throw UsageError{"expects one job id (farm status JOB)"};
    const std::string id = args.positional()[0];
    if (id.empty() || id.size() > 20 || id.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError{"JOB must be a job id (digits, as farm submit printed), got '" + id + "'"};
    if (!onPath("squeue")) {
        std::fprintf(stderr, "raystudio-cli farm status: squeue is not on PATH (Slurm's client)\n");
        return 1;
    }
    // One line per array task: id, state, elapsed time, node or reason.
    ChildResult q = runChild({"squeue", "-h", "-r", "-t", "all", "-j", id, "-o", "%i %T %M %R"},
                             kSchedulerTimeoutS);
    if (q.timedOut) {
        std::fprintf(stderr, "raystudio-cli farm status: %s\n",
                     schedulerFailure("squeue", q).c_str());
        return 1;
    }
    std::string lines = q.exitCode == 0 ? q.output : std::string();
    if (lines.empty() && onPath("sacct")) {  // gone from the queue: ask accounting, if kept
        ChildResult a = runChild({"sacct", "-n", "-X", "-P", "--delimiter= ", "-j", id, "-o",
                                  "JobID,State,Elapsed,NodeList"},
                                 kSchedulerTimeoutS);
        if (a.exitCode == 0) lines = a.output;
    }
    if (lines.empty()) {
        std::fprintf(stderr,
                     "raystudio-cli farm status: job %s is neither queued (squeue) nor in "
                     "the accounting records (sacct): finished longer ago than the cluster "
                     "keeps jobs, or never submitted\n",
                     id.c_str());
        return 2;
    }
    std::map<std::string, int> states;
    int tasks = 0;
    std::istringstream in(lines);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string task, state;
        if (!(words >> task >> state)) continue;
        ++tasks, ++states[state];
    }
    std::string summary;
    for (const auto& [state, n] : states)
        summary += (summary.empty() ? "" : ", ") + std::to_string(n) + " " + state;
    std::printf("job %s: %d task%s: %s\n%s", id.c_str(), tasks, tasks == 1 ? "" : "s",
                summary.c_str(), lines.c_str());
    return 0;
}

}  // namespace

int runFarm(int argc, char** argv) {
    const std::string sub = argc > 2 ? argv[2] : "";
    if (sub == "submit") return runSubmit(argc, argv);
    if (sub == "status") return runStatus(argc, argv);
    throw UsageError{
        sub.empty()
            ? "expects a sub-command: farm submit SCENE -o OUT --parts N, or farm status JOB"
            : "unknown sub-command '" + sub + "' (farm submit, farm status)"};
}

}  // namespace rs::cli
