// The TextureStore: header checks, the sRGB-decoding reader, and OpenImageIO lookups.
#include "texture/texture_store.h"

#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include "core/input_file.h"
#include "texture/srgb_input.h"
#include "texture/texel_cache.h"

namespace rs {

namespace {

using OIIO::TextureOpt;
using OIIO::TextureSystem;

/// Untiled images appear to the lookups as tiles of this many pixels square.
constexpr int kAutoTile = 64;

std::string describeFile(const std::string& path) {
    return "texture file '" + path + "'";
}

/// What a file was when it was last registered with the cache; a change means a re-read.
struct Registration {
    FileStamp file;
    bool srgb = false;
    bool operator==(const Registration&) const = default;
};

/// This thread's OpenImageIO record for `system`, fetched once per thread.
TextureSystem::Perthread* perthreadOf(TextureSystem* system) {
    thread_local const TextureSystem* owner = nullptr;
    thread_local TextureSystem::Perthread* info = nullptr;
    if (owner != system || !info) {
        info = system->get_perthread_info();
        owner = system;
    }
    return info;
}

/// One version of an open file's MIP pyramid, read through the TextureSystem: its tile
/// cache (bounded by the cache's megabytes) stays what reads the file, lazily, tile by tile.
class OiioTexels final : public TexelSource {
public:
    OiioTexels(TextureSystem* system, TextureSystem::TextureHandle* handle, int channels)
        : system_(system), handle_(handle), channels_(channels >= 3 ? 3 : 1) {}

    bool fetch(int level, int x0, int x1, int y0, int y1, float* out) const override {
        TextureOpt options;
        const std::size_t count = std::size_t(x1 - x0) * std::size_t(y1 - y0);
        if (channels_ == 3)
            return system_->get_texels(handle_, perthreadOf(system_), options, level, x0, x1, y0,
                                       y1, 0, 1, 0, 3, OIIO::TypeFloat, out);
        // Grey: read one channel into the front of `out`, then spread it, last texel first.
        if (!system_->get_texels(handle_, perthreadOf(system_), options, level, x0, x1, y0, y1, 0,
                                 1, 0, 1, OIIO::TypeFloat, out))
            return false;
        for (std::size_t i = count; i-- > 0;) out[3 * i] = out[3 * i + 1] = out[3 * i + 2] = out[i];
        return true;
    }

private:
    TextureSystem* system_;
    TextureSystem::TextureHandle* handle_;
    int channels_;
};

/// The header alone: the image's size, pixel format and whether it has MIP levels. Empty, or
/// why the file cannot be a texture (not an image, no pixels, too large to MIP-map while
/// rendering).
std::string readHeader(const std::string& path, OIIO::ImageSpec& spec, bool& mipmapped) {
    {
        auto input = OIIO::ImageInput::open(path);
        if (!input) {
            std::string detail = OIIO::geterror();
            if (detail.empty()) detail = "unknown format or corrupt header";
            return describeFile(path) + " is not an image that can be read: " + detail;
        }
        spec = input->spec();
        mipmapped = input->seek_subimage(0, 1);
        (void)input->geterror();
    }
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        return describeFile(path) + " has no pixels";
    const std::int64_t pixels = std::int64_t(spec.width) * spec.height * std::max(spec.depth, 1);
    if (!mipmapped && pixels > kMaxAutoMipPixels)
        return describeFile(path) + " is " + std::to_string(spec.width) + " x " +
               std::to_string(spec.height) +
               " pixels without MIP levels, more than the 4096 x 4096 that are MIP-mapped "
               "while rendering; make a tiled, MIP-mapped copy with maketx (Debian's "
               "openimageio-tools), e.g. `maketx '" +
               path + "' -o copy.exr`, and use that";
    return {};
}

}  // namespace

struct TextureStore::Impl {
    OIIO::ImageCache* cache = nullptr;
    TextureSystem* system = nullptr;
    std::atomic<float> megabytes{kDefaultTextureCacheMegabytes};
    std::mutex registerMutex;
    std::map<std::string, Registration> registered;
    /// Handles given out, by path, with the file's stamp then: a snapshot compiled per edit
    /// (every drag step) asks again for the same files, and needs no header read for them.
    std::map<std::string, std::pair<Registration, TextureHandle>> opened;

    TextureSystem::Perthread* perthread() const { return perthreadOf(system); }

    /// Registers the file with the reader it needs the first time, and afresh when it has
    /// changed on disk (handles already given out stay valid and see the new pixels). Empty,
    /// or why the cache cannot read it.
    std::string registerFile(const std::string& path, const OIIO::ustring& name,
                             const Registration& stamp) {
        std::lock_guard<std::mutex> lock(registerMutex);
        auto found = registered.find(path);
        if (found != registered.end() && found->second == stamp) return {};
        const bool replace = found != registered.end();
        if (replace) system->invalidate(name, true);
        if (!cache->add_file(name, stamp.srgb ? &createSrgbLinearInput : nullptr, nullptr,
                             replace)) {
            std::string detail = cache->geterror();
            return describeFile(path) +
                   " cannot be read: " + (detail.empty() ? std::string("unknown error") : detail);
        }
        registered[path] = stamp;
        return {};
    }

    /// The MIP pyramid of the file registered as `name`, or null when its levels cannot be
    /// read. Call with registerMutex held.
    std::shared_ptr<const TexelSource> pyramid(const OIIO::ustring& name,
                                               TextureSystem::TextureHandle* handle, int channels,
                                               bool eightBitSrgb) {
        int levels = 0;
        if (!cache->get_image_info(name, 0, 0, OIIO::ustring("miplevels"), OIIO::TypeInt,
                                   &levels) ||
            levels <= 0) {
            (void)cache->geterror();
            return nullptr;
        }
        auto texels = std::make_shared<OiioTexels>(system, handle, channels);
        texels->levels = std::min(levels, kMaxMipLevels);
        // 8-bit sRGB decoded to linear: every channel in [0, 1], and 16-bit linear fractions
        // are finer than the file's steps (its darkest, 1/255 decoded, is 20 of them).
        texels->unitRange = eightBitSrgb;
        for (int level = 0; level < texels->levels; ++level) {
            const OIIO::ImageSpec* spec = cache->imagespec(name, 0, level);
            if (!spec || spec->width <= 0 || spec->height <= 0) {
                (void)cache->geterror();
                return nullptr;
            }
            texels->width[std::size_t(level)] = spec->width;
            texels->height[std::size_t(level)] = spec->height;
        }
        return texels;
    }
};

TextureStore& TextureStore::shared() {
    static TextureStore* store = new TextureStore;
    return *store;
}

TextureStore::TextureStore() : impl_(new Impl) {
    impl_->cache = OIIO::ImageCache::create(/*shared=*/false);
    impl_->cache->attribute("max_memory_MB", kDefaultTextureCacheMegabytes);
    impl_->cache->attribute("autotile", kAutoTile);
    impl_->cache->attribute("automip", 1);
    impl_->cache->attribute("accept_untiled", 1);
    impl_->cache->attribute("accept_unmipped", 1);
    impl_->cache->attribute("unassociatedalpha", 1);  // colours as stored, alpha ignored
    impl_->system = TextureSystem::create(/*shared=*/false, impl_->cache);
}

void TextureStore::setCacheMegabytes(float mb) {
    if (!(mb > 0.0f) || !std::isfinite(mb)) return;
    impl_->megabytes.store(mb);
    impl_->cache->attribute("max_memory_MB", mb);
    setResidentTexelBudget(std::size_t(double(mb) * 0.5 * 1024.0 * 1024.0));
}

float TextureStore::cacheMegabytes() const {
    return impl_->megabytes.load();
}

TextureHandle TextureStore::open(const std::string& path, std::string& error) {
    TextureHandle handle = openFile(path, error);
    if (!handle) handle.file = fileStampOf(path);
    return handle;
}

TextureHandle TextureStore::openFile(const std::string& path, std::string& error) {
    error.clear();
    const std::string why = checkInputFile(path, kMaxTextureFileBytes);
    if (!why.empty()) {
        error = describeFile(path) + (why.rfind("is ", 0) == 0 ? " " : ": ") + why;
        return {};
    }
    const FileStamp stamp = fileStampOf(path);
    {
        std::lock_guard<std::mutex> lock(impl_->registerMutex);
        const auto known = impl_->opened.find(path);
        if (known != impl_->opened.end() && known->second.first.file == stamp)
            return known->second.second;
    }

    OIIO::ImageSpec spec;
    bool mipmapped = false;
    error = readHeader(path, spec, mipmapped);
    if (!error.empty()) return {};

    TextureHandle handle;
    handle.file = stamp;
    handle.srgb = isSrgbEncoded(spec.format);
    handle.channels = spec.nchannels;
    const OIIO::ustring name(path);
    error = impl_->registerFile(path, name, Registration{stamp, handle.srgb});
    if (!error.empty()) return {};
    auto* oiioHandle = impl_->system->get_texture_handle(name, impl_->perthread());
    if (!oiioHandle || !impl_->system->good(oiioHandle)) {
        std::string detail = impl_->system->geterror();
        error = describeFile(path) +
                " cannot be read: " + (detail.empty() ? std::string("unknown error") : detail);
        return {};
    }
    handle.handle = oiioHandle;
    std::lock_guard<std::mutex> lock(impl_->registerMutex);
    handle.texels =
        impl_->pyramid(name, oiioHandle, handle.channels, handle.srgb && spec.format.size() == 1);
    if (!handle.texels) {
        error = describeFile(path) + " cannot be read: its MIP levels are not readable";
        return {};
    }
    impl_->opened[path] = {Registration{stamp, handle.srgb}, handle};
    return handle;
}

Color TextureStore::lookup(const TextureHandle& texture, float s, float t, float dsdx, float dtdx,
                           float dsdy, float dtdy) const {
    Color c;
    if (!texture.texels || !filteredLookup(*texture.texels, s, t, dsdx, dtdx, dsdy, dtdy,
                                           /*clampT=*/false, c))
        return missingTexture(s, t);  // also a file that broke after opening
    return c;
}

Color TextureStore::environment(const TextureHandle& texture, const Vec3& d, float rotationDegrees,
                                float coneAngle) const {
    EnvironmentSpot spot;
    environmentSpots(1, {&d.x, &d.y, &d.z}, rotationDegrees, coneAngle, &spot);
    return environmentAt(texture, spot);
}

Color TextureStore::environmentAt(const TextureHandle& texture, const EnvironmentSpot& spot) const {
    Color c;
    if (!texture.texels || !filteredLookup(*texture.texels, spot.s, spot.t, spot.ds, 0.0f, 0.0f,
                                           spot.dt, /*clampT=*/true, c))
        return missingTexture(spot.s, spot.t);
    return c;
}

void TextureStore::environmentAt(const TextureHandle& texture, std::size_t count,
                                 const EnvironmentSpot* spots, Color* out) const {
    std::size_t i = 0;
    if (texture.texels)
        for (; i + 4 <= count; i += 4)
            if (!magnifiedSpots(*texture.texels, spots + i, out + i))
                for (std::size_t k = i; k < i + 4; ++k) out[k] = environmentAt(texture, spots[k]);
    for (; i < count; ++i) out[i] = environmentAt(texture, spots[i]);
}

Color missingTexture(float s, float t) {
    const double cells = std::floor(8.0 * double(s)) + std::floor(8.0 * double(t));
    const bool even = cells - 2.0 * std::floor(0.5 * cells) == 0.0;
    return even ? Color(1.0f, 0.0f, 1.0f) : Color(0.0f);
}

}  // namespace rs
