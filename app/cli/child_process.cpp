// Scheduler tools run through the render library's child process (fork, deadline, pipes),
// with exec in the child; no shell, so arguments need no quoting.
#include "child_process.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <sstream>

#include "io/child_process.h"

namespace rs::cli {

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const std::string file = (dir.empty() ? std::string(".") : dir) + "/" + program;
        struct stat st {};
        if (::stat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
            ::access(file.c_str(), X_OK) == 0)
            return true;
    }
    return false;
}

ChildResult runChild(const std::vector<std::string>& argv, int timeoutS) {
    ChildResult result;
    if (argv.empty()) return result;
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ChildLimits limits;
    limits.wallTime = std::chrono::seconds(timeoutS);
    limits.maxMessageBytes = std::size_t(1) << 20;
    const ChildOutcome outcome = runInChildProcess(
        [&](int) {
            const int devNull = ::open("/dev/null", O_RDONLY);
            if (devNull >= 0) ::dup2(devNull, 0);
            ::execvp(args[0], args.data());
            const std::string msg = "cannot run " + argv[0] + "\n";
            (void)!::write(2, msg.data(), msg.size());
            ::_exit(127);
        },
        limits);
    result.timedOut = outcome.ending == ChildOutcome::Ending::TimedOut;
    if (outcome.ending == ChildOutcome::Ending::Exited) result.exitCode = outcome.status;
    result.output = outcome.messages;  // What it printed, stdout and stderr together.
    return result;
}

}  // namespace rs::cli
