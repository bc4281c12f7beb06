// Unique temporary names beside a target file (a per-process random seed and a counter),
// and the write-then-rename that uses them.
#include "image/temporary_file.h"

#include <atomic>
#include <random>
#include <string>

namespace rs {

std::filesystem::path temporarySibling(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    static const unsigned seed = std::random_device{}();
    // Built with append rather than "." + string: GCC 12 warns (-Wrestrict) on that form.
    std::string name(".");
    name.append(path.stem().string());
    name.append(".tmp-");
    name.append(std::to_string(seed));
    name.append("-");
    name.append(std::to_string(counter++));
    name.append(path.extension().string());
    std::filesystem::path tmp = path;
    tmp.replace_filename(name);
    return tmp;
}

bool writeAtomically(const std::string& path,
                     const std::function<bool(const std::filesystem::path& tmp)>& write,
                     std::string& error) {
    const std::filesystem::path target(path);
    const std::filesystem::path tmp = temporarySibling(target);
    std::error_code ec;
    if (!write(tmp)) {
        std::filesystem::remove(tmp, ec);
        return false;
    }
    std::filesystem::rename(tmp, target, ec);
    if (ec) {
        error = "cannot write '" + path + "': " + ec.message();
        std::filesystem::remove(tmp, ec);
        return false;
    }
    return true;
}

}  // namespace rs
