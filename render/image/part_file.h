// Part files: one band of a final image in a linear float EXR that says where it belongs (data
// window inside the display window) and what it was rendered from (a render fingerprint).
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "image/image_part.h"
#include "scene/document.h"

namespace rs {

/// What a part file says about itself (its EXR header).
struct PartHeader {
    ImagePart part;
    int fullWidth = 0;  ///< The whole image (display window).
    int fullHeight = 0;
    RowRange rows;                     ///< Rows of the whole image this part holds (data window).
    std::string fingerprint;           ///< renderFingerprint of the scene, settings and engine.
    ToneMap tonemap = ToneMap::Clamp;  ///< For a merge into a display format.
    float exposure = 0.0f;
    bool hasIds = false;  ///< An "id" channel (uint32 object ids) follows R, G, B.
};

/// Writes `band` (header.rows of the image, full width) as float RGB EXR, with `ids` as a
/// uint32 channel when not empty, atomically. False with `error` naming the path otherwise.
bool writePart(const std::string& path, const PartHeader& header, const ImageRgb& band,
               const std::vector<ObjectId>& ids, std::string& error);

/// Reads and checks a part file's header (a RayStudio part, float RGB, its data window the
/// rows its part number gives, a size within the image limits). False with `error` otherwise.
bool readPartHeader(const std::string& path, PartHeader& header, std::string& error);

/// Reads a part's pixels into rows header.rows of `image` (fullWidth wide, at least
/// header.rows.end rows) and, when `ids` is given and the part has them, its ids likewise.
bool readPartPixels(const std::string& path, const PartHeader& header, ImageRgb& image,
                    std::vector<ObjectId>* ids, std::string& error);

}  // namespace rs
