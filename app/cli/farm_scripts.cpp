// The batch scripts' text: #SBATCH options, then one exec of raystudio-cli each.
#include "farm_scripts.h"

#include <cctype>
#include <cstdio>

namespace rs::cli {

namespace {

/// The #SBATCH lines both scripts share.
std::string commonOptions(const FarmJob& job) {
    std::string text;
    if (!job.partition.empty()) text += "#SBATCH --partition=" + job.partition + "\n";
    if (!job.time.empty()) text += "#SBATCH --time=" + job.time + "\n";
    return text;
}

/// An #SBATCH path option: Slurm reads the line itself, not a shell, so no quotes; paths with
/// spaces or quotes are refused before we get here (farm submit's path check).
std::string sbatchPath(const std::string& option, const std::string& path) {
    return "#SBATCH " + option + "=" + path + "\n";
}

}  // namespace

std::string shellQuote(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string partPath(const FarmJob& job, int index) {
    char name[32];
    std::snprintf(name, sizeof name, "part-%04d.exr", index);
    return job.partsDir + "/" + name;
}

std::string renderScript(const FarmJob& job) {
    std::string text = "#!/bin/bash\n";
    text += "# RayStudio: task I of this job array renders part I of " + std::to_string(job.parts) +
            " of " + job.scene + "\n";
    text += "#SBATCH --job-name=raystudio-render\n";
    text += "#SBATCH --array=0-" + std::to_string(job.parts - 1) + "\n";
    text += "#SBATCH --cpus-per-task=" + std::to_string(job.cpusPerTask) + "\n";
    text += sbatchPath("--output", job.partsDir + "/logs/render-%A_%a.log");
    text += commonOptions(job);
    text += "set -euo pipefail\n";
    text += "part=$(printf '%04d' \"$SLURM_ARRAY_TASK_ID\")\n";
    text += "exec " + shellQuote(job.cli) + " render " + shellQuote(job.scene) +
            " --tile \"$SLURM_ARRAY_TASK_ID/" + std::to_string(job.parts) + "\" -o " +
            shellQuote(job.partsDir + "/part-") + "\"$part\".exr --threads " +
            std::to_string(job.cpusPerTask);
    for (const std::string& arg : job.renderArgs) {
        text += ' ';  // Not `" " + shellQuote(arg)`: that temporary trips GCC 12's -Wrestrict.
        text += shellQuote(arg);
    }
    return text + "\n";
}

std::string mergeScript(const FarmJob& job) {
    std::string text = "#!/bin/bash\n";
    text += "# RayStudio: merges the " + std::to_string(job.parts) + " parts into " + job.output +
            " (submitted with --dependency=afterok on the render array)\n";
    text += "#SBATCH --job-name=raystudio-merge\n";
    text += "#SBATCH --cpus-per-task=1\n";
    text += sbatchPath("--output", job.partsDir + "/logs/merge-%j.log");
    text += commonOptions(job);
    text += "set -euo pipefail\n";
    text += "parts=()\n";
    text += "for ((i = 0; i < " + std::to_string(job.parts) + "; ++i)); do\n";
    text +=
        "    parts+=(" + shellQuote(job.partsDir + "/part-") + "\"$(printf '%04d' \"$i\")\".exr)\n";
    text += "done\n";
    text += "exec " + shellQuote(job.cli) + " merge \"${parts[@]}\" -o " + shellQuote(job.output) +
            "\n";
    return text;
}

std::string partitionError(const std::string& value) {
    bool ok = !value.empty() && value.size() <= 64;
    for (char c : value)
        ok =
            ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.');
    return ok ? std::string()
              : "--partition expects a partition name (letters, digits, '_', '-', '.'), got '" +
                    value + "'";
}

std::string timeLimitError(const std::string& value) {
    // Slurm's forms: minutes, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS (digits, ':' and '-').
    bool ok = !value.empty() && value.size() <= 16 &&
              std::isdigit(static_cast<unsigned char>(value.front())) &&
              std::isdigit(static_cast<unsigned char>(value.back()));
    int dashes = 0, colons = 0;
    for (char c : value) {
        dashes += c == '-', colons += c == ':';
        ok = ok && (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == ':');
    }
    ok = ok && dashes <= 1 && colons <= 2 && (dashes == 0 || value.find('-') < value.find(':'));
    return ok ? std::string()
              : "--time expects a Slurm time limit (MINUTES, HH:MM:SS or D-HH:MM:SS), got '" +
                    value + "'";
}

}  // namespace rs::cli
