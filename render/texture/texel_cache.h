// Filtered texture lookups over blocks of texels each thread keeps near at hand.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>

#include "core/math.h"
#include "texture/environment_spot.h"

namespace rs {

/// Most MIP levels a texture has (a 2^31-wide image has 32).
inline constexpr int kMaxMipLevels = 32;
/// Most samples one lookup takes along the long axis of an elongated footprint.
inline constexpr int kMaxAnisotropy = 8;

/// Where the texels come from: one open texture's MIP pyramid (level 0 the full image, each
/// further level half the size). Immutable after construction; fetch() is thread-safe.
/// Destroying it gives its whole levels' bytes back to the resident budget.
class TexelSource {
public:
    TexelSource();
    virtual ~TexelSource();
    TexelSource(const TexelSource&) = delete;
    TexelSource& operator=(const TexelSource&) = delete;
    /// Copies the texels [x0, x1) x [y0, y1) of `level` into `out` as linear RGB floats,
    /// row by row, the top row first. False when they cannot be read.
    virtual bool fetch(int level, int x0, int x1, int y0, int y1, float* out) const = 0;

    int levels = 0;
    std::array<int, kMaxMipLevels> width{}, height{};
    /// This source's number, never given to another in the process: what the threads'
    /// blocks are keyed by (an address may be reused once a source is freed).
    const std::uint64_t serial;

    /// Every channel of every texel lies in [0, 1] and 16-bit fractions hold it as well as
    /// the file does (textures decoded from 8-bit sRGB): whole levels are then kept as 16-bit
    /// fractions, 8 bytes a texel instead of 16.
    bool unitRange = false;

    /// Level `level` whole, when it is small enough and the budget allows (see
    /// filteredLookup), fetched on the first call; else null. Texels in four lanes (RGB and a
    /// spare), row by row, each row width + 1 texels long (its first texel again at the end,
    /// so a texel's right neighbour is always next to it): floats, or 16-bit fractions of
    /// 65535 when `unitRange`.
    const void* residentLevel(int level) const {
        // Once decided, a level is read without a call (this runs twice a lookup).
        const unsigned char now = state_[std::size_t(level)].load(std::memory_order_acquire);
        if (now == kResident) return whole_[std::size_t(level)].get();
        return now == kRefused ? nullptr : decideResident(level);
    }

private:
    /// The first call for `level`: fetches it whole if it fits, under the lock.
    const void* decideResident(int level) const;
    /// What level `level` takes kept whole.
    std::size_t wholeBytes(int level) const;

    enum : unsigned char { kUntried, kResident, kRefused };
    mutable std::array<std::atomic<unsigned char>, kMaxMipLevels> state_{};
    mutable std::array<std::unique_ptr<unsigned char[]>, kMaxMipLevels> whole_;
    mutable std::mutex mutex_;
};

/// Largest level kept whole: 1024 x 1024 texels (16 MiB as floats, 8 MiB as 16-bit fractions).
inline constexpr std::size_t kMaxResidentTexels = std::size_t(1) << 20;
/// Sets how many bytes all whole levels together may take (default 128 MiB); levels already
/// kept stay. TextureStore keeps it at half its cache's bound.
void setResidentTexelBudget(std::size_t bytes);
/// How many bytes all whole levels of the sources alive now take.
std::size_t residentTexelBytes();

/// The texture filter every image lookup goes through: trilinear (bilinear within the two
/// MIP levels whose texels are nearest half the footprint's width, blended by the fraction),
/// taking up to kMaxAnisotropy such samples spread along the long axis of an elongated
/// footprint, as OpenImageIO's anisotropic mode does; a footprint whose half-axes are both
/// under half a level-0 texel magnifies and takes one bilinear sample. (s, t) in [0, 1)^2 covers
/// the image with t = 0 its top row; texel centres lie at ((i + 0.5) / width, (j + 0.5) / height),
/// so a lookup there with zero derivatives returns the texel exactly. s always wraps periodically;
/// t wraps periodically, or is clamped to the first and last rows when `clampT` (latitude-
/// longitude environments). The derivatives are the footprint's two axes in (s, t).
///
/// Texels are read from memory the lookup owns, so it takes no lock and makes no call into
/// the source once they are at hand: a few tens of nanoseconds where a TextureSystem::texture()
/// call cost 300-600. Levels of up to kMaxResidentTexels are fetched whole on first use and
/// kept, shared by all threads, while the resident budget lasts (what footprint-filtered
/// lookups mostly read: a 4096^2 texture seen across 300 pixels is read at its 512^2 and
/// 256^2 levels). Larger levels come in blocks of 16 x 16 that each thread keeps in its own
/// direct-mapped table of 1024 blocks (4 MiB a thread). Blocks are keyed by the source's
/// serial, so a block is never mistaken for another texture's, nor for a freed source's.
///
/// Returns false (and leaves `out` alone) when a block could not be fetched.
bool filteredLookup(const TexelSource& source, float s, float t, float dsdx, float dtdx, float dsdy,
                    float dtdy, bool clampT, Color& out);

/// filteredLookup of four environment spots (derivatives (ds, 0) and (0, dt), t clamped) at
/// once, each bit for bit what it gives alone, when the lookups are the common ones under a
/// sky: every footprint magnifies (one bilinear sample at level 0) and level 0 is kept whole.
/// False otherwise, `out` untouched: look them up one by one.
bool magnifiedSpots(const TexelSource& source, const EnvironmentSpot* spots, Color* out);

}  // namespace rs
