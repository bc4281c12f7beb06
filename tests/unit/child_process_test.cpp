// The import child process: how it ends (exit, crash, timeout, too much output, cancel).
#include "io/child_process.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

namespace rs {
namespace {

using Ending = ChildOutcome::Ending;
using std::chrono::milliseconds;

/// Where an allocation's result goes, so the compiler cannot assume it succeeded.
void* volatile allocated = nullptr;

ChildLimits limitsOf(milliseconds wall, std::size_t maxOutput = 1 << 20) {
    ChildLimits limits;
    limits.memoryBytes = std::uintmax_t(64) << 20;
    limits.wallTime = wall;
    limits.maxOutputBytes = maxOutput;
    return limits;
}

TEST(ChildProcess, OutputComesBackWhole) {
    const std::string big(300000, 'x');  // More than a pipe holds: the parent reads as it comes.
    const ChildOutcome out = runInChildProcess(
        [&](int fd) { writeAllTo(fd, big.data(), big.size()); }, limitsOf(milliseconds(60000)));
    EXPECT_EQ(out.ending, Ending::Exited);
    EXPECT_EQ(out.status, 0);
    EXPECT_EQ(out.output, big);
}

TEST(ChildProcess, AnAbortInTheChild_IsReportedWithWhatItPrinted) {
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    const ChildOutcome out = runInChildProcess(
        [](int) {
            std::fputs("assertion failed", stderr);
            std::fflush(stderr);
            std::puts(" and so on");
            std::fflush(stdout);
            std::abort();
        },
        limitsOf(milliseconds(60000)));
    // Nothing reached this process's own stdout or stderr.
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(out.ending, Ending::Signalled);
    EXPECT_EQ(out.status, SIGABRT);
    EXPECT_EQ(out.messages, "assertion failed and so on\n");
    EXPECT_EQ(describeSignal(SIGABRT).rfind("signal 6", 0), 0u) << describeSignal(SIGABRT);
}

// A handler of this process (a crash reporter, say) does not run in the child: there an
// abort is a death by SIGABRT, whatever this process does with the signal.
TEST(ChildProcess, AnAbortInTheChild_DoesNotRunThisProcesssHandler) {
    struct sigaction handler {
    }, before{};
    handler.sa_handler = [](int) { ::_exit(42); };
    sigemptyset(&handler.sa_mask);
    ASSERT_EQ(::sigaction(SIGABRT, &handler, &before), 0);
    const ChildOutcome out =
        runInChildProcess([](int) { std::abort(); }, limitsOf(milliseconds(60000)));
    ::sigaction(SIGABRT, &before, nullptr);
    EXPECT_EQ(out.ending, Ending::Signalled);
    EXPECT_EQ(out.status, SIGABRT);
}

// The child waits for a signal that never comes (pause(), not a sleep): only the parent's
// deadline can end it, on any machine at any load.
TEST(ChildProcess, AChildThatNeverFinishes_IsKilledAtTheDeadline) {
    const ChildOutcome out = runInChildProcess(
        [](int fd) {
            writeAllTo(fd, "started", 7);
            for (;;) ::pause();
        },
        limitsOf(milliseconds(200)));
    EXPECT_EQ(out.ending, Ending::TimedOut);
}

TEST(ChildProcess, OutputBeyondTheLimit_StopsTheChild) {
    const ChildOutcome out = runInChildProcess(
        [](int fd) {
            const std::string chunk(4096, 'y');
            for (;;) writeAllTo(fd, chunk.data(), chunk.size());  // Without end.
        },
        limitsOf(milliseconds(60000), 100000));
    EXPECT_EQ(out.ending, Ending::OutputTooLarge);
    EXPECT_LE(out.output.size(), 100000u);
}

TEST(ChildProcess, Cancel_StopsTheChild) {
    std::atomic<bool> cancel{true};
    ChildLimits limits = limitsOf(milliseconds(60000));
    limits.cancel = &cancel;
    const ChildOutcome out = runInChildProcess(
        [](int) {
            for (;;) ::pause();
        },
        limits);
    EXPECT_EQ(out.ending, Ending::Cancelled);
}

TEST(ChildProcess, AnAllocationBeyondTheMemoryBudget_FailsInTheChild) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "a sanitizer's allocator reserves its address space up front and dies "
                    "when a fresh mapping fails";
#endif
    // 512 MiB is far beyond the 64 MiB budget; in this process it succeeds.
    const std::size_t bytes = std::size_t(512) << 20;
    const ChildOutcome out = runInChildProcess(
        [&](int fd) {
            allocated = std::malloc(bytes);
            const char verdict = allocated ? 'y' : 'n';
            writeAllTo(fd, &verdict, 1);
        },
        limitsOf(milliseconds(60000)));
    EXPECT_EQ(out.ending, Ending::Exited);
    EXPECT_EQ(out.output, "n");
    allocated = std::malloc(bytes);
    EXPECT_NE(allocated, nullptr);
    std::free(allocated);
}

}  // namespace
}  // namespace rs
