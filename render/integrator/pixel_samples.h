// The camera samples of a pixel: where each lies in the pixel and the seed it traces with.
// Full renders and the session's supersample pass both take them from here, so a pixel gets
// the same samples (and bits) whichever traced it.
#pragma once

#include <cstdint>

#include "integrator/sampling.h"
#include "snapshot/camera_model.h"

namespace rs {

/// pixelSeed(x, y, k) given the row's key hashKey(y) and the sample's key hashKey(k): a row
/// of pixels works both keys out once.
inline uint32_t pixelSeedKeyed(int x, uint32_t rowKey, uint32_t sampleKey) {
    return hashKeyed(hashKeyed(uint32_t(x), rowKey), sampleKey);
}
/// Seed of sample `k` of pixel (x, y): depends on the pixel alone, not on tiles or threads.
/// It is hashCombine(hashCombine(x, y), k).
inline uint32_t pixelSeed(int x, int y, int k) {
    return pixelSeedKeyed(x, hashKey(uint32_t(y)), hashKey(uint32_t(k)));
}

/// Samples k = 0 ... spp - 1 of pixel (x, y) when it is supersampled (spp > 1): sample k's
/// ray passes through pixelSampleOffset(k, spp) of the pixel, on the pattern seeded by the
/// pixel, and traces with pixelSeed(x, y, k). A pixel's colour is the sum of its samples in
/// order k = 0, 1, ... over spp.
class PixelSamples {
public:
    PixelSamples(int x, int y, int spp)
        : x_(x), y_(y), spp_(spp), patternSeed_(pixelSeed(x, y, kPatternKey)) {}
    /// Sample k's camera ray.
    Ray ray(const CameraModel& camera, int k) const {
        const Vec3 o = pixelSampleOffset(k, spp_, patternSeed_);
        return camera.generateRay(float(x_) + o.x, float(y_) + o.y);
    }
    /// Sample k's seed.
    uint32_t seed(int k) const { return pixelSeed(x_, y_, k); }

private:
    /// The sample index whose pixelSeed seeds the pattern.
    static constexpr int kPatternKey = 0x5eed;
    int x_, y_, spp_;
    uint32_t patternSeed_;
};

}  // namespace rs
