// Band geometry of image parts and the "I/N" notation the command line uses for them.
#include "image/image_part.h"

#include <charconv>
#include <cstdint>

namespace rs {

RowRange partRows(const ImagePart& part, int height) {
    auto edge = [&](int i) { return int(int64_t(i) * int64_t(height) / int64_t(part.count)); };
    return {edge(part.index), edge(part.index + 1)};
}

std::string partError(const ImagePart& part, int height) {
    if (part.count < 1 || part.count > kMaxImageParts)
        return "the number of parts must be between 1 and " + std::to_string(kMaxImageParts) +
               ", got " + std::to_string(part.count);
    if (part.count > height)
        return "an image " + std::to_string(height) + " rows tall has at most " +
               std::to_string(height) + " parts (one row each), got " + std::to_string(part.count);
    if (part.index < 0 || part.index >= part.count)
        return "part index must be between 0 and " + std::to_string(part.count - 1) + ", got " +
               std::to_string(part.index);
    return {};
}

bool parseImagePart(const std::string& text, ImagePart& part, std::string& error) {
    const std::size_t slash = text.find('/');
    auto number = [](const char* first, const char* last, int& value) {
        auto [ptr, ec] = std::from_chars(first, last, value);
        return first != last && ec == std::errc() && ptr == last;
    };
    const char* begin = text.data();
    const char* end = begin + text.size();
    ImagePart parsed;
    if (slash == std::string::npos || !number(begin, begin + slash, parsed.index) ||
        !number(begin + slash + 1, end, parsed.count)) {
        error = "expects I/N (part I of N, 0-based), got '" + text + "'";
        return false;
    }
    part = parsed;
    return true;
}

}  // namespace rs
