// Running raystudio-cli as a process from the command-line tests: exit code, stdout, stderr.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

struct CliRun {
    int exitCode;     ///< -1 when the process died from a signal; 124 when it hung.
    std::string out;  ///< stdout: results only.
    std::string err;  ///< stderr: messages, usage, progress.
};

inline std::string readAll(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// Runs the CLI with `args` (shell words), capturing stdout and stderr apart. A run that
/// takes over `timeoutS` seconds is killed: nothing the CLI is given may make it hang. `env`
/// goes before the program (e.g. "env PATH=/nonexistent").
inline CliRun cli(const std::string& args, int timeoutS = 120, const std::string& env = "") {
    static int calls = 0;
    const std::filesystem::path errFile =
        std::filesystem::temp_directory_path() /
        ("raystudio-cli-test-stderr-" + std::to_string(getpid()) + "-" + std::to_string(++calls));
    const std::string cmd = "timeout " + std::to_string(timeoutS) + " " + env + " '" +
                            RAYSTUDIO_CLI + "' " + args + " 2>'" + errFile.string() + "'";
    FILE* pipe = popen(cmd.c_str(), "r");
    CliRun run{-1, {}, {}};
    std::array<char, 4096> buf;
    while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe))
        run.out.append(buf.data(), n);
    const int status = pclose(pipe);
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.err = readAll(errFile);
    std::filesystem::remove(errFile);
    return run;
}

}  // namespace
