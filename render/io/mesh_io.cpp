// Loading a mesh: the guards here, the assimp import (io/mesh_import.cpp) in a child process
// under a memory and time budget, the triangles back through the mesh wire format.
#include "io/mesh_io.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <system_error>

#include "core/input_file.h"
#include "io/asset_content.h"
#include "io/child_process.h"
#include "io/mesh_header_check.h"
#include "io/mesh_import.h"
#include "io/mesh_wire.h"

namespace rs {

namespace {
namespace fs = std::filesystem;

/// Set in the import child by its new-handler: an allocation failed, so the error is the
/// budget's, whatever assimp made of the std::bad_alloc.
std::atomic<bool> childOutOfMemory{false};

/// The import child's work: assimp, then the result (mesh or message) into `fd`.
void importIntoPipe(int fd, const std::string& file, bool smoothNormals,
                    std::uintmax_t memoryBytes) {
    std::set_new_handler([] {
        childOutOfMemory = true;
        std::set_new_handler(nullptr);
        throw std::bad_alloc();
    });
    MeshLoadResult result;
    try {
        result = importMeshWithAssimp(file, smoothNormals);
    } catch (const std::bad_alloc&) {
        childOutOfMemory = true;
    }
    if (childOutOfMemory) {
        result.mesh.reset();  // Its memory is what the message below needs.
        writeMeshWireError(fd, "the import needed more than its " + describeByteCount(memoryBytes) +
                                   " memory budget");
    } else if (!result.ok()) {
        writeMeshWireError(fd, result.error);
    } else {
        writeMeshWire(fd, *result.mesh, result.asset ? *result.asset : AssetContent{},
                      fs::path(file).parent_path().string());
    }
}

std::string describeSeconds(std::chrono::milliseconds time) {
    const double seconds = double(time.count()) / 1000.0;
    char text[32];
    std::snprintf(text, sizeof text, seconds >= 10 ? "%.0f s" : "%.3g s", seconds);
    return text;
}

/// ": " and the first line with words that the child printed (assimp's assertion text, or a
/// sanitizer's report under its rule of '=' signs), or "".
std::string firstMessage(const ChildOutcome& outcome) {
    constexpr std::size_t kLongest = 300;
    std::size_t start = 0;
    while (start < outcome.messages.size()) {
        const std::size_t end =
            std::min(outcome.messages.find('\n', start), outcome.messages.size());
        std::string line = outcome.messages.substr(start, end - start);
        start = end + 1;
        if (std::none_of(line.begin(), line.end(), [](unsigned char c) { return std::isalpha(c); }))
            continue;
        while (std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
        if (line.size() > kLongest) line = line.substr(0, kLongest) + "...";
        return ": " + line;
    }
    return "";
}

/// Why the child's outcome is not a mesh, or "" when its output is to be decoded; `crashed`
/// says whether the child itself failed (a signal other than its budget's, or an error exit).
std::string describeFailure(const ChildOutcome& outcome, std::uintmax_t memoryBytes,
                            std::chrono::milliseconds wallTime, std::chrono::milliseconds cpuTime,
                            bool& crashed) {
    crashed = false;
    using Ending = ChildOutcome::Ending;
    switch (outcome.ending) {
        case Ending::NotStarted:
            return "cannot run the import: " + outcome.problem;
        case Ending::TimedOut:
            return "the import took longer than its " + describeSeconds(wallTime) +
                   " budget and was stopped";
        case Ending::Cancelled:
            return "the import was cancelled";
        case Ending::OutputTooLarge:
            return "the imported mesh is larger than its " + describeByteCount(memoryBytes) +
                   " memory budget";
        case Ending::Signalled:
            if (outcome.status == SIGXCPU)
                return "the import used more than its " + describeSeconds(cpuTime) +
                       " of processor time and was stopped";
            if (outcome.status == SIGKILL)
                return "the import process was killed (" + describeSignal(SIGKILL) +
                       "), probably by the system for lack of memory";
            crashed = true;
            return "assimp crashed while reading it (" + describeSignal(outcome.status) + ")" +
                   firstMessage(outcome);
        case Ending::Exited:
            crashed = outcome.status != 0;
            if (crashed)
                return "the import process failed (exit status " + std::to_string(outcome.status) +
                       ")" + firstMessage(outcome);
            return "";
    }
    return "";
}
}  // namespace

std::uintmax_t defaultMeshImportMemory(std::uintmax_t fileBytes) {
    // assimp's peak, measured on 1M-triangle files: 16.9 bytes per byte of an OBJ (37.6 MB,
    // 606 MiB resident), 40.5 per byte of a binary STL (50 MB, 1.93 GiB); the limit is address
    // space, which runs above what is resident, so the budget leaves room over the worst.
    const std::uintmax_t wanted = (std::uintmax_t(512) << 20) + 64 * fileBytes;
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return wanted;
    return std::min(wanted, std::uintmax_t(pages) * std::uintmax_t(pageSize));
}

std::chrono::milliseconds defaultMeshImportTime(std::uintmax_t fileBytes) {
    return std::chrono::milliseconds(10000 + fileBytes / ((std::uintmax_t(10) << 20) / 1000));
}

MeshLoadResult loadMesh(const std::string& path, bool smoothNormals,
                        const MeshImportOptions& options) {
    MeshLoadResult result;
    std::error_code ec;
    fs::path file = fs::absolute(fs::path(path), ec);
    if (ec) file = path;
    file = file.lexically_normal();
    auto fail = [&](const std::string& why) {
        result.error = "mesh \"" + file.string() + "\": " + why;
        return result;
    };
    if (!fs::exists(file, ec)) return fail("file not found");
    // Before anything is opened: directories, devices, FIFOs and oversized files are refused.
    std::uintmax_t size = 0;
    if (std::string why = checkInputFile(file.string(), kMaxMeshFileBytes, &size); !why.empty())
        return fail(why);
    if (!std::ifstream(file, std::ios::binary))
        return fail("cannot open: " + std::error_code(errno, std::generic_category()).message());
    // A header that lies about its counts makes assimp allocate for them first.
    if (std::string why = checkMeshHeader(file.string(), size); !why.empty()) return fail(why);

    ChildLimits limits;
    limits.memoryBytes = options.memoryBytes.value_or(defaultMeshImportMemory(size));
    if (options.wallTime) {
        limits.wallTime = *options.wallTime;
    } else {
        // The work is bounded by processor time; the wall clock only stops an import that
        // waits (a blocked read), so a loaded machine, where an import gets a fraction of a
        // core, does not refuse a mesh it would load on a quiet one.
        limits.cpuTime = defaultMeshImportTime(size);
        limits.wallTime = *limits.cpuTime * kMeshImportWallFactor;
    }
    // The child held the mesh in its budget, so its bytes cannot be more (plus a header).
    limits.maxOutputBytes = std::size_t(std::min<std::uintmax_t>(
        limits.memoryBytes + 4096, std::numeric_limits<std::size_t>::max()));
    limits.cancel = options.cancel;
    const ChildOutcome outcome = runInChildProcess(
        [&](int fd) { importIntoPipe(fd, file.string(), smoothNormals, limits.memoryBytes); },
        limits);
    bool crashed = false;
    if (std::string why = describeFailure(outcome, limits.memoryBytes, limits.wallTime,
                                          limits.cpuTime.value_or(limits.wallTime), crashed);
        !why.empty()) {
        if (crashed) result.childMessages = outcome.messages;
        return fail(why);
    }
    MeshLoadResult decoded = decodeMeshWire(outcome.output, file.string());
    if (!decoded.ok()) return fail(decoded.error);
    return decoded;
}

}  // namespace rs
