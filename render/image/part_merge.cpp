// Part-set checks (same render, complete, no duplicates) and assembly into one image.
#include "image/part_merge.h"

#include <map>

namespace rs {

std::string partSetError(const std::vector<std::string>& paths,
                         const std::vector<PartHeader>& headers) {
    if (headers.empty()) return "no parts given";
    std::string error;
    auto problem = [&](const std::string& line) { error += (error.empty() ? "" : "\n") + line; };
    const PartHeader& first = headers.front();
    const std::string count = std::to_string(first.part.count);
    std::map<int, std::size_t> byIndex;  // part index -> the first path that has it
    for (std::size_t i = 0; i < headers.size(); ++i) {
        const PartHeader& h = headers[i];
        const std::string name = std::to_string(h.part.index) + "/" + std::to_string(h.part.count);
        if (h.fingerprint != first.fingerprint) {
            problem("'" + paths[i] + "' belongs to another scene or other settings (fingerprint " +
                    h.fingerprint + ", '" + paths[0] + "' has " + first.fingerprint + ")");
            continue;
        }
        if (h.part.count != first.part.count || h.fullWidth != first.fullWidth ||
            h.fullHeight != first.fullHeight) {
            problem("'" + paths[i] + "' is part " + name + " of a " + std::to_string(h.fullWidth) +
                    "x" + std::to_string(h.fullHeight) + " image, '" + paths[0] + "' part of " +
                    count + " of a " + std::to_string(first.fullWidth) + "x" +
                    std::to_string(first.fullHeight) + " image");
            continue;
        }
        if (h.hasIds != first.hasIds) {
            problem("'" + paths[i] + "' " + (h.hasIds ? "has" : "has no") + " id channel, '" +
                    paths[0] + "' " + (first.hasIds ? "has" : "has none"));
            continue;
        }
        auto [it, fresh] = byIndex.emplace(h.part.index, i);
        if (!fresh)
            problem("part " + name + " is given twice: '" + paths[it->second] + "' and '" +
                    paths[i] + "'");
    }
    if (!error.empty()) return error;
    std::string missing;
    int missingCount = 0;
    for (int p = 0; p < first.part.count; ++p) {
        if (byIndex.count(p)) continue;
        if (++missingCount <= 20) missing += (missing.empty() ? "" : ", ") + std::to_string(p);
    }
    if (missingCount > 0)
        problem(std::to_string(missingCount) + " of " + count + " parts missing: " + missing +
                (missingCount > 20 ? ", ..." : "") + " (each of 0.." +
                std::to_string(first.part.count - 1) + " is needed once)");
    return error;
}

bool mergeParts(const std::vector<std::string>& paths, MergedImage& merged, std::string& error) {
    std::vector<PartHeader> headers(paths.size());
    std::string unreadable;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        std::string why;
        if (!readPartHeader(paths[i], headers[i], why))
            unreadable += (unreadable.empty() ? "" : "\n") + why;
    }
    if (!unreadable.empty()) {
        error = unreadable;
        return false;
    }
    if (error = partSetError(paths, headers); !error.empty()) return false;
    MergedImage result;
    result.header = headers.front();
    result.image = ImageRgb::uninitialized(result.header.fullWidth, result.header.fullHeight);
    if (result.header.hasIds) result.ids.resize(result.image.pixels.size());
    for (std::size_t i = 0; i < paths.size(); ++i)
        if (!readPartPixels(paths[i], headers[i], result.image,
                            result.header.hasIds ? &result.ids : nullptr, error))
            return false;
    merged = std::move(result);
    return true;
}

}  // namespace rs
