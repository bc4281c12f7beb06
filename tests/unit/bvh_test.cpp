// BVH tests: closest/any hit equal brute force on random scenes and rays, refit, degenerate input.
#include "accel/bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <variant>
#include <vector>

#include "geometry/shapes.h"

namespace rs {
namespace {

using Prim = std::variant<SphereShape, RectangleShape, BoxShape, TriangleShape>;

bool intersectPrim(const Prim& prim, const Ray& ray, float tmin, float tmax, float& t) {
    return std::visit(
        [&](const auto& s) {
            if constexpr (std::is_same_v<std::decay_t<decltype(s)>, TriangleShape>) {
                float b1, b2;
                return intersect(s, ray, tmin, tmax, t, b1, b2);
            } else {
                ShapeHit h{};
                const bool hit = intersect(s, ray, tmin, tmax, h);
                t = h.t;
                return hit;
            }
        },
        prim);
}

Aabb primBounds(const Prim& prim) {
    return std::visit([](const auto& s) { return bounds(s); }, prim);
}

class SceneMaker {
public:
    explicit SceneMaker(unsigned seed) : rng_(seed) {}
    float uniform(float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(rng_);
    }
    Vec3 point(float extent) {
        return Vec3(uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent));
    }

    /// A mix of all four bounded shapes; some rectangles axis-aligned (flat boxes).
    Prim randomPrim(float extent) {
        const Vec3 c = point(extent);
        switch (std::uniform_int_distribution<int>(0, 3)(rng_)) {
            case 0:
                return SphereShape{c, uniform(0.05f, 1.0f)};
            case 1: {
                if (uniform(0, 1) < 0.3f)
                    return RectangleShape::make(c, Vec3(uniform(0.1f, 1), 0, 0),
                                                Vec3(0, 0, uniform(0.1f, 1)));
                return RectangleShape::make(c, point(1.0f), point(1.0f));
            }
            case 2: {
                const Vec3 half(uniform(0.05f, 1), uniform(0.05f, 1), uniform(0.05f, 1));
                return BoxShape{{c - half, c + half}};
            }
            default:
                return TriangleShape::make(c, c + point(1.0f), c + point(1.0f));
        }
    }

    std::vector<Prim> randomScene(int count, float extent) {
        std::vector<Prim> prims;
        for (int i = 0; i < count; ++i) prims.push_back(randomPrim(extent));
        return prims;
    }

    /// Random origin and non-unit direction; a fifth of the rays get zero direction components
    /// and origins snapped onto a primitive's box planes, to hit the slab test's NaN corner.
    Ray randomRay(float extent, const std::vector<Aabb>& boxes) {
        Vec3 o = point(extent * 1.3f);
        Vec3 d = point(1.0f);
        if (!boxes.empty() && uniform(0, 1) < 0.2f) {
            const Aabb& b =
                boxes[std::uniform_int_distribution<std::size_t>(0, boxes.size() - 1)(rng_)];
            const int axis = std::uniform_int_distribution<int>(0, 2)(rng_);
            d[axis] = 0.0f;
            o[axis] = uniform(0, 1) < 0.5f ? b.min[axis] : b.max[axis];
        }
        return Ray::make(o, d);
    }

private:
    std::mt19937 rng_;
};

std::vector<Aabb> boxesOf(const std::vector<Prim>& prims) {
    std::vector<Aabb> boxes;
    for (const Prim& p : prims) boxes.push_back(primBounds(p));
    return boxes;
}

struct Closest {
    bool hit = false;
    float t = kInfinity;
    uint32_t prim = 0;
};

Closest bruteClosest(const std::vector<Prim>& prims, const Ray& ray, float tmin) {
    Closest c;
    for (uint32_t i = 0; i < prims.size(); ++i) {
        float t;
        if (intersectPrim(prims[i], ray, tmin, c.t, t)) c = {true, t, i};
    }
    return c;
}

bool bruteAny(const std::vector<Prim>& prims, const Ray& ray, float tmin, float tmax) {
    float t;
    for (const Prim& p : prims)
        if (intersectPrim(p, ray, tmin, tmax, t)) return true;
    return false;
}

Closest bvhClosest(const Bvh& bvh, const std::vector<Prim>& prims, const Ray& ray, float tmin) {
    Closest c;
    c.hit = bvh.closestHit(ray, tmin, c.t, [&](uint32_t i, float& tmax) {
        float t;
        if (!intersectPrim(prims[i], ray, tmin, tmax, t)) return false;
        tmax = t;
        c.prim = i;
        return true;
    });
    return c;
}

bool bvhAny(const Bvh& bvh, const std::vector<Prim>& prims, const Ray& ray, float tmin,
            float tmax) {
    return bvh.anyHit(ray, tmin, tmax, [&](uint32_t i) {
        float t;
        return intersectPrim(prims[i], ray, tmin, tmax, t);
    });
}

/// Fires `rays` random rays and requires the BVH to answer exactly as brute force: same closest
/// t, same primitive (or an exact tie in t), same any-hit answer for a random shadow range.
void expectMatchesBruteForce(const Bvh& bvh, const std::vector<Prim>& prims, SceneMaker& maker,
                             float extent, int rays) {
    const std::vector<Aabb> boxes = boxesOf(prims);
    int mismatches = 0, hits = 0;
    for (int r = 0; r < rays && mismatches < 5; ++r) {
        const Ray ray = maker.randomRay(extent, boxes);
        const float tmin = r % 4 == 0 ? maker.uniform(0, 2) : 0.0f;
        const Closest want = bruteClosest(prims, ray, tmin);
        const Closest got = bvhClosest(bvh, prims, ray, tmin);
        hits += want.hit;
        bool same = got.hit == want.hit;
        if (same && want.hit) {
            float tGot = kInfinity;
            const bool tie =
                intersectPrim(prims[got.prim], ray, tmin, kInfinity, tGot) && tGot == want.t;
            same = got.t == want.t && (got.prim == want.prim || tie);
        }
        const float tShadow = want.hit && r % 2 ? want.t * maker.uniform(0.5f, 1.5f) : kInfinity;
        same =
            same && bvhAny(bvh, prims, ray, tmin, tShadow) == bruteAny(prims, ray, tmin, tShadow);
        if (!same) {
            ++mismatches;
            ADD_FAILURE() << "ray " << r << ": brute (" << want.hit << ", t " << want.t << ", prim "
                          << want.prim << ") vs bvh (" << got.hit << ", t " << got.t << ", prim "
                          << got.prim << ")";
        }
    }
    if (prims.size() > 20) {
        EXPECT_GT(hits, rays / 20) << "rays should actually hit something";
    }
}

int depthOf(const Bvh& bvh, uint32_t node = 0) {
    const Bvh::Node& n = bvh.nodes()[node];
    if (n.isLeaf()) return 0;
    return 1 + std::max(depthOf(bvh, node + 1), depthOf(bvh, n.offset));
}

/// Structure checks: each primitive once, leaves within size, children inside their parent.
void expectWellFormed(const Bvh& bvh, std::size_t primCount, uint32_t maxLeafSize) {
    std::vector<int> seen(primCount, 0);
    for (uint32_t i = 0; i < bvh.nodes().size(); ++i) {
        const Bvh::Node& n = bvh.nodes()[i];
        if (n.isLeaf()) {
            EXPECT_LE(n.count, maxLeafSize);
            for (uint32_t j = 0; j < n.count; ++j) ++seen[bvh.primIndices()[n.offset + j]];
            continue;
        }
        for (uint32_t child : {i + 1, n.offset}) {
            const Aabb& c = bvh.nodes()[child].bounds;
            EXPECT_TRUE(glm::all(glm::lessThanEqual(n.bounds.min, c.min)) &&
                        glm::all(glm::greaterThanEqual(n.bounds.max, c.max)));
        }
    }
    for (int s : seen) {
        ASSERT_EQ(s, 1);
    }
    EXPECT_LE(depthOf(bvh), Bvh::kMaxDepth);
}

TEST(Bvh, RandomScenes_ClosestAndAnyHitMatchBruteForce) {
    SceneMaker maker(1234);
    const int sizes[] = {1, 3, 40, 500, 1200};
    const int leafSizes[] = {1, 2, 4, 8, 4};
    for (int s = 0; s < 5; ++s) {
        const float extent = s == 4 ? 20.0f : 6.0f;
        const std::vector<Prim> prims = maker.randomScene(sizes[s], extent);
        Bvh bvh;
        bvh.build(boxesOf(prims), leafSizes[s]);
        expectWellFormed(bvh, prims.size(), static_cast<uint32_t>(leafSizes[s]));
        expectMatchesBruteForce(bvh, prims, maker, extent, 20000);
    }
}

TEST(Bvh, RefitAndRefitPrimitive_AnswerLikeARebuild) {
    SceneMaker maker(99);
    std::vector<Prim> prims = maker.randomScene(800, 8.0f);
    Bvh whole, single;
    whole.build(boxesOf(prims));
    single.build(boxesOf(prims));
    // Move a tenth of the primitives, some far away (growing boxes), some shrunk to a point.
    for (int m = 0; m < 80; ++m) {
        const auto i =
            static_cast<uint32_t>(maker.uniform(0, 1) * static_cast<float>(prims.size() - 1));
        prims[i] =
            m % 5 == 0 ? Prim{SphereShape{maker.point(8.0f), 0.0f}} : maker.randomPrim(15.0f);
        single.refitPrimitive(i, primBounds(prims[i]));
    }
    const std::vector<Aabb> boxes = boxesOf(prims);
    whole.refit(boxes);
    Bvh rebuilt;
    rebuilt.build(boxes);
    Aabb all;
    for (const Aabb& b : boxes) all.expand(b);
    for (const Bvh* bvh : {&whole, &single}) {
        EXPECT_EQ(bvh->bounds().min, all.min);  // refit recomputes, so boxes stay tight
        EXPECT_EQ(bvh->bounds().max, all.max);
        expectWellFormed(*bvh, prims.size(), 4);
    }
    expectMatchesBruteForce(rebuilt, prims, maker, 15.0f, 8000);
    expectMatchesBruteForce(whole, prims, maker, 15.0f, 8000);
    expectMatchesBruteForce(single, prims, maker, 15.0f, 8000);
}

TEST(Bvh, NoPrimitives_IsEmptyAndNeverHits) {
    Bvh bvh;
    bvh.build({});
    EXPECT_TRUE(bvh.empty());
    EXPECT_TRUE(bvh.bounds().empty());
    float tmax = kInfinity;
    const Ray ray = Ray::make(Vec3(0), Vec3(1, 0, 0));
    EXPECT_FALSE(bvh.closestHit(ray, 0, tmax, [](uint32_t, float&) { return true; }));
    EXPECT_FALSE(bvh.anyHit(ray, 0, kInfinity, [](uint32_t) { return true; }));
}

TEST(Bvh, OnePrimitive_IsOneLeafThatIsFound) {
    const std::vector<Prim> prims{SphereShape{Vec3(3, 0, 0), 1.0f}};
    Bvh bvh;
    bvh.build(boxesOf(prims));
    ASSERT_EQ(bvh.nodes().size(), 1u);
    const Closest c = bvhClosest(bvh, prims, Ray::make(Vec3(0), Vec3(1, 0, 0)), 0);
    EXPECT_TRUE(c.hit);
    EXPECT_FLOAT_EQ(c.t, 2.0f);
    EXPECT_FALSE(bvhClosest(bvh, prims, Ray::make(Vec3(0), Vec3(-1, 0, 0)), 0).hit);
}

TEST(Bvh, AllPrimitivesInOnePlace_SplitsTheListAndStaysShallow) {
    const std::vector<Prim> prims(5000, Prim{BoxShape{{Vec3(-1), Vec3(1)}}});
    Bvh bvh;
    bvh.build(boxesOf(prims), 2);
    expectWellFormed(bvh, prims.size(), 2);
    EXPECT_LE(depthOf(bvh), 13);  // halving 5000 down to 2
    const Closest c = bvhClosest(bvh, prims, Ray::make(Vec3(-5, 0, 0), Vec3(1, 0, 0)), 0);
    EXPECT_TRUE(c.hit);
    EXPECT_FLOAT_EQ(c.t, 4.0f);
}

TEST(Bvh, CentroidsSpreadSixteenfoldPerStep_DepthBoundForcesMedianSplits) {
    // Each centroid is 16x further out than the last, so every binned split can only peel off
    // the outermost primitive: unbounded, 63 primitives would make a tree 62 levels deep.
    // The boxes are thin in y and z so that surface areas stay finite in float up to 2^124.
    const float thin = std::ldexp(1.0f, -100);
    std::vector<Prim> prims;
    for (int j = 0; j < 63; ++j) {
        const float x = std::ldexp(1.0f, 4 * j - 124);
        prims.push_back(BoxShape{{Vec3(x, -thin, -thin), Vec3(x, thin, thin)}});
    }
    Bvh bvh;
    bvh.build(boxesOf(prims), 1);
    expectWellFormed(bvh, prims.size(), 1);
    EXPECT_GE(depthOf(bvh), Bvh::kMaxDepth - 3) << "scene no longer pushes against the bound";
    // Rays with dir.x == 0 lying exactly in a box's zero-width x slab: only that box is hit.
    for (uint32_t j = 0; j < prims.size(); ++j) {
        const Vec3 o(std::get<BoxShape>(prims[j]).box.min.x, 5, 0);
        const Closest c = bvhClosest(bvh, prims, Ray::make(o, Vec3(0, -1, 0)), 0);
        EXPECT_TRUE(c.hit && c.prim == j && c.t == 5.0f) << j;
    }
}

TEST(Bvh, ManyThousandsOfTriangleBoxes_BuildWellFormed) {
    SceneMaker maker(7);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 200000; ++i) {
        const Vec3 c = maker.point(100.0f);
        boxes.push_back(
            bounds(TriangleShape::make(c, c + maker.point(0.5f), c + maker.point(0.5f))));
    }
    Bvh bvh;
    bvh.build(boxes);
    expectWellFormed(bvh, boxes.size(), 4);
}

}  // namespace
}  // namespace rs
