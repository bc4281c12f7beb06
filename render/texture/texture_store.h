// Image textures and environments through one process-wide OpenImageIO TextureSystem.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/input_file.h"
#include "core/math.h"
#include "texture/environment_spot.h"

namespace rs {

class TexelSource;

/// Largest texture file opened: 2 GiB (the same bound as meshes).
inline constexpr std::uintmax_t kMaxTextureFileBytes = std::uintmax_t(2) << 30;
/// Largest image MIP-mapped on the fly: 4096 x 4096 pixels. OpenImageIO builds the missing
/// MIP levels of a plain image from its full-resolution level and, while doing so, raises
/// the cache's bound to twice that level's size (a 4096 x 4096 RGB image is 96 MiB in the
/// cache as linear half floats, so the bound is then at least 192 MiB). Larger images
/// without MIP levels are refused with a message saying how to make a tiled, MIP-mapped copy
/// with `maketx` (Debian's openimageio-tools); such copies, at any size, are read tile by tile
/// as lookups need them and stay within the cache's bound.
inline constexpr std::int64_t kMaxAutoMipPixels = std::int64_t(4096) * 4096;
/// The texture cache's default bound: 256 MB of decoded tiles (OpenImageIO's max_memory_MB).
inline constexpr float kDefaultTextureCacheMegabytes = 256.0f;

/// An open texture: cheap to copy. Its texels live as long as a handle to them does.
struct TextureHandle {
    void* handle = nullptr;  ///< OpenImageIO's TextureSystem::TextureHandle.
    /// The file's MIP pyramid as the lookups read it (texel_cache.h); one per version of the
    /// file opened, freed with the last handle to it (the snapshots that show that version,
    /// and the store while it is the file's latest).
    std::shared_ptr<const TexelSource> texels;
    bool srgb = false;  ///< 8- or 16-bit integer texels, decoded from sRGB to linear.
    int channels = 0;   ///< Channels in the file (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA).
    /// The file's stamp when it was opened, or when it failed to open: a stamp on disk that
    /// differs says the file was saved again since (from a paint program, say).
    FileStamp file;
    explicit operator bool() const { return handle != nullptr; }
};

/// The texture cache. Every call is thread-safe. OpenImageIO's TextureSystem opens the files,
/// builds missing MIP levels and holds the decoded tiles; lookups filter with
/// filteredLookup (texel_cache.h) over texels copied out of it, whole small levels shared
/// by all threads and blocks of larger ones per thread, taking no lock. (A TextureSystem
/// texture() call per lookup cost 260-600 ns on the 2-core development machine, more than
/// tracing the ray.) Nothing is printed: errors come back to the caller.
///
/// Colours: 8- and 16-bit integer files are sRGB and are decoded to linear as their tiles
/// enter the cache (exact sRGB EOTF), so filtering and MIP levels average linear values;
/// float and half files are linear as stored. One-channel images are grey; alpha is ignored
/// (never premultiplied into the colour).
///
/// Memory: the cache holds at most cacheMegabytes() of decoded tiles (kMaxAutoMipPixels says
/// when OpenImageIO may exceed that); whole levels copied out for lookups take at most half
/// as much again, and each rendering thread 4 MiB of blocks. Plain PNG/JPEG/... images are
/// MIP-mapped on the fly (OpenImageIO's automip) and read as 64-row tiles (autotile); open() reads
/// headers only.
class TextureStore {
public:
    static TextureStore& shared();

    /// The cache's bound in MB (OpenImageIO's max_memory_MB); default
    /// kDefaultTextureCacheMegabytes. Takes effect for tiles read from now on.
    void setCacheMegabytes(float mb);
    float cacheMegabytes() const;

    /// Opens an image for lookups, reading only its header. On failure returns an empty
    /// handle and sets `error` to a sentence naming the file and the problem: missing, not a
    /// regular file, over kMaxTextureFileBytes, not an image OpenImageIO can read (corrupt or
    /// unknown header), or a plain image over kMaxAutoMipPixels. A file changed on disk since
    /// it was last opened is read afresh.
    TextureHandle open(const std::string& path, std::string& error);

    /// Filtered, MIP-mapped lookup (trilinear, anisotropic: filteredLookup) at
    /// (s, t), with the footprint's derivatives along the two screen axes; s and t wrap
    /// periodically, t = 0 is the image's TOP row (so callers pass t = 1 - v). Zero
    /// derivatives give the bilinear interpolation of the full-resolution level, exactly the
    /// texel's colour at a texel centre. An empty handle, or a file that fails to read later,
    /// gives missingTexture(s, t).
    Color lookup(const TextureHandle& texture, float s, float t, float dsdx, float dtdx, float dsdy,
                 float dtdy) const;

    /// A latitude-longitude environment seen along unit world direction `d`, with the same
    /// map as sphereUV: u = phi / (2 pi), phi the angle from +X toward +Z, v = 0.5 + asin(y)/pi
    /// (the image's top row straight up), looked up at s = u + rotationDegrees / 360,
    /// t = 1 - v. So `rotationDegrees` turns the environment about +Y by the rotation
    /// (x, z) -> (x cos a + z sin a, -x sin a + z cos a), which takes +Z to +X at 90 degrees:
    /// what the image shows at +Z is then seen toward +X. Filtered over a cone of full angle
    /// `coneAngle` radians (the ray's spread; 0 point-samples): coneAngle / pi in t and
    /// coneAngle / (2 pi cos(latitude)) in s, at most one turn. Empty handle: missingTexture.
    Color environment(const TextureHandle& texture, const Vec3& d, float rotationDegrees,
                      float coneAngle) const;
    /// The environment at a spot environmentSpots found (many directions at once):
    /// environment() is environmentSpots for one direction, then this.
    Color environmentAt(const TextureHandle& texture, const EnvironmentSpot& spot) const;
    /// environmentAt of `count` spots into out[0, count): most skies' lookups four at a time.
    void environmentAt(const TextureHandle& texture, std::size_t count,
                       const EnvironmentSpot* spots, Color* out) const;

private:
    TextureStore();
    /// open() but for the stamp of a file that fails.
    TextureHandle openFile(const std::string& path, std::string& error);
    struct Impl;
    Impl* impl_;  // Never freed: lookups may run from threads that outlive static destructors.
};

/// The "missing" pattern: magenta (1, 0, 1) and black checks, 8 x 8 per unit square of
/// (s, t), magenta where floor(8 s) + floor(8 t) is even.
Color missingTexture(float s, float t);

}  // namespace rs
