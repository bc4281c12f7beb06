// makeThumbnail: OpenImageIO's ImageBuf and ImageBufAlgo::resize (a box filter), then 8-bit sRGB.
#include "texture/thumbnail.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace rs {

namespace {

float srgbEncode(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

Thumbnail failure(const std::string& path, const std::string& why) {
    Thumbnail t;
    t.error = "cannot make a preview of image file \"" + path + "\": " + why;
    return t;
}

}  // namespace

Thumbnail makeThumbnail(const std::string& path, int maxSide) {
    if (maxSide <= 0) return failure(path, "the preview size must be positive");
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return failure(path, "no such file");
    if (!std::filesystem::is_regular_file(path, ec)) return failure(path, "not a regular file");

    OIIO::ImageBuf probe(path);
    if (!probe.init_spec(path, 0, 0)) {
        std::string why = probe.geterror();
        return failure(path, why.empty() ? "unknown format or corrupt header" : why);
    }
    // The smallest MIP level that still covers the preview (level 0 for a plain image).
    int level = 0;
    for (int l = 1; l < probe.nmiplevels(); ++l) {
        OIIO::ImageBuf next(path, 0, l);
        if (!next.init_spec(path, 0, l)) break;
        if (std::max(next.spec().width, next.spec().height) < maxSide) break;
        level = l;
    }
    OIIO::ImageBuf src(path, 0, level);
    if (!src.read(0, level, /*force=*/true)) {
        std::string why = src.geterror();
        return failure(path, why.empty() ? "the pixels could not be read" : why);
    }
    const OIIO::ImageSpec& spec = src.spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        return failure(path, "the image has no pixels");
    const bool linear = spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                        spec.format.basetype == OIIO::TypeDesc::HALF ||
                        spec.format.basetype == OIIO::TypeDesc::DOUBLE;

    const double fit = double(maxSide) / std::max(spec.width, spec.height);
    const int w = std::max(1, int(std::lround(spec.width * fit)));
    const int h = std::max(1, int(std::lround(spec.height * fit)));
    const int channels = std::min(spec.nchannels, 3);
    // A box filter: each preview pixel the mean of the texels it covers. (The default,
    // Lanczos 3, took 1.3 of the 1.8 s a 4096 x 4096 PNG's preview cost, for a picture a few
    // hundred pixels wide.)
    OIIO::ImageBuf small = OIIO::ImageBufAlgo::resize(
        src, "box", 0.0f, OIIO::ROI(0, w, 0, h, 0, 1, 0, spec.nchannels));
    if (small.has_error()) return failure(path, small.geterror());
    std::vector<float> pixels(std::size_t(w) * h * spec.nchannels);
    if (!small.get_pixels(OIIO::ROI(0, w, 0, h, 0, 1, 0, spec.nchannels), OIIO::TypeDesc::FLOAT,
                          pixels.data()))
        return failure(path, small.geterror());

    Thumbnail t;
    t.width = w;
    t.height = h;
    t.rgb.resize(std::size_t(w) * h * 3);
    for (std::size_t p = 0; p < std::size_t(w) * h; ++p)
        for (int c = 0; c < 3; ++c) {
            // Grey (one or two channels) repeats its first channel.
            const float v = pixels[p * spec.nchannels + std::size_t(channels == 3 ? c : 0)];
            const float encoded = linear ? srgbEncode(v) : std::clamp(v, 0.0f, 1.0f);
            t.rgb[p * 3 + c] = std::uint8_t(std::lround(encoded * 255.0f));
        }
    return t;
}

}  // namespace rs
