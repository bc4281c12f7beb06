// Haines and Greenberg's light buffer: a direction cube around a light whose cells list the
// objects a shadow ray toward that light can meet, so most shadow rays test none or one.
#pragma once

#include "core/math.h"

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace rs {

/// A sphere that encloses one bounded object (exactly the sphere for sphere objects).
struct BoundingSphere {
    Vec3 center;
    float radius;
};

/// An infinite plane for the light buffer: a point on it and its unit normal.
struct BufferPlane {
    Vec3 point;
    Vec3 normal;
};

/// Candidate lists for shadow rays toward one light. Conservative: every object a shadow ray
/// can hit is listed in the cell the ray's origin falls in, so testing only those objects gives
/// exactly the answer of testing them all.
///
/// Why it is conservative: a shadow ray leaves `o` toward a point `q` of the light (within
/// `lightRadius` of its centre L) and stops `eps` short, from a shading point `eps` behind
/// `o`. Every point of that segment lies within lightRadius + 2 eps of the segment from L to o
/// (see light_buffer.cpp), so an object it hits, grown by that much, meets the ray from L
/// through o, whose direction picks the cell. A plane is listed where a ray from L in some
/// direction of the cell meets it, or everywhere when L lies within that distance of it.
/// Each entry also keeps how far from L a ray origin must be for the entry to be in reach,
/// so objects and planes behind the shading point are skipped.
class LightBuffer {
public:
    /// Set on list entries that are planes; the rest of the bits are the plane's index.
    static constexpr uint32_t kPlaneBit = 0x80000000u;
    /// Cells along each edge of a cube face: 6 * 16 * 16 cells of about 7 degrees.
    static constexpr int kResolution = 16;

    LightBuffer() = default;
    /// Lists, for each cell, the objects whose sphere grown by `reach` (light radius plus ray
    /// offsets) can be seen from `light` in a direction of that cell, then the planes.
    LightBuffer(const Vec3& light, float reach, std::span<const BoundingSphere> objects,
                std::span<const BufferPlane> planes);

    /// One list entry: an object index (or kPlaneBit | plane index) and the squared distance
    /// from the light below which a shadow ray origin cannot have the entry in its way.
    struct Entry {
        uint32_t item;
        float minDistance2;
    };

    /// The list a shadow ray leaving `origin` toward the light looks up, and the origin's
    /// squared distance to the light (for the entries' minDistance2). False when the origin is
    /// the light itself: there is no direction to look up, and everything must be tested.
    bool cell(const Vec3& origin, std::span<const Entry>& entries, float& distance2) const {
        const Vec3 v = origin - light_;
        const float ax = std::abs(v.x), ay = std::abs(v.y), az = std::abs(v.z);
        int face;
        float m, a, b;
        if (ax >= ay && ax >= az) {
            face = v.x < 0.0f, m = ax, a = v.y, b = v.z;
        } else if (ay >= az) {
            face = 2 + (v.y < 0.0f), m = ay, a = v.z, b = v.x;
        } else {
            face = 4 + (v.z < 0.0f), m = az, a = v.x, b = v.y;
        }
        if (!(m > 0.0f)) return false;  // also NaN
        distance2 = v.x * v.x + v.y * v.y + v.z * v.z;
        // One reciprocal for both coordinates: a rounding step off the quotients moves a
        // direction by far less than the cells' angular margin.
        const float inv = 1.0f / m;
        const std::size_t c =
            std::size_t((face * kResolution + cellIndex(b * inv)) * kResolution + cellIndex(a * inv));
        entries = std::span<const Entry>(entries_.data() + start_[c], start_[c + 1] - start_[c]);
        return true;
    }

    /// Calls `test(item)` for the entries a shadow ray leaving `origin` toward the light may
    /// meet, in list order (objects, then planes), until one returns true. Returns 1 when one
    /// did, 0 when none did, and -1 when the origin is the light itself (no direction to look
    /// up; the caller must test everything).
    template <class Test>
    int anyHit(const Vec3& origin, Test&& test) const {
        std::span<const Entry> entries;
        float distance2;
        if (!cell(origin, entries, distance2)) return -1;
        for (const Entry& e : entries)
            if (distance2 >= e.minDistance2 && test(e.item)) return 1;
        return 0;
    }

    /// Average list length over all cells (for tests and statistics).
    float averageCandidates() const;

    // The layout, for lookups of many origins at once that mirror cell()'s operations.
    const Vec3& light() const { return light_; }
    /// 6 * kResolution^2 + 1 offsets: cell c lists entries()[starts()[c], starts()[c + 1]).
    const uint32_t* starts() const { return start_.data(); }
    const Entry* entries() const { return entries_.data(); }
    /// Cell coordinate of a face coordinate u in [-1, 1] (clamped).
    static int cellIndex(float u) {
        const int i = int((u + 1.0f) * (0.5f * float(kResolution)));
        return i < 0 ? 0 : (i >= kResolution ? kResolution - 1 : i);
    }

private:
    Vec3 light_{0.0f};
    std::vector<uint32_t> start_;  ///< 6 * kResolution^2 + 1 offsets into entries_.
    std::vector<Entry> entries_;
};

}  // namespace rs
