// BVH construction (binned SAH over all three axes, depth-bounded) and bottom-up refitting.
#include "accel/bvh.h"

#include <algorithm>
#include <cmath>

namespace rs {

namespace {

constexpr int kBins = 16;

/// A primitive as the builder moves it around: partitioning these records, not indices into
/// the caller's array, keeps every pass over a node's range sequential in memory.
struct BuildRef {
    Aabb bounds;
    Vec3 c2;  ///< centroid2(bounds), computed once: binning and partitioning must agree on it
    uint32_t prim;
};

/// Twice the box centre; non-finite (empty or infinite boxes) maps to the origin so binning
/// never sees a NaN.
inline Vec3 centroid2(const Aabb& b) {
    Vec3 c = b.min + b.max;
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(c[k])) c[k] = 0.0f;
    return c;
}

inline int ceilLog2(uint32_t n) {
    int d = 0;
    while ((uint64_t{1} << d) < n) ++d;
    return d;
}

struct Bin {
    Aabb bounds;
    uint32_t count = 0;
};

/// Maps a centroid coordinate to its bin on one axis; shared by binning and partitioning.
struct AxisBinning {
    float origin = 0.0f;
    float scale = 0.0f;
    int last = kBins - 1;
    int bin(float c) const {
        const int b = static_cast<int>((c - origin) * scale);
        return std::clamp(b, 0, last);
    }
};

class Builder {
public:
    Builder(std::vector<BuildRef>& refs, int maxLeafSize, std::vector<Bvh::Node>& nodes)
        : refs_(refs), maxLeafSize_(static_cast<uint32_t>(maxLeafSize)), nodes_(nodes) {}

    /// Emits the subtree for refs_[begin, end) in depth-first order and returns its root index.
    uint32_t build(uint32_t begin, uint32_t end, const Aabb& bounds, int depth) {
        const auto index = static_cast<uint32_t>(nodes_.size());
        nodes_.push_back({bounds, begin, end - begin});  // a leaf unless split below
        const uint32_t count = end - begin;
        if (count <= maxLeafSize_) return index;

        Aabb centroidBounds;
        for (uint32_t i = begin; i < end; ++i) centroidBounds.expand(refs_[i].c2);

        uint32_t mid = begin;
        Aabb leftBounds, rightBounds;
        // Close to the depth limit only median splits, which halve the count, are allowed:
        // then every leaf ends at depth <= kMaxDepth and the traversal stack cannot overflow.
        const bool mustHalve = depth + ceilLog2(count) >= Bvh::kMaxDepth;
        if (mustHalve || !splitSah(begin, end, centroidBounds, mid, leftBounds, rightBounds))
            splitMedian(begin, end, centroidBounds, mid, leftBounds, rightBounds);

        build(begin, mid, leftBounds, depth + 1);  // lands at index + 1
        const uint32_t right = build(mid, end, rightBounds, depth + 1);
        nodes_[index].offset = right;
        nodes_[index].count = 0;
        return index;
    }

private:
    /// Best binned-SAH split over the three axes; false when none exists (all centroids in one
    /// bin). On success partitions the range and gives the child boxes. There is no "leaf is
    /// cheaper" exit: only ranges above maxLeafSize get here, and leaves never exceed it.
    bool splitSah(uint32_t begin, uint32_t end, const Aabb& centroidBounds, uint32_t& mid,
                  Aabb& leftBounds, Aabb& rightBounds) {
        // Small ranges get fewer bins: as good a choice there, and much less fixed work per node.
        const int binCount = static_cast<int>(std::min<uint32_t>(kBins, end - begin));
        AxisBinning axes[3];
        Bin bins[3][kBins];
        bool usable[3];
        for (int k = 0; k < 3; ++k) {
            // Slightly under binCount so the largest centroid stays in the last bin. A denormal
            // extent would overflow the scale (then 0 * inf = NaN): such an axis is not binned.
            const float extent = centroidBounds.max[k] - centroidBounds.min[k];
            const float scale = static_cast<float>(binCount) * (1.0f - 1e-5f) / extent;
            usable[k] = extent > 0.0f && std::isfinite(extent) && std::isfinite(scale);
            axes[k].origin = centroidBounds.min[k];
            axes[k].scale = usable[k] ? scale : 0.0f;
            axes[k].last = binCount - 1;
        }
        if (!usable[0] && !usable[1] && !usable[2]) return false;
        for (uint32_t i = begin; i < end; ++i) {
            const Vec3 c = refs_[i].c2;
            for (int k = 0; k < 3; ++k) {
                Bin& b = bins[k][axes[k].bin(c[k])];
                b.bounds.expand(refs_[i].bounds);
                ++b.count;
            }
        }
        float bestCost = kInfinity;
        int bestAxis = -1, bestSplit = -1;
        for (int k = 0; k < 3; ++k) {
            if (!usable[k]) continue;
            // Right-to-left sweep stores the right side's cost; left-to-right finishes it.
            float rightCost[kBins];
            Aabb acc;
            uint32_t n = 0;
            for (int i = binCount - 1; i > 0; --i) {
                acc.expand(bins[k][i].bounds);
                n += bins[k][i].count;
                rightCost[i] = n ? static_cast<float>(n) * acc.surfaceArea() : kInfinity;
            }
            acc = Aabb{};
            n = 0;
            for (int i = 0; i < binCount - 1; ++i) {
                acc.expand(bins[k][i].bounds);
                n += bins[k][i].count;
                if (n == 0) continue;
                const float cost = static_cast<float>(n) * acc.surfaceArea() + rightCost[i + 1];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = k;
                    bestSplit = i;
                }
            }
        }
        if (bestAxis < 0) return false;  // every candidate cost overflowed

        const AxisBinning& axis = axes[bestAxis];
        auto* first = refs_.data() + begin;
        auto* split = std::partition(first, refs_.data() + end, [&](const BuildRef& r) {
            return axis.bin(r.c2[bestAxis]) <= bestSplit;
        });
        mid = begin + static_cast<uint32_t>(split - first);
        leftBounds = rightBounds = Aabb{};
        for (int i = 0; i < binCount; ++i)
            (i <= bestSplit ? leftBounds : rightBounds).expand(bins[bestAxis][i].bounds);
        return true;
    }

    /// Halves the range at the median centroid of the widest axis; with all centroids equal
    /// it just cuts the list in the middle (nothing to order by).
    void splitMedian(uint32_t begin, uint32_t end, const Aabb& centroidBounds, uint32_t& mid,
                     Aabb& leftBounds, Aabb& rightBounds) {
        mid = begin + (end - begin) / 2;
        const Vec3 e = centroidBounds.extent();
        const int axis = (e.x >= e.y && e.x >= e.z) ? 0 : (e.y >= e.z ? 1 : 2);
        if (e[axis] > 0.0f) {
            std::nth_element(
                refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                [axis](const BuildRef& a, const BuildRef& b) { return a.c2[axis] < b.c2[axis]; });
        }
        leftBounds = rightBounds = Aabb{};
        for (uint32_t i = begin; i < mid; ++i) leftBounds.expand(refs_[i].bounds);
        for (uint32_t i = mid; i < end; ++i) rightBounds.expand(refs_[i].bounds);
    }

    std::vector<BuildRef>& refs_;
    uint32_t maxLeafSize_;
    std::vector<Bvh::Node>& nodes_;
};

}  // namespace

void Bvh::build(std::span<const Aabb> primBounds, int maxLeafSize) {
    maxLeafSize_ = std::max(1, maxLeafSize);
    primBounds_.assign(primBounds.begin(), primBounds.end());
    nodes_.clear();
    primIndices_.clear();
    parent_.clear();
    leafOfPrim_.clear();
    if (primBounds.empty()) return;

    const auto n = static_cast<uint32_t>(primBounds.size());
    std::vector<BuildRef> refs(n);
    Aabb rootBounds;
    for (uint32_t i = 0; i < n; ++i) {
        refs[i] = {primBounds[i], centroid2(primBounds[i]), i};
        rootBounds.expand(primBounds[i]);
    }
    nodes_.reserve(2 * static_cast<std::size_t>(n / static_cast<uint32_t>(maxLeafSize_)) + 1);
    Builder(refs, maxLeafSize_, nodes_).build(0, n, rootBounds, 0);
    nodes_.shrink_to_fit();

    primIndices_.resize(n);
    for (uint32_t i = 0; i < n; ++i) primIndices_[i] = refs[i].prim;
    parent_.assign(nodes_.size(), 0);
    leafOfPrim_.assign(n, 0);
    for (uint32_t i = 0; i < nodes_.size(); ++i) {
        const Node& node = nodes_[i];
        if (node.isLeaf()) {
            for (uint32_t j = 0; j < node.count; ++j)
                leafOfPrim_[primIndices_[node.offset + j]] = i;
        } else {
            parent_[i + 1] = i;
            parent_[node.offset] = i;
        }
    }
}

Aabb Bvh::leafBounds(const Node& leaf) const {
    Aabb b;
    for (uint32_t j = 0; j < leaf.count; ++j) b.expand(primBounds_[primIndices_[leaf.offset + j]]);
    return b;
}

void Bvh::refit(std::span<const Aabb> primBounds) {
    if (primBounds.size() != primBounds_.size()) {
        // A different primitive count has no topology to keep: build afresh.
        build(primBounds, maxLeafSize_);
        return;
    }
    primBounds_.assign(primBounds.begin(), primBounds.end());
    // Depth-first order puts children after their parent, so a reverse sweep is bottom-up.
    for (std::size_t i = nodes_.size(); i-- > 0;) {
        Node& node = nodes_[i];
        if (node.isLeaf()) {
            node.bounds = leafBounds(node);
        } else {
            node.bounds = nodes_[i + 1].bounds;
            node.bounds.expand(nodes_[node.offset].bounds);
        }
    }
}

void Bvh::refitPrimitive(uint32_t prim, const Aabb& newBounds) {
    if (prim >= primBounds_.size()) return;
    primBounds_[prim] = newBounds;
    uint32_t i = leafOfPrim_[prim];
    nodes_[i].bounds = leafBounds(nodes_[i]);
    // Recompute (not just grow) each ancestor so a shrinking primitive tightens the tree too.
    // Once a box comes out unchanged, nothing above it can change either.
    while (i != 0) {
        i = parent_[i];
        Aabb b = nodes_[i + 1].bounds;
        b.expand(nodes_[nodes_[i].offset].bounds);
        Aabb& old = nodes_[i].bounds;
        if (b.min == old.min && b.max == old.max) break;
        old = b;
    }
}

}  // namespace rs
