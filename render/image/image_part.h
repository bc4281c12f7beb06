// Parts of a final image for rendering on several machines: part I of N is a band of rows.
#pragma once

#include <string>

namespace rs {

/// Most parts one image may be cut into (each part is at least one row).
inline constexpr int kMaxImageParts = 4096;

/// Part `index` (0-based) of `count` parts of an image.
struct ImagePart {
    int index = 0;
    int count = 1;
    bool operator==(const ImagePart&) const = default;
};

/// Rows [begin, end) of an image.
struct RowRange {
    int begin = 0;
    int end = 0;
    bool operator==(const RowRange&) const = default;
};

/// The rows part `part` covers in an image `height` rows tall: [I*H/N, (I+1)*H/N), so the
/// parts tile the image in order and differ in height by at most one row.
RowRange partRows(const ImagePart& part, int height);

/// Empty when `part` is a part of an image `height` rows tall; otherwise a message naming what
/// is wrong (index outside [0, N), N over kMaxImageParts or over the image's rows).
std::string partError(const ImagePart& part, int height);

/// Parses "I/N" (two whole numbers); false with `error` naming the text otherwise. Ranges are
/// checked by partError, which knows the image.
bool parseImagePart(const std::string& text, ImagePart& part, std::string& error);

}  // namespace rs
