// Running untrusted work (a third-party importer) in a forked child process under a memory,
// CPU and wall-clock budget, with its result coming back through a pipe.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace rs {

/// What the child may use. Memory is address space on top of what the parent already had
/// mapped when it forked (RLIMIT_AS); the wall-clock limit is the parent's, which kills the
/// child when it passes; the CPU limit (RLIMIT_CPU) is `cpuTime`, or as many seconds as the
/// wall-clock limit when that is not set.
struct ChildLimits {
    std::uintmax_t memoryBytes = std::uintmax_t(1) << 30;
    std::chrono::milliseconds wallTime{10000};
    std::optional<std::chrono::milliseconds> cpuTime;
    std::size_t maxOutputBytes = std::size_t(1) << 30;  ///< More is killed and reported.
    std::size_t maxMessageBytes = 4096;         ///< What it prints beyond this is read and dropped.
    const std::atomic<bool>* cancel = nullptr;  ///< Polled; true kills the child.
};

/// How the child ended, and what it wrote.
struct ChildOutcome {
    enum class Ending {
        Exited,          ///< exit(status): `status` holds it.
        Signalled,       ///< Killed by a signal it raised or got (not ours): `status` holds it.
        TimedOut,        ///< Past `wallTime`: killed by the parent.
        Cancelled,       ///< `cancel` became true: killed by the parent.
        OutputTooLarge,  ///< Wrote more than `maxOutputBytes`: killed by the parent.
        NotStarted,      ///< pipe() or fork() failed: `problem` says why.
    };
    Ending ending = Ending::NotStarted;
    int status = 0;
    std::string output;    ///< Everything the child wrote to its pipe.
    std::string messages;  ///< The start of what it printed (stdout and stderr together).
    std::string problem;   ///< For NotStarted, the system's reason.
};

/// Forks; the child applies `limits`, runs `work(fd)` (which writes its result to fd) and
/// exits with status 0 without running atexit handlers or static destructors (nothing of
/// the parent's state is torn down twice). The parent collects the output until the child
/// closes the pipe, then reaps it. The child must not start threads; it holds no file
/// descriptor of the parent's but stdin, and its stdout and stderr go to `messages`. (A lock
/// another thread of the parent held at the fork stays held in the child; should the work
/// need it, the child waits until the deadline kills it: a late error, never a hang.)
ChildOutcome runInChildProcess(const std::function<void(int fd)>& work, const ChildLimits& limits);

/// Writes all `size` bytes at `data` to `fd` (retrying on EINTR and short writes); false on
/// an error.
bool writeAllTo(int fd, const void* data, std::size_t size);

/// "signal 6, Aborted": a signal number with the system's name for it.
std::string describeSignal(int signal);

}  // namespace rs
