// Image files through OpenImageIO: display formats tone-mapped to 8-bit sRGB, HDR formats linear.
#include "image/image_io.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <system_error>
#include <vector>

#include "image/temporary_file.h"
#include "image/tonemap.h"

namespace rs {

namespace {

namespace fs = std::filesystem;

/// How a file extension is written.
enum class FileKind { Display8, LinearFloat };

constexpr const char* kSupportedExtensions = ".png .jpg .jpeg .tif .tiff .exr .hdr";

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool kindForExtension(const std::string& ext, FileKind& kind) {
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".tif" || ext == ".tiff") {
        kind = FileKind::Display8;
        return true;
    }
    if (ext == ".exr" || ext == ".hdr") {
        kind = FileKind::LinearFloat;
        return true;
    }
    return false;
}

std::string oiioError(const std::string& message) {
    return message.empty() ? std::string("unknown OpenImageIO error") : message;
}

/// The pixels in the layout and type the file will hold.
std::vector<uint8_t> display8Pixels(const ImageRgb& image, ToneMap op, float exposure) {
    std::vector<uint8_t> out(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        toDisplay8(image.pixels[i], op, exposure, &out[3 * i]);
    return out;
}

bool writeWithOiio(const std::string& path, const fs::path& tmp, const ImageRgb& image,
                   FileKind kind, ToneMap op, float exposure, std::string& error) {
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) {
        error = "cannot write '" + path + "': " + oiioError(OIIO::geterror());
        return false;
    }
    const bool display = kind == FileKind::Display8;
    OIIO::ImageSpec spec(image.width, image.height, 3,
                         display ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.attribute("oiio:ColorSpace", display ? "sRGB" : "Linear");
    if (lowerExtension(path) == ".jpg" || lowerExtension(path) == ".jpeg")
        spec.attribute("Compression",
                       "jpeg:95");  // OIIO's default 98 is larger for no visible gain
    if (!out->open(tmp.string(), spec)) {
        error = "cannot write '" + path + "': " + oiioError(out->geterror());
        return false;
    }
    bool ok;
    if (display) {
        const std::vector<uint8_t> bytes = display8Pixels(image, op, exposure);
        ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    } else {
        // glm::vec3 is three tightly packed floats, so the pixel vector is already RGB float.
        static_assert(sizeof(Color) == 3 * sizeof(float));
        ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    }
    if (!ok) {
        error = "cannot write '" + path + "': " + oiioError(out->geterror());
        out->close();
        return false;
    }
    if (!out->close()) {
        error = "cannot write '" + path + "': " + oiioError(out->geterror());
        return false;
    }
    return true;
}

}  // namespace

std::string imageFormatError(const std::string& path) {
    FileKind kind;
    const std::string ext = lowerExtension(path);
    if (kindForExtension(ext, kind)) return {};
    return "cannot write '" + path + "': " +
           (ext.empty() ? std::string("no file extension")
                        : "unsupported extension '" + ext + "'") +
           " (supported: " + kSupportedExtensions + ")";
}

bool writeImage(const std::string& path, const ImageRgb& image, ToneMap op, float exposure,
                std::string& error) {
    FileKind kind;
    if (!kindForExtension(lowerExtension(path), kind)) {
        error = imageFormatError(path);
        return false;
    }
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != std::size_t(image.width) * std::size_t(image.height)) {
        error =
            "cannot write '" + path + "': the image is empty or its size does not match its pixels";
        return false;
    }

    // Write next to the target and rename over it, so readers and crashes never see a
    // half-written image and a failed write leaves any previous file untouched.
    return writeAtomically(
        path,
        [&](const fs::path& tmp) {
            return writeWithOiio(path, tmp, image, kind, op, exposure, error);
        },
        error);
}

bool readImage(const std::string& path, ImageRgb& image, std::string& error) {
    // Keep straight (unassociated) alpha as stored: we drop alpha, and premultiplying first
    // would darken semi-transparent pixels.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        error = "cannot read '" + path + "': " + oiioError(OIIO::geterror());
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.depth > 1 || spec.nchannels < 1) {
        error = "cannot read '" + path + "': not a 2D image with colour channels";
        return false;
    }
    // One channel is grey (replicated below); with three or more, the first three are RGB.
    const int channels = spec.nchannels >= 3 ? 3 : 1;
    std::vector<float> data(std::size_t(spec.width) * std::size_t(spec.height) *
                            std::size_t(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data())) {
        error = "cannot read '" + path + "': " + oiioError(in->geterror());
        return false;
    }
    // Integer files are display-referred (sRGB) unless they say they are linear; float
    // files (EXR, HDR, float TIFF) already hold linear radiance.
    const std::string colorSpace = spec.get_string_attribute("oiio:ColorSpace");
    const bool isFloat = spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                         spec.format.basetype == OIIO::TypeDesc::HALF ||
                         spec.format.basetype == OIIO::TypeDesc::DOUBLE;
    const bool decode = !isFloat && !OIIO::Strutil::iequals(colorSpace, "linear");

    ImageRgb result(spec.width, spec.height);
    for (std::size_t i = 0; i < result.pixels.size(); ++i) {
        const float* p = &data[i * std::size_t(channels)];
        Color c = channels == 3 ? Color(p[0], p[1], p[2]) : Color(p[0]);
        if (decode) c = Color(srgbDecode(c.x), srgbDecode(c.y), srgbDecode(c.z));
        result.pixels[i] = c;
    }
    image = std::move(result);
    return true;
}

}  // namespace rs
