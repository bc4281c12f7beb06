// Slurm batch scripts for `farm submit`: a job array rendering the parts, a job merging them.
#pragma once

#include <string>
#include <vector>

namespace rs::cli {

/// Everything the two scripts name. Paths are absolute and must be seen by every node.
struct FarmJob {
    std::string cli;       ///< raystudio-cli on the nodes (this very executable).
    std::string scene;     ///< The scene file.
    std::string output;    ///< The merged image.
    std::string partsDir;  ///< Where the parts and the logs go (OUT + ".parts").
    int parts = 1;
    int cpusPerTask = 1;
    std::string partition;                ///< Empty: the cluster's default partition.
    std::string time;                     ///< Empty: the partition's default limit.
    std::vector<std::string> renderArgs;  ///< Render options forwarded to every part.
};

/// `text` as one POSIX shell word (single quotes; a quote inside becomes '\'').
std::string shellQuote(const std::string& text);

/// Part I's file: partsDir/part-IIII.exr (four digits at least, so they sort).
std::string partPath(const FarmJob& job, int index);

/// The job array script: task I runs `render SCENE --tile I/N -o PART`.
std::string renderScript(const FarmJob& job);

/// The merge script: `merge` over every part into the output; submitted with
/// --dependency=afterok on the array, so it runs only when every part succeeded.
std::string mergeScript(const FarmJob& job);

/// Empty when `value` is a Slurm partition name or time limit farm submit passes on; otherwise
/// a message naming the option and what it accepts.
std::string partitionError(const std::string& value);
std::string timeLimitError(const std::string& value);

}  // namespace rs::cli
