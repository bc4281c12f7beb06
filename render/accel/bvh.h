// Bounding volume hierarchy over primitive boxes: binned SAH build, flat nodes, refit.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/math.h"

namespace rs {

/// A BVH that knows only primitive boxes; callers supply the primitive tests at traversal.
/// Nodes are in depth-first order: a node's left child is the next node, so a reverse sweep
/// visits children before parents (bottom-up refit).
class Bvh {
public:
    struct Node {
        Aabb bounds;
        uint32_t offset;  ///< Leaf: first index into primIndices(). Inner: right child index.
        uint32_t count;   ///< Primitives in a leaf; 0 for an inner node.
        bool isLeaf() const { return count != 0; }
    };

    /// Builds with a binned surface-area heuristic; leaves hold at most `maxLeafSize` prims.
    void build(std::span<const Aabb> primBounds, int maxLeafSize = 4);
    /// Recomputes every node box from new primitive boxes, keeping the topology.
    void refit(std::span<const Aabb> primBounds);
    /// Updates one primitive's box and walks its ancestors bottom-up (thesis 3.2).
    void refitPrimitive(uint32_t prim, const Aabb& newBounds);

    bool empty() const { return nodes_.empty(); }
    /// Root box; an empty box when nothing was built (so an empty mesh is safe to ask).
    const Aabb& bounds() const { return nodes_.empty() ? kEmptyBounds : nodes_.front().bounds; }
    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<uint32_t>& primIndices() const { return primIndices_; }

    /// Closest hit. `test(prim, tmax)` intersects one primitive against (tmin, tmax) and, on a
    /// hit, shrinks tmax and returns true. Returns whether anything was hit.
    template <class PrimTest>
    bool closestHit(const Ray& ray, float tmin, float& tmax, PrimTest&& test) const;
    /// Any hit in (tmin, tmax), for shadow rays. `test(prim)` returns true when prim blocks.
    template <class PrimTest>
    bool anyHit(const Ray& ray, float tmin, float tmax, PrimTest&& test) const;

    /// Deepest leaf the build makes; traversal pushes at most one node per level, so its
    /// fixed stack of kStackSize entries never overflows.
    static constexpr int kMaxDepth = 60;
    static constexpr int kStackSize = 64;

private:
    static inline const Aabb kEmptyBounds{};  // what bounds() gives for an empty tree

    Aabb leafBounds(const Node& leaf) const;

    std::vector<Node> nodes_;
    std::vector<uint32_t> primIndices_;
    std::vector<uint32_t> parent_;      ///< Parent of each node (root: itself).
    std::vector<uint32_t> leafOfPrim_;  ///< Leaf node holding each primitive.
    std::vector<Aabb> primBounds_;      ///< Kept for refitPrimitive.
    int maxLeafSize_ = 4;               ///< Kept so refit can rebuild on a count change.
};

// Traversal lives in the header so the primitive test inlines. A fixed stack: no heap per ray.
// Both children are tested at their parent: the nearer (by entry distance) is visited first and
// the other is pushed with its entry distance, then skipped on pop once a closer hit is known.
template <class PrimTest>
bool Bvh::closestHit(const Ray& ray, float tmin, float& tmax, PrimTest&& test) const {
    static_assert(kMaxDepth < kStackSize);
    if (nodes_.empty()) return false;
    struct Pending {
        uint32_t node;
        float tEntry;
    };
    Pending stack[kStackSize];
    int top = 0;
    float tEntry;
    if (!intersectSlabs(nodes_[0].bounds, ray, tmin, tmax, tEntry)) return false;
    uint32_t node = 0;
    bool hit = false;
    for (;;) {
        const Node& n = nodes_[node];
        if (!n.isLeaf()) {
            uint32_t nearNode = node + 1, farNode = n.offset;
            float tNear, tFar;
            const bool hitNear = intersectSlabs(nodes_[nearNode].bounds, ray, tmin, tmax, tNear);
            const bool hitFar = intersectSlabs(nodes_[farNode].bounds, ray, tmin, tmax, tFar);
            if (hitNear && hitFar) {
                if (tFar < tNear) {
                    std::swap(nearNode, farNode);
                    std::swap(tNear, tFar);
                }
                stack[top++] = {farNode, tFar};
                node = nearNode;
                continue;
            }
            if (hitNear || hitFar) {
                node = hitNear ? nearNode : farNode;
                continue;
            }
        } else {
            for (uint32_t i = 0; i < n.count; ++i) hit |= test(primIndices_[n.offset + i], tmax);
        }
        // Same answer as re-running the slab test with the shrunken tmax, without the box loads.
        do {
            if (top == 0) return hit;
            --top;
        } while (stack[top].tEntry > tmax);
        node = stack[top].node;
    }
}

template <class PrimTest>
bool Bvh::anyHit(const Ray& ray, float tmin, float tmax, PrimTest&& test) const {
    static_assert(kMaxDepth < kStackSize);
    if (nodes_.empty()) return false;
    if (!intersectSlabs(nodes_[0].bounds, ray, tmin, tmax)) return false;
    uint32_t stack[kStackSize];
    int top = 0;
    uint32_t node = 0;
    for (;;) {
        const Node& n = nodes_[node];
        if (!n.isLeaf()) {
            // Any hit will do, so no ordering: just avoid a second box load for the popped node.
            const bool hitLeft = intersectSlabs(nodes_[node + 1].bounds, ray, tmin, tmax);
            const bool hitRight = intersectSlabs(nodes_[n.offset].bounds, ray, tmin, tmax);
            if (hitLeft) {
                if (hitRight) stack[top++] = n.offset;
                node = node + 1;
                continue;
            }
            if (hitRight) {
                node = n.offset;
                continue;
            }
        } else {
            for (uint32_t i = 0; i < n.count; ++i)
                if (test(primIndices_[n.offset + i])) return true;
        }
        if (top == 0) return false;
        node = stack[--top];
    }
}

}  // namespace rs
