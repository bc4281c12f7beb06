// Bounding volume hierarchy over primitive boxes: binned SAH build, flat nodes, refit.
#pragma once

#include "core/math.h"

#include <cstdint>
#include <span>
#include <vector>

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
    const Aabb& bounds() const { return nodes_.front().bounds; }
    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<uint32_t>& primIndices() const { return primIndices_; }

    /// Closest hit. `test(prim, tmax)` intersects one primitive against (tmin, tmax) and, on a
    /// hit, shrinks tmax and returns true. Returns whether anything was hit.
    template <class PrimTest>
    bool closestHit(const Ray& ray, float tmin, float& tmax, PrimTest&& test) const;
    /// Any hit in (tmin, tmax), for shadow rays. `test(prim)` returns true when prim blocks.
    template <class PrimTest>
    bool anyHit(const Ray& ray, float tmin, float tmax, PrimTest&& test) const;

private:
    std::vector<Node> nodes_;
    std::vector<uint32_t> primIndices_;
    std::vector<uint32_t> parent_;    ///< Parent of each node (root: itself).
    std::vector<uint32_t> leafOfPrim_;  ///< Leaf node holding each primitive.
    std::vector<Aabb> primBounds_;      ///< Kept for refitPrimitive.
};

// Traversal lives in the header so the primitive test inlines. A fixed stack: no heap per ray.
template <class PrimTest>
bool Bvh::closestHit(const Ray& ray, float tmin, float& tmax, PrimTest&& test) const {
    if (nodes_.empty()) return false;
    uint32_t stack[64];
    int top = 0;
    uint32_t node = 0;
    bool hit = false;
    for (;;) {
        const Node& n = nodes_[node];
        if (intersectSlabs(n.bounds, ray, tmin, tmax)) {
            if (n.isLeaf()) {
                for (uint32_t i = 0; i < n.count; ++i)
                    hit |= test(primIndices_[n.offset + i], tmax);
            } else {
                stack[top++] = n.offset;
                node = node + 1;
                continue;
            }
        }
        if (top == 0) break;
        node = stack[--top];
    }
    return hit;
}

template <class PrimTest>
bool Bvh::anyHit(const Ray& ray, float tmin, float tmax, PrimTest&& test) const {
    if (nodes_.empty()) return false;
    uint32_t stack[64];
    int top = 0;
    uint32_t node = 0;
    for (;;) {
        const Node& n = nodes_[node];
        if (intersectSlabs(n.bounds, ray, tmin, tmax)) {
            if (n.isLeaf()) {
                for (uint32_t i = 0; i < n.count; ++i)
                    if (test(primIndices_[n.offset + i])) return true;
            } else {
                stack[top++] = n.offset;
                node = node + 1;
                continue;
            }
        }
        if (top == 0) break;
        node = stack[--top];
    }
    return false;
}

}  // namespace rs
