// MeshAccel tests: closest hit and occlusion equal brute force over the mesh's own triangles.
#include "accel/mesh_accel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>
#include <vector>

namespace rs {
namespace {

/// A bumpy n x n heightfield over [-5, 5]^2 with shared vertices and random vertex normals.
std::shared_ptr<MeshData> bumpyGrid(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> gauss;
    auto mesh = std::make_shared<MeshData>();
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const float x = -5.0f + 10.0f * static_cast<float>(i) / static_cast<float>(n);
            const float y = -5.0f + 10.0f * static_cast<float>(j) / static_cast<float>(n);
            mesh->positions.emplace_back(x, y, std::sin(1.7f * x) * std::cos(1.3f * y));
            mesh->normals.push_back(glm::normalize(Vec3(gauss(rng), gauss(rng), gauss(rng))));
        }
    }
    const auto row = static_cast<uint32_t>(n + 1);
    for (uint32_t j = 0; j < static_cast<uint32_t>(n); ++j) {
        for (uint32_t i = 0; i < static_cast<uint32_t>(n); ++i) {
            const uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
            mesh->indices.insert(mesh->indices.end(), {a, b, d, a, d, c});
        }
    }
    return mesh;
}

TriangleShape triangleOf(const MeshData& m, std::size_t tri) {
    const uint32_t* idx = &m.indices[3 * tri];
    return TriangleShape::make(m.positions[idx[0]], m.positions[idx[1]], m.positions[idx[2]]);
}

Vec3 expectedNormal(const MeshData& m, std::size_t tri, float b1, float b2, bool smooth) {
    const TriangleShape t = triangleOf(m, tri);
    if (!smooth) return glm::normalize(glm::cross(t.e1, t.e2));
    const uint32_t* idx = &m.indices[3 * tri];
    return glm::normalize((1 - b1 - b2) * m.normals[idx[0]] + b1 * m.normals[idx[1]] +
                          b2 * m.normals[idx[2]]);
}

void expectMatchesBruteForce(bool smooth) {
    const auto mesh = bumpyGrid(40, 3);
    const MeshAccel accel(mesh, smooth);
    ASSERT_EQ(accel.triangleCount(), mesh->triangleCount());
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int hits = 0, failures = 0;
    for (int r = 0; r < 10000 && failures < 5; ++r) {
        const Ray ray =
            Ray::make(Vec3(6 * u(rng), 6 * u(rng), 3 * u(rng)), Vec3(u(rng), u(rng), u(rng)));
        float bestT = kInfinity, bestB1 = 0, bestB2 = 0;
        std::size_t best = 0;
        bool want = false;
        for (std::size_t i = 0; i < mesh->triangleCount(); ++i) {
            float t, b1, b2;
            if (intersect(triangleOf(*mesh, i), ray, 0, bestT, t, b1, b2)) {
                want = true;
                bestT = t, bestB1 = b1, bestB2 = b2, best = i;
            }
        }
        float tmax = kInfinity;
        ShapeHit hit{};
        const bool got = accel.intersect(ray, 0, tmax, hit);
        hits += want;
        bool same = got == want && accel.occluded(ray, 0, kInfinity) == want;
        if (same && want) {
            same = hit.t == bestT && tmax == bestT && std::abs(glm::length(hit.n) - 1) < 1e-5f &&
                   !accel.occluded(ray, 0, bestT) && accel.occluded(ray, 0, bestT * 1.001f);
            const Vec3 n = expectedNormal(*mesh, best, bestB1, bestB2, smooth);
            if (glm::length(hit.n - n) >= 1e-4f) {
                // Only right when another triangle is hit at exactly the same t (a shared edge).
                int atSameT = 0;
                for (std::size_t i = 0; i < mesh->triangleCount(); ++i) {
                    float t, b1, b2;
                    atSameT +=
                        intersect(triangleOf(*mesh, i), ray, 0, kInfinity, t, b1, b2) && t == bestT;
                }
                same = same && atSameT > 1;
            }
        }
        if (!same) {
            ++failures;
            ADD_FAILURE() << "ray " << r << ": brute " << want << " t " << bestT << " tri " << best
                          << " vs accel " << got << " t " << hit.t;
        }
    }
    EXPECT_GT(hits, 1000) << "rays should hit the mesh often";
}

TEST(MeshAccel, FlatShading_MatchesBruteForceWithGeometricNormals) {
    expectMatchesBruteForce(false);
}

TEST(MeshAccel, SmoothShading_MatchesBruteForceWithInterpolatedNormals) {
    expectMatchesBruteForce(true);
}

std::shared_ptr<MeshData> oneTriangle() {
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh->normals = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh->indices = {0, 1, 2};
    return mesh;
}

TEST(MeshAccel, Smooth_InterpolatesVertexNormalsAndNormalises) {
    const MeshAccel accel(oneTriangle(), true);
    float tmax = kInfinity;
    ShapeHit hit{};
    ASSERT_TRUE(accel.intersect(Ray::make(Vec3(0.25f, 0.25f, 2), Vec3(0, 0, -1)), 0, tmax, hit));
    EXPECT_FLOAT_EQ(hit.t, 2.0f);
    EXPECT_FLOAT_EQ(tmax, 2.0f);
    const Vec3 want = glm::normalize(Vec3(0.25f, 0.25f, 0.5f));
    EXPECT_NEAR(glm::length(hit.n - want), 0.0f, 1e-6f);
}

TEST(MeshAccel, FlatOrWithoutNormals_UsesGeometricNormal) {
    auto noNormals = oneTriangle();
    noNormals->normals.clear();
    for (const MeshAccel& accel : {MeshAccel(oneTriangle(), false), MeshAccel(noNormals, true)}) {
        float tmax = kInfinity;
        ShapeHit hit{};
        ASSERT_TRUE(
            accel.intersect(Ray::make(Vec3(0.25f, 0.25f, -2), Vec3(0, 0, 3)), 0, tmax, hit));
        EXPECT_EQ(hit.n, Vec3(0, 0, 1));  // e1 x e2, not flipped toward the ray
    }
}

// MeshData keeps its bounds after the first call; a copy (the way an edited mesh is made)
// works out its own, and threads asking at once all get the same box.
TEST(MeshData, Bounds_AreKeptAndACopyWorksOutItsOwn) {
    auto mesh = oneTriangle();
    EXPECT_EQ(mesh->bounds().min, Vec3(0, 0, 0));
    EXPECT_EQ(mesh->bounds().max, Vec3(1, 1, 0));
    MeshData moved = *mesh;
    moved.positions[1] = Vec3(4, 0, -2);
    EXPECT_EQ(moved.bounds().max, Vec3(4, 1, 0));
    EXPECT_EQ(moved.bounds().min, Vec3(0, 0, -2));
    EXPECT_EQ(mesh->bounds().max, Vec3(1, 1, 0));  // the original is untouched
    MeshData assigned;
    EXPECT_TRUE(assigned.bounds().empty());
    assigned = moved;
    EXPECT_EQ(assigned.bounds().max, Vec3(4, 1, 0));  // not the empty box it kept before

    const auto grid = bumpyGrid(64, 3);
    std::vector<Aabb> seen(4);
    std::vector<std::thread> threads;
    for (Aabb& box : seen) threads.emplace_back([&grid, &box] { box = grid->bounds(); });
    for (std::thread& t : threads) t.join();
    Aabb all;
    for (const Vec3& p : grid->positions) all.expand(p);
    for (const Aabb& box : seen) {
        EXPECT_EQ(box.min, all.min);
        EXPECT_EQ(box.max, all.max);
    }
}

TEST(MeshAccel, EmptyOrNullMesh_NeverHitsAndHasEmptyBounds) {
    for (const MeshAccel& accel :
         {MeshAccel(std::make_shared<MeshData>(), true), MeshAccel(nullptr, false)}) {
        EXPECT_EQ(accel.triangleCount(), 0u);
        EXPECT_TRUE(accel.bounds().empty());
        float tmax = kInfinity;
        ShapeHit hit{};
        EXPECT_FALSE(accel.intersect(Ray::make(Vec3(0), Vec3(1, 0, 0)), 0, tmax, hit));
        EXPECT_FALSE(accel.occluded(Ray::make(Vec3(0), Vec3(1, 0, 0)), 0, kInfinity));
    }
}

TEST(MeshAccel, OutOfRangeIndex_DropsOnlyThatTriangle) {
    auto mesh = oneTriangle();
    mesh->positions.push_back(Vec3(0, 0, 5));
    mesh->indices.insert(mesh->indices.end(), {0, 1, 99, 3, 1, 2});  // second is broken
    // Shift the third triangle to z = 5 so each ray below can only hit one of them.
    mesh->positions.push_back(Vec3(1, 0, 5));
    mesh->positions.push_back(Vec3(0, 1, 5));
    mesh->indices[7] = 4;
    mesh->indices[8] = 5;
    const MeshAccel accel(mesh, false);
    EXPECT_EQ(accel.triangleCount(), 3u);
    float tmax = kInfinity;
    ShapeHit hit{};
    ASSERT_TRUE(accel.intersect(Ray::make(Vec3(0.2f, 0.2f, 10), Vec3(0, 0, -1)), 0, tmax, hit));
    EXPECT_FLOAT_EQ(hit.t, 5.0f);  // the z = 5 triangle, then the z = 0 one behind it
    EXPECT_TRUE(accel.occluded(Ray::make(Vec3(0.2f, 0.2f, 1), Vec3(0, 0, -1)), 0, kInfinity));
}

}  // namespace
}  // namespace rs
