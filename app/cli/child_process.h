// Running the scheduler's command-line tools (sbatch, squeue, sacct) from farm commands.
#pragma once

#include <string>
#include <vector>

namespace rs::cli {

/// What a finished command printed and how it ended.
struct ChildResult {
    int exitCode = -1;  ///< -1 when it could not be started or died from a signal.
    bool timedOut = false;
    std::string output;  ///< stdout and stderr together.
};

/// True when `program` is an executable file in a folder of PATH.
bool onPath(const std::string& program);

/// Runs argv (argv[0] looked up on PATH) with stdin from /dev/null, killing it after
/// `timeoutS` seconds: a scheduler that does not answer costs a message, not a hang. Output
/// past 1 MiB is dropped.
ChildResult runChild(const std::vector<std::string>& argv, int timeoutS);

}  // namespace rs::cli
