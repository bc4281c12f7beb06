// Shape texture coordinates: known points, upright box faces, seams, and gradients against
// central finite differences.
#include "texture/shape_uv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace rs {
namespace {

constexpr double kPiD = 3.14159265358979323846;

void expectUV(const ShapeUV& uv, float u, float v, float eps = 1e-5f) {
    EXPECT_NEAR(uv.u, u, eps);
    EXPECT_NEAR(uv.v, v, eps);
}

/// Checks dudp and dvdp against central differences along two tangent directions: the
/// difference quotient of a step h either side must match dot(gradient, t) within `tol`
/// relative to the larger of the two (at least 0.05, for gradients near zero).
void expectGradients(const std::function<ShapeUV(const Vec3&)>& uvAt, const Vec3& p, const Vec3& t1,
                     const Vec3& t2, float h, float tol) {
    const ShapeUV at = uvAt(p);
    for (const Vec3& t : {t1, t2, glm::normalize(t1 + t2)}) {
        const ShapeUV plus = uvAt(p + h * t), minus = uvAt(p - h * t);
        const double du = (double(plus.u) - minus.u) / (2.0 * h);
        const double dv = (double(plus.v) - minus.v) / (2.0 * h);
        const double gu = glm::dot(at.dudp, t), gv = glm::dot(at.dvdp, t);
        EXPECT_NEAR(gu, du, tol * std::max({std::abs(du), std::abs(gu), 0.05}))
            << "du at " << p.x << " " << p.y << " " << p.z;
        EXPECT_NEAR(gv, dv, tol * std::max({std::abs(dv), std::abs(gv), 0.05}))
            << "dv at " << p.x << " " << p.y << " " << p.z;
    }
}

/// Two unit tangents of the sphere at p.
void sphereTangents(const Vec3& p, const Vec3& c, Vec3& t1, Vec3& t2) {
    const Vec3 n = glm::normalize(p - c);
    t1 = glm::normalize(glm::cross(n, std::abs(n.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0)));
    t2 = glm::cross(n, t1);
}

TEST(SphereUV, AxesMapToTheDocumentedCoordinates) {
    const Vec3 c(1.0f, -2.0f, 3.0f);
    const float r = 2.5f;
    expectUV(sphereUV(c + Vec3(r, 0, 0), c, r), 0.0f, 0.5f);
    expectUV(sphereUV(c + Vec3(0, 0, r), c, r), 0.25f, 0.5f);
    expectUV(sphereUV(c + Vec3(-r, 0, 0), c, r), 0.5f, 0.5f);
    expectUV(sphereUV(c + Vec3(0, 0, -r), c, r), 0.75f, 0.5f);
    expectUV(sphereUV(c + Vec3(0, r, 0), c, r), 0.0f, 1.0f);
    expectUV(sphereUV(c + Vec3(0, -r, 0), c, r), 0.0f, 0.0f);
    // 45 degrees north, 60 degrees from +X toward +Z.
    const double lat = kPiD / 4, lon = kPiD / 3;
    const Vec3 d(float(std::cos(lat) * std::cos(lon)), float(std::sin(lat)),
                 float(std::cos(lat) * std::sin(lon)));
    expectUV(sphereUV(c + r * d, c, r), 1.0f / 6.0f, 0.75f);
    // 30 degrees south, 300 degrees round (z < 0: phi = 2 pi - acos).
    const double lat2 = -kPiD / 6, lon2 = 5 * kPiD / 3;
    const Vec3 d2(float(std::cos(lat2) * std::cos(lon2)), float(std::sin(lat2)),
                  float(std::cos(lat2) * std::sin(lon2)));
    expectUV(sphereUV(c + r * d2, c, r), 5.0f / 6.0f, 1.0f / 3.0f);
    // The centre itself has no direction.
    expectUV(sphereUV(c, c, r), 0.0f, 0.5f);
}

TEST(SphereUV, SeamWrapsFromOneToZeroAtPlusX) {
    const Vec3 c(0.0f);
    const ShapeUV above = sphereUV(Vec3(1.0f, 0.1f, 1e-4f), c, 1.0f);
    const ShapeUV below = sphereUV(Vec3(1.0f, 0.1f, -1e-4f), c, 1.0f);
    EXPECT_GE(above.u, 0.0f);
    EXPECT_LT(above.u, 1e-4f);
    EXPECT_LT(below.u, 1.0f);
    EXPECT_GT(below.u, 1.0f - 1e-4f);
    // u stays in [0, 1) on the seam itself and just below it.
    for (float z : {0.0f, -0.0f, -1e-30f, 1e-30f}) {
        const ShapeUV uv = sphereUV(Vec3(1.0f, 0.0f, z), c, 1.0f);
        EXPECT_GE(uv.u, 0.0f);
        EXPECT_LT(uv.u, 1.0f);
    }
    // Both sides share the seam's v and the gradient of u is continuous across it.
    EXPECT_NEAR(above.v, below.v, 1e-6f);
    EXPECT_NEAR(above.dudp.z, below.dudp.z, 1e-3f * std::abs(above.dudp.z));
}

TEST(SphereUV, GradientsMatchFiniteDifferences) {
    const Vec3 c(0.5f, 1.0f, -1.5f);
    const float r = 2.0f;
    const float dirs[][3] = {{0.3f, 0.5f, 0.8f},
                             {-0.7f, -0.2f, 0.4f},
                             {0.1f, 0.9f, -0.3f},
                             {-0.5f, 0.0f, -0.6f},
                             {0.8f, -0.6f, -0.1f}};
    for (const auto& q : dirs) {
        const Vec3 p = c + r * glm::normalize(Vec3(q[0], q[1], q[2]));
        Vec3 t1, t2;
        sphereTangents(p, c, t1, t2);
        expectGradients([&](const Vec3& x) { return sphereUV(x, c, r); }, p, t1, t2, 1e-3f, 2e-3f);
    }
    // Magnitudes: along the equator u runs once round 2 pi r, v pole to pole over pi r.
    const ShapeUV eq = sphereUV(c + Vec3(0, 0, r), c, r);
    EXPECT_NEAR(glm::length(eq.dudp), 1.0 / (2.0 * kPiD * r), 1e-6);
    EXPECT_NEAR(glm::length(eq.dvdp), 1.0 / (kPiD * r), 1e-6);
}

TEST(PlaneUV, FloorIsXAndMinusZ) {
    const ShapeUV uv = planeUV(Vec3(3.0f, 0.0f, -2.0f), Vec3(0.0f), Vec3(0, 1, 0));
    expectUV(uv, 3.0f, 2.0f);
    EXPECT_EQ(uv.dudp, Vec3(1, 0, 0));
    EXPECT_EQ(uv.dvdp, Vec3(0, 0, -1));
    // The reference point is the origin of the coordinates; the normal need not be unit.
    expectUV(planeUV(Vec3(4.5f, 1.0f, 0.0f), Vec3(1.0f, 1.0f, 1.0f), Vec3(0, 3, 0)), 3.5f, 1.0f);
}

TEST(PlaneUV, NormalsNearXUseZ) {
    // n = +X: T1 = Z, T2 = X x Z = -Y.
    const ShapeUV uv = planeUV(Vec3(0.0f, 2.0f, 5.0f), Vec3(0.0f), Vec3(1, 0, 0));
    expectUV(uv, 5.0f, -2.0f);
    // n = -X: T1 = Z, T2 = -X x Z = +Y.
    expectUV(planeUV(Vec3(0.0f, 2.0f, 5.0f), Vec3(0.0f), Vec3(-1, 0, 0)), 5.0f, 2.0f);
}

TEST(PlaneUV, TiltedPlaneIsAnOrthonormalProjection) {
    const Vec3 n = glm::normalize(Vec3(0.3f, 0.8f, -0.5f));
    const Vec3 point(1.0f, 2.0f, 3.0f);
    // Gram-Schmidt of X against n, written out: T1 = (X - n n.x) / |X - n n.x|.
    const double nx = n.x, ny = n.y, nz = n.z;
    const double ax = 1 - nx * nx, ay = -nx * ny, az = -nx * nz;
    const double len = std::sqrt(ax * ax + ay * ay + az * az);
    const double t1[3] = {ax / len, ay / len, az / len};
    const double t2[3] = {ny * t1[2] - nz * t1[1], nz * t1[0] - nx * t1[2],
                          nx * t1[1] - ny * t1[0]};
    const Vec3 d(0.7f, -1.1f, 2.3f);
    const ShapeUV uv = planeUV(point + d, point, n);
    EXPECT_NEAR(uv.u, d.x * t1[0] + d.y * t1[1] + d.z * t1[2], 1e-5);
    EXPECT_NEAR(uv.v, d.x * t2[0] + d.y * t2[1] + d.z * t2[2], 1e-5);
    EXPECT_NEAR(glm::dot(uv.dudp, n), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(uv.dvdp, uv.dudp), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(uv.dvdp), 1.0f, 1e-6f);
    const Vec3 t1v(t1[0], t1[1], t1[2]), t2v(t2[0], t2[1], t2[2]);
    expectGradients([&](const Vec3& x) { return planeUV(x, point, n); }, point + d, t1v, t2v, 1e-2f,
                    1e-3f);
}

TEST(RectangleUV, CornersAndCentre) {
    const Vec3 c(1.0f, 2.0f, 3.0f), u(2.0f, 0.0f, 0.0f), v(0.0f, 1.0f, 0.0f);
    expectUV(rectangleUV(c - u - v, c, u, v), 0.0f, 0.0f);
    expectUV(rectangleUV(c + u - v, c, u, v), 1.0f, 0.0f);
    expectUV(rectangleUV(c - u + v, c, u, v), 0.0f, 1.0f);
    expectUV(rectangleUV(c + u + v, c, u, v), 1.0f, 1.0f);
    expectUV(rectangleUV(c, c, u, v), 0.5f, 0.5f);
    // Repeats outside [0,1]^2 without clamping: two widths to the right.
    expectUV(rectangleUV(c + 3.0f * u, c, u, v), 2.0f, 0.5f);
}

TEST(RectangleUV, ShearedEdgesUseTheDualBasis) {
    const Vec3 c(0.0f), u(2.0f, 0.0f, 0.0f), v(1.0f, 1.0f, 0.0f);
    // c + a u + b v -> ((a + 1) / 2, (b + 1) / 2) for any a, b.
    for (float a : {-1.0f, -0.3f, 0.5f, 1.0f})
        for (float b : {-1.0f, 0.2f, 0.9f})
            expectUV(rectangleUV(c + a * u + b * v, c, u, v), 0.5f * (a + 1), 0.5f * (b + 1));
    const Vec3 n = glm::normalize(glm::cross(u, v));
    const Vec3 t1 = glm::normalize(u), t2 = glm::normalize(glm::cross(n, t1));
    expectGradients([&](const Vec3& x) { return rectangleUV(x, c, u, v); }, c + 0.3f * u - 0.2f * v,
                    t1, t2, 1e-2f, 1e-3f);
    // A tilted one in 3D.
    const Vec3 c3(1, 2, 3), u3(0.5f, 0.2f, -0.4f), v3(-0.1f, 0.9f, 0.3f);
    expectUV(rectangleUV(c3 + 0.4f * u3 - 0.6f * v3, c3, u3, v3), 0.7f, 0.2f);
}

struct Face {
    Vec3 n, right, up;  // outward normal; the viewer's right and up seen from outside
};

TEST(BoxUV, EveryFaceIsUprightSeenFromOutside) {
    const Vec3 lo(-1.0f, 0.0f, 2.0f), hi(3.0f, 2.0f, 5.0f);
    // Seen from outside the viewer looks along -n; right = forward x up.
    const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    const Face faces[] = {{X, glm::cross(-X, Y), Y},   {-X, glm::cross(X, Y), Y},
                          {Z, glm::cross(-Z, Y), Y},   {-Z, glm::cross(Z, Y), Y},
                          {Y, glm::cross(-Y, -Z), -Z}, {-Y, glm::cross(Y, Z), Z}};
    const Vec3 centre = 0.5f * (lo + hi), half = 0.5f * (hi - lo);
    for (const Face& f : faces) {
        const Vec3 onFace = centre + f.n * glm::dot(glm::abs(f.n), half);
        const ShapeUV mid = boxUV(onFace, f.n, lo, hi);
        expectUV(mid, 0.5f, 0.5f);
        // The lower-left corner seen from outside is (0, 0), the upper-right (1, 1).
        const Vec3 r = f.right * glm::dot(glm::abs(f.right), half);
        const Vec3 u = f.up * glm::dot(glm::abs(f.up), half);
        expectUV(boxUV(onFace - r - u, f.n, lo, hi), 0.0f, 0.0f);
        expectUV(boxUV(onFace + r + u, f.n, lo, hi), 1.0f, 1.0f);
        expectUV(boxUV(onFace + r - u, f.n, lo, hi), 1.0f, 0.0f);
        // Gradients: u grows along right, v along up, by one over the face's extents.
        EXPECT_NEAR(glm::dot(mid.dudp, f.right), 1.0f / glm::dot(glm::abs(f.right), hi - lo),
                    1e-6f);
        EXPECT_NEAR(glm::dot(mid.dvdp, f.up), 1.0f / glm::dot(glm::abs(f.up), hi - lo), 1e-6f);
        EXPECT_NEAR(glm::dot(mid.dudp, f.up), 0.0f, 1e-7f);
        EXPECT_NEAR(glm::dot(mid.dvdp, f.right), 0.0f, 1e-7f);
        expectGradients([&](const Vec3& x) { return boxUV(x, f.n, lo, hi); },
                        onFace + 0.3f * r - 0.1f * u, glm::normalize(f.right), glm::normalize(f.up),
                        1e-2f, 1e-3f);
    }
}

TEST(BoxUV, DocumentedFormulasAtAPoint) {
    const Vec3 lo(0.0f), hi(4.0f, 2.0f, 8.0f);
    const Vec3 p(1.0f, 0.5f, 2.0f);  // used on every face: only the chosen axes matter
    expectUV(boxUV(p, Vec3(1, 0, 0), lo, hi), (8.0f - 2.0f) / 8.0f, 0.25f);
    expectUV(boxUV(p, Vec3(-1, 0, 0), lo, hi), 2.0f / 8.0f, 0.25f);
    expectUV(boxUV(p, Vec3(0, 1, 0), lo, hi), 0.25f, (8.0f - 2.0f) / 8.0f);
    expectUV(boxUV(p, Vec3(0, -1, 0), lo, hi), 0.25f, 2.0f / 8.0f);
    expectUV(boxUV(p, Vec3(0, 0, 1), lo, hi), 0.25f, 0.25f);
    expectUV(boxUV(p, Vec3(0, 0, -1), lo, hi), 0.75f, 0.25f);
    // The dominant axis picks the face; ties go to X, then Y.
    expectUV(boxUV(p, Vec3(0.2f, -0.9f, 0.3f), lo, hi), 0.25f, 2.0f / 8.0f);
    expectUV(boxUV(p, Vec3(0.5f, 0.5f, 0.5f), lo, hi), (8.0f - 2.0f) / 8.0f, 0.25f);
    expectUV(boxUV(p, Vec3(0.0f, 0.5f, 0.5f), lo, hi), 0.25f, (8.0f - 2.0f) / 8.0f);
}

TEST(BoxUV, FlatBoxGivesZeroOnItsFlatAxis) {
    const ShapeUV uv = boxUV(Vec3(1.0f, 0.0f, 0.5f), Vec3(0, 0, 1), Vec3(0.0f, 0.0f, 0.0f),
                             Vec3(2.0f, 0.0f, 1.0f));
    EXPECT_NEAR(uv.u, 0.5f, 1e-6f);
    EXPECT_EQ(uv.v, 0.0f);
    EXPECT_EQ(uv.dvdp, Vec3(0.0f));
}

}  // namespace
}  // namespace rs
