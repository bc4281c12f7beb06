// What /proc/self/smaps says of the mapping that holds an address, for huge-page tests.
#pragma once

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace rs::test {

/// Whether the kernel gives transparent huge pages at all (not "[never]", not built without).
inline bool kernelHasHugePages() {
    std::ifstream enabled("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string mode;
    return std::getline(enabled, mode) && mode.find("[never]") == std::string::npos;
}

/// The VmFlags line of /proc/self/smaps for the mapping that holds `p` ("" if none). " hg":
/// the mapping asked for huge pages (MADV_HUGEPAGE), which Debian's THP "madvise" default
/// requires before it gives any.
inline std::string vmFlagsOf(const void* p) {
    std::ifstream smaps("/proc/self/smaps");
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> lo >> dash >> hi && dash == '-' &&
            line.find(' ') != std::string::npos && line.find(':') > line.find(' ')) {
            inside = lo <= at && at < hi;
            continue;
        }
        if (inside && line.rfind("VmFlags:", 0) == 0) return line;
    }
    return "";
}

}  // namespace rs::test
