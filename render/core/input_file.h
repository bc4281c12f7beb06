// Guards on the files the program reads: regular files below a documented size, read whole.
#pragma once

#include <cstdint>
#include <string>

namespace rs {

/// Largest scene file read (scenes/FORMAT.md, "Limits"): far beyond any hand-made or saved scene.
inline constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t(256) << 20;
/// Largest mesh file read: 2 GiB, about 60 M triangles of binary PLY or STL.
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(2) << 30;

/// Checks, without opening it, that `path` names a regular file of at most `limit` bytes.
/// Returns "" when it does (and stores its size in `size`), else why not ("is a directory",
/// "is a FIFO", "is 3.1 GiB, more than the 2 GiB limit", "No such file or directory").
std::string checkInputFile(const std::string& path, std::uintmax_t limit,
                           std::uintmax_t* size = nullptr);

/// Reads the whole of `path` into `text` after checkInputFile. On failure returns false with
/// `error` saying why; a failing read is reported as one ("Input/output error"), never as
/// the shorter text it left behind.
bool readInputFile(const std::string& path, std::uintmax_t limit, std::string& text,
                   std::string& error);

/// What a file on disk was when looked at: its modification time and size. Equal stamps mean
/// the file is taken to be unchanged (a re-saved image gets a new one); a missing file has
/// `exists` false.
struct FileStamp {
    bool exists = false;
    long long modified = 0;  ///< Nanoseconds since the epoch.
    std::uintmax_t size = 0;
    bool operator==(const FileStamp&) const = default;
};
/// The stamp of `path`, from one stat() (it runs per textured material on every snapshot
/// compile, i.e. every drag step).
FileStamp fileStampOf(const std::string& path);

/// "512 B", "3.5 MiB", "2 GiB": a byte count for messages.
std::string describeByteCount(std::uintmax_t bytes);

}  // namespace rs
