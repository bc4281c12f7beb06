// runInChildProcess: fork, limits in the child, a poll() loop with a deadline in the parent.
#include "io/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <system_error>

namespace rs {

namespace {
using Clock = std::chrono::steady_clock;

/// The child's exit status when `work` threw (it is meant to report its own errors).
constexpr int kWorkThrew = 70;
/// How often the parent looks at the cancel flag while the child is quiet.
constexpr std::chrono::milliseconds kCancelPoll{50};

std::string errnoMessage(int error) {
    return std::error_code(error, std::generic_category()).message();
}

/// The address space mapped now (/proc/self/statm's first field), or 0 when unknown.
/// Plain system calls: the child of a multithreaded parent should stay away from locks.
std::uintmax_t mappedBytes() {
    const int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return 0;
    char text[64];
    const ssize_t n = ::read(fd, text, sizeof text - 1);
    ::close(fd);
    if (n <= 0) return 0;
    std::uintmax_t pages = 0;
    for (ssize_t i = 0; i < n && text[i] >= '0' && text[i] <= '9'; ++i)
        pages = pages * 10 + std::uintmax_t(text[i] - '0');
    return pages * std::uintmax_t(::sysconf(_SC_PAGESIZE));
}

/// Sets `resource` to `soft`/`hard`, never above the hard limit already in force.
void limit(int resource, rlim_t soft, rlim_t hard) {
    rlimit now{};
    if (::getrlimit(resource, &now) != 0) return;
    if (now.rlim_max != RLIM_INFINITY) {
        if (hard > now.rlim_max) hard = now.rlim_max;
        if (soft > hard) soft = hard;
    }
    const rlimit wanted{soft, hard};
    ::setrlimit(resource, &wanted);
}

/// Closes every descriptor but 0, 1, 2 and `keep`: a second child forked meanwhile by
/// another thread must not hold this child's pipe open (the parent waits for its end).
void closeOtherDescriptors(int keep) {
    const int top = int(::sysconf(_SC_OPEN_MAX) > 0 ? ::sysconf(_SC_OPEN_MAX) : 1024);
#ifdef __linux__
    if ((keep == 3 || ::close_range(3, unsigned(keep) - 1, 0) == 0) &&
        ::close_range(unsigned(keep) + 1, ~0u, 0) == 0)
        return;
#endif
    for (int fd = 3; fd < top && fd < 65536; ++fd)
        if (fd != keep) ::close(fd);
}

/// The parent's handlers (a fuzzer's crash reporter, a designer's) must not run in the
/// child: a crash there is the child's death by its signal, which the parent reports.
void defaultSignals() {
    for (int signal :
         {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGXCPU, SIGPIPE, SIGTERM, SIGINT, SIGHUP})
        ::signal(signal, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
}

/// `fd` moved to 3 or above (a parent with stdout closed can get a pipe at 1).
int aboveStandard(int fd) {
    if (fd >= 3) return fd;
    const int moved = ::fcntl(fd, F_DUPFD, 3);
    if (moved < 0) ::_exit(kWorkThrew);
    return moved;
}

[[noreturn]] void runChild(int fd, int messages, pid_t parent, const std::function<void(int)>& work,
                           const ChildLimits& limits) {
    fd = aboveStandard(fd);
    messages = aboveStandard(messages);
    // What the child prints (an importer's assertion text, a sanitizer's report) goes to
    // the parent as `messages`, never to the program's own stdout or stderr.
    ::dup2(messages, 1);
    ::dup2(messages, 2);
    closeOtherDescriptors(fd);
    defaultSignals();
#ifdef __linux__
    // Dies with the parent (the designer killed mid-import leaves no importer behind), and
    // is the one the out-of-memory killer takes first.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(kWorkThrew);
    const int adjust = ::open("/proc/self/oom_score_adj", O_WRONLY | O_CLOEXEC);
    if (adjust >= 0) {
        [[maybe_unused]] ssize_t ignored = ::write(adjust, "1000", 4);
        ::close(adjust);
    }
#else
    (void)parent;
#endif
    limit(RLIMIT_CORE, 0, 0);  // An importer's crash is reported, not dumped.
    const auto cpuSeconds = rlim_t(limits.cpuTime.value_or(limits.wallTime).count() / 1000 + 1);
    limit(RLIMIT_CPU, cpuSeconds, cpuSeconds + 1);
    // The copy of the parent's mappings is already there; the budget is what comes on top.
    const std::uintmax_t mapped = mappedBytes();
    if (mapped > 0) {
        const auto as = rlim_t(mapped + limits.memoryBytes);
        limit(RLIMIT_AS, as, as);
    }
    try {
        work(fd);
    } catch (...) {
        ::_exit(kWorkThrew);
    }
    ::_exit(0);
}

/// Kills and reaps `pid` (it cannot ignore SIGKILL, so the wait is short).
void killAndReap(pid_t pid) {
    ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
}

/// A started child: its pid and the read ends of its result and message pipes.
struct StartedChild {
    pid_t pid = -1;
    int result = -1, messages = -1;
};

/// Makes the pipes and forks a child that runs `work`; on failure says why in
/// outcome.problem and returns a pid below 0.
StartedChild startChild(const std::function<void(int fd)>& work, const ChildLimits& limits,
                        ChildOutcome& outcome) {
    int result[2], messages[2];
    // O_CLOEXEC: a program another thread starts meanwhile does not inherit the pipes.
    if (::pipe2(result, O_CLOEXEC) != 0) {
        outcome.problem = "cannot create a pipe: " + errnoMessage(errno);
        return {};
    }
    if (::pipe2(messages, O_CLOEXEC) != 0) {
        outcome.problem = "cannot create a pipe: " + errnoMessage(errno);
        ::close(result[0]);
        ::close(result[1]);
        return {};
    }
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
        outcome.problem = "cannot start a process: " + errnoMessage(errno);
        for (int fd : {result[0], result[1], messages[0], messages[1]}) ::close(fd);
        return {};
    }
    if (pid == 0) {
        ::close(result[0]);
        ::close(messages[0]);
        runChild(result[1], messages[1], parent, work, limits);
    }
    ::close(result[1]);
    ::close(messages[1]);
    return {pid, result[0], messages[0]};
}

/// Reads the child's result and messages into `outcome` until it closes both pipes (Exited)
/// or something stops it first: the cancel flag, the deadline, too much output, a failed
/// poll. Closes the pipes.
ChildOutcome::Ending readChild(const StartedChild& child, const ChildLimits& limits,
                               Clock::time_point deadline, ChildOutcome& outcome) {
    ChildOutcome::Ending stoppedBy = ChildOutcome::Ending::Exited;
    char buffer[1 << 16];
    pollfd pipes[2] = {{child.result, POLLIN, 0}, {child.messages, POLLIN, 0}};
    int openPipes = 2;
    while (openPipes > 0) {
        if (limits.cancel && limits.cancel->load()) {
            stoppedBy = ChildOutcome::Ending::Cancelled;
            break;
        }
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
        if (left.count() <= 0) {
            stoppedBy = ChildOutcome::Ending::TimedOut;
            break;
        }
        const auto wait = limits.cancel ? std::min(left, kCancelPoll) : left;
        const int ready = ::poll(pipes, 2, int(std::min<long long>(wait.count(), 1 << 30)));
        if (ready < 0 && errno != EINTR) {
            outcome.problem = "cannot wait for the child process: " + errnoMessage(errno);
            stoppedBy = ChildOutcome::Ending::NotStarted;
            break;
        }
        for (pollfd& p : pipes) {
            if (ready <= 0 || p.fd < 0 || p.revents == 0) continue;
            const ssize_t n = ::read(p.fd, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {  // The child closed its end: it exited or is exiting.
                ::close(p.fd);
                p.fd = -1;
                --openPipes;
            } else if (&p == &pipes[1]) {
                const std::size_t room = limits.maxMessageBytes - outcome.messages.size();
                outcome.messages.append(buffer, std::min(room, std::size_t(n)));
            } else if (outcome.output.size() + std::size_t(n) > limits.maxOutputBytes) {
                stoppedBy = ChildOutcome::Ending::OutputTooLarge;
            } else {
                outcome.output.append(buffer, std::size_t(n));
            }
        }
        if (stoppedBy != ChildOutcome::Ending::Exited) break;
    }
    for (const pollfd& p : pipes)
        if (p.fd >= 0) ::close(p.fd);
    return stoppedBy;
}

/// The child's ending and status once its pipes are closed: it is on its way out, but it
/// gets only the time left before `deadline`.
void reapChild(pid_t pid, Clock::time_point deadline, ChildOutcome& outcome) {
    int status = 0;
    for (;;) {
        const pid_t reaped = ::waitpid(pid, &status, WNOHANG);
        if (reaped == pid) break;
        if (reaped < 0 && errno == EINTR) continue;
        if (reaped < 0) {
            // ECHILD: SIGCHLD is ignored and the system reaped it; the output must speak.
            outcome.ending = ChildOutcome::Ending::Exited;
            return;
        }
        if (Clock::now() >= deadline) {
            killAndReap(pid);
            outcome.ending = ChildOutcome::Ending::TimedOut;
            return;
        }
        ::usleep(1000);
    }
    if (WIFSIGNALED(status)) {
        outcome.ending = ChildOutcome::Ending::Signalled;
        outcome.status = WTERMSIG(status);
    } else {
        outcome.ending = ChildOutcome::Ending::Exited;
        outcome.status = WEXITSTATUS(status);
    }
}
}  // namespace

std::string describeSignal(int signal) {
    const char* name = ::strsignal(signal);
    return "signal " + std::to_string(signal) + (name ? std::string(", ") + name : std::string());
}

bool writeAllTo(int fd, const void* data, std::size_t size) {
    const char* bytes = static_cast<const char*>(data);
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::write(fd, bytes + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += std::size_t(n);
    }
    return true;
}

ChildOutcome runInChildProcess(const std::function<void(int fd)>& work, const ChildLimits& limits) {
    ChildOutcome outcome;
    const StartedChild child = startChild(work, limits, outcome);
    if (child.pid < 0) return outcome;
    const Clock::time_point deadline = Clock::now() + limits.wallTime;
    const ChildOutcome::Ending stoppedBy = readChild(child, limits, deadline, outcome);
    if (stoppedBy != ChildOutcome::Ending::Exited) {
        killAndReap(child.pid);
        outcome.ending = stoppedBy;
        return outcome;
    }
    reapChild(child.pid, deadline, outcome);
    return outcome;
}

}  // namespace rs
