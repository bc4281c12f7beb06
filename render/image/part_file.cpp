// Part files through OpenImageIO's EXR writer: data window, display window and raystudio:
// metadata carry the part's place and origin.
#include "image/part_file.h"

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <filesystem>
#include <system_error>

#include "image/temporary_file.h"

namespace rs {

namespace {

namespace fs = std::filesystem;

constexpr const char* kPartKey = "raystudio:part";
constexpr const char* kFingerprintKey = "raystudio:fingerprint";
constexpr const char* kToneMapKey = "raystudio:tonemap";
constexpr const char* kExposureKey = "raystudio:exposure";

std::string cause(const std::string& message) {
    return message.empty() ? std::string("unknown OpenImageIO error") : message;
}

/// One pixel as the file stores it when it has ids: three floats, then the id.
struct PixelWithId {
    Color color;
    ObjectId id;
};
static_assert(sizeof(PixelWithId) == 4 * sizeof(float));

bool writeFile(const fs::path& tmp, const std::string& path, const PartHeader& header,
               const ImageRgb& band, const std::vector<ObjectId>& ids, std::string& error) {
    auto out = OIIO::ImageOutput::create("exr");
    if (!out) {
        error = "cannot write '" + path + "': " + cause(OIIO::geterror());
        return false;
    }
    const bool withIds = !ids.empty();
    OIIO::ImageSpec spec(band.width, band.height, withIds ? 4 : 3, OIIO::TypeDesc::FLOAT);
    spec.y = header.rows.begin;
    spec.full_x = 0, spec.full_y = 0;
    spec.full_width = header.fullWidth, spec.full_height = header.fullHeight;
    spec.channelnames = {"R", "G", "B"};
    if (withIds) {
        spec.channelnames.push_back("id");
        spec.channelformats = {OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::FLOAT,
                               OIIO::TypeDesc::UINT32};
    }
    spec.attribute("oiio:ColorSpace", "Linear");
    spec.attribute(kPartKey,
                   std::to_string(header.part.index) + "/" + std::to_string(header.part.count));
    spec.attribute(kFingerprintKey, header.fingerprint);
    spec.attribute(kToneMapKey, int(header.tonemap));
    spec.attribute(kExposureKey, header.exposure);
    if (!out->open(tmp.string(), spec)) {
        error = "cannot write '" + path + "': " + cause(out->geterror());
        return false;
    }
    bool ok;
    if (withIds) {
        std::vector<PixelWithId> pixels(band.pixels.size());
        for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = {band.pixels[i], ids[i]};
        ok = out->write_image(OIIO::TypeDesc::UNKNOWN, pixels.data());  // native formats
    } else {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, band.pixels.data());
    }
    if (!ok || !out->close()) {
        error = "cannot write '" + path + "': " + cause(out->geterror());
        return false;
    }
    return true;
}

}  // namespace

bool writePart(const std::string& path, const PartHeader& header, const ImageRgb& band,
               const std::vector<ObjectId>& ids, std::string& error) {
    if (band.width != header.fullWidth || band.height != header.rows.end - header.rows.begin ||
        (!ids.empty() && ids.size() != band.pixels.size())) {
        error = "cannot write '" + path + "': the band's size does not match its part";
        return false;
    }
    return writeAtomically(
        path, [&](const fs::path& tmp) { return writeFile(tmp, path, header, band, ids, error); },
        error);
}

bool readPartHeader(const std::string& path, PartHeader& header, std::string& error) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        error = "cannot read '" + path + "': " + cause(OIIO::geterror());
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    auto refuse = [&](const std::string& why) {
        error = "'" + path + "' " + why;
        return false;
    };
    const std::string partText = spec.get_string_attribute(kPartKey);
    if (partText.empty() || spec.get_string_attribute(kFingerprintKey).empty())
        return refuse(
            "is not a RayStudio part (no raystudio:part metadata; write parts with "
            "render --tile I/N)");
    PartHeader h;
    std::string why;
    if (!parseImagePart(partText, h.part, why)) return refuse("has a bad raystudio:part: " + why);
    h.fingerprint = spec.get_string_attribute(kFingerprintKey);
    h.fullWidth = spec.full_width, h.fullHeight = spec.full_height;
    if (const std::string size = imageSizeError(h.fullWidth, h.fullHeight); !size.empty())
        return refuse("has a bad display window: " + size);
    if (const std::string bad = partError(h.part, h.fullHeight); !bad.empty())
        return refuse("has a bad raystudio:part: " + bad);
    const int tonemap = spec.get_int_attribute(kToneMapKey, -1);
    if (tonemap < int(ToneMap::Clamp) || tonemap > int(ToneMap::Aces))
        return refuse("has a bad raystudio:tonemap");
    h.tonemap = ToneMap(tonemap);
    h.exposure = spec.get_float_attribute(kExposureKey, 0.0f);
    h.rows = partRows(h.part, h.fullHeight);
    if (spec.full_x != 0 || spec.full_y != 0 || spec.x != 0 || spec.width != h.fullWidth ||
        spec.y != h.rows.begin || spec.height != h.rows.end - h.rows.begin || spec.depth != 1)
        return refuse("does not hold the rows [" + std::to_string(h.rows.begin) + ", " +
                      std::to_string(h.rows.end) + ") that part " + partText + " of a " +
                      std::to_string(h.fullWidth) + "x" + std::to_string(h.fullHeight) +
                      " image covers");
    if (spec.nchannels < 3 || spec.nchannels > 4 ||
        spec.channelformat(0) != OIIO::TypeDesc::FLOAT ||
        spec.channelformat(1) != OIIO::TypeDesc::FLOAT ||
        spec.channelformat(2) != OIIO::TypeDesc::FLOAT)
        return refuse("is not float RGB (parts keep the renderer's 32-bit floats)");
    h.hasIds = spec.nchannels == 4;
    if (h.hasIds &&
        (spec.channelnames[3] != "id" || spec.channelformat(3) != OIIO::TypeDesc::UINT32))
        return refuse("has a fourth channel that is not the uint32 'id' channel");
    header = std::move(h);
    return true;
}

bool readPartPixels(const std::string& path, const PartHeader& header, ImageRgb& image,
                    std::vector<ObjectId>* ids, std::string& error) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        error = "cannot read '" + path + "': " + cause(OIIO::geterror());
        return false;
    }
    const std::size_t first = std::size_t(header.rows.begin) * std::size_t(image.width);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, &image.pixels[first])) {
        error = "cannot read '" + path + "': " + cause(in->geterror());
        return false;
    }
    if (ids && header.hasIds &&
        !in->read_image(0, 0, 3, 4, OIIO::TypeDesc::UINT32, &(*ids)[first])) {
        error = "cannot read '" + path + "': " + cause(in->geterror());
        return false;
    }
    return true;
}

}  // namespace rs
