// Input file guards: stat() before open, so directories, devices and FIFOs never block a read.
#include "core/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace rs {

namespace {
namespace fs = std::filesystem;

std::string errnoText(const char* fallback) {
    return errno != 0 ? std::error_code(errno, std::generic_category()).message() : fallback;
}

const char* describeNonRegular(fs::file_type type) {
    switch (type) {
        case fs::file_type::directory:
            return "is a directory, not a regular file";
        case fs::file_type::character:
            return "is a character device, not a regular file";
        case fs::file_type::block:
            return "is a block device, not a regular file";
        case fs::file_type::fifo:
            return "is a FIFO (named pipe), not a regular file";
        case fs::file_type::socket:
            return "is a socket, not a regular file";
        default:
            return "is not a regular file";
    }
}
}  // namespace

FileStamp fileStampOf(const std::string& path) {
    FileStamp stamp;
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return stamp;
    stamp.exists = true;
    stamp.modified = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
    stamp.size = static_cast<std::uintmax_t>(st.st_size);
    return stamp;
}

std::string describeByteCount(std::uintmax_t bytes) {
    static const char* const units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    double value = double(bytes);
    int unit = 0;
    while (value >= 1024.0 && unit < 6) {
        value /= 1024.0;
        ++unit;
    }
    char buf[32];
    if (unit == 0 || value == double(std::uintmax_t(value)))
        std::snprintf(buf, sizeof buf, "%.0f %s", value, units[unit]);
    else
        std::snprintf(buf, sizeof buf, "%.1f %s", value, units[unit]);
    return buf;
}

std::string checkInputFile(const std::string& path, std::uintmax_t limit, std::uintmax_t* size) {
    // status() and file_size() are stat(): nothing is opened, so a FIFO cannot block here
    // and a device is never read from.
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec) return ec.message();
    if (!fs::is_regular_file(status)) return describeNonRegular(status.type());
    const std::uintmax_t bytes = fs::file_size(path, ec);
    if (ec) return ec.message();
    if (bytes > limit)
        return "is " + describeByteCount(bytes) + ", more than the " + describeByteCount(limit) +
               " limit";
    if (size) *size = bytes;
    return {};
}

bool readInputFile(const std::string& path, std::uintmax_t limit, std::string& text,
                   std::string& error) {
    std::uintmax_t size = 0;
    error = checkInputFile(path, limit, &size);
    if (!error.empty()) return false;
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = errnoText("cannot open");
        return false;
    }
    // Read in chunks up to the limit: the file may have grown since stat(), and procfs-like
    // files report a size of 0 and still have contents.
    text.clear();
    text.reserve(static_cast<std::size_t>(size));
    char chunk[1 << 16];
    while (in) {
        errno = 0;
        in.read(chunk, sizeof chunk);
        if (in.bad()) {
            error = "read error: " + errnoText("the file could not be read");
            return false;
        }
        text.append(chunk, static_cast<std::size_t>(in.gcount()));
        if (text.size() > limit) {
            error = "grew beyond the " + describeByteCount(limit) + " limit while being read";
            return false;
        }
    }
    return true;
}

}  // namespace rs
