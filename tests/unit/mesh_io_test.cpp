// Mesh loading through assimp: formats, node transforms, degenerate triangles and bad files.
#include "io/mesh_io.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>

namespace rs {
namespace {

std::string meshPath(const char* name) {
    return std::string(RAYSTUDIO_TEST_DATA) + "/meshes/" + name;
}

struct FormatCase {
    const char* file;
    std::size_t triangles;
    Vec3 min;
    Vec3 max;
};

class MeshFormat : public testing::TestWithParam<FormatCase> {};

TEST_P(MeshFormat, LoadsWithTriangleCountAndBounds) {
    const FormatCase& c = GetParam();
    MeshLoadResult r = loadMesh(meshPath(c.file), true);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.mesh->triangleCount(), c.triangles);
    EXPECT_EQ(r.mesh->indices.size(), 3 * c.triangles);
    Aabb b = r.mesh->bounds();
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(b.min[a], c.min[a], 1e-5f) << "axis " << a;
        EXPECT_NEAR(b.max[a], c.max[a], 1e-5f) << "axis " << a;
    }
    EXPECT_EQ(r.mesh->droppedDegenerate, 0u);
    EXPECT_TRUE(std::filesystem::path(r.mesh->sourcePath).is_absolute());
    for (uint32_t i : r.mesh->indices) ASSERT_LT(i, r.mesh->positions.size());
}

INSTANTIATE_TEST_SUITE_P(
    Formats, MeshFormat,
    testing::Values(FormatCase{"cube.obj", 12, Vec3(0), Vec3(1)},
                    FormatCase{"tetra.ply", 4, Vec3(0), Vec3(1)},
                    FormatCase{"tetra.stl", 4, Vec3(0), Vec3(1)},
                    // The node translates the unit quad by +10 in x: transforms are applied.
                    FormatCase{"quad_translated.gltf", 2, Vec3(10, 0, 0), Vec3(11, 1, 0)},
                    FormatCase{"cube.glb", 12, Vec3(0), Vec3(1)},
                    FormatCase{"cube.fbx", 12, Vec3(0), Vec3(1)}),
    [](const testing::TestParamInfo<FormatCase>& info) {
        std::string name = info.param.file;
        for (char& ch : name)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return name;
    });

TEST(MeshIo, SmoothNormals_GivesOneUnitNormalPerVertex) {
    MeshLoadResult r = loadMesh(meshPath("cube.obj"), true);
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.mesh->normals.size(), r.mesh->positions.size());
    for (const Vec3& n : r.mesh->normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    // A cube corner's smooth normal points diagonally away from the centre.
    for (std::size_t i = 0; i < r.mesh->positions.size(); ++i) {
        Vec3 outward = r.mesh->positions[i] - Vec3(0.5f);
        EXPECT_GT(glm::dot(r.mesh->normals[i], outward), 0.0f);
    }
}

TEST(MeshIo, FlatShading_LeavesNormalsEmptyAndSharesVertices) {
    MeshLoadResult r = loadMesh(meshPath("tetra.stl"), false);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.mesh->normals.empty());
    // STL repeats corners per facet; joined, the tetrahedron has its 4 corners.
    EXPECT_EQ(r.mesh->positions.size(), 4u);
}

TEST(MeshIo, DegenerateTriangles_AreDroppedAndCounted) {
    MeshLoadResult r = loadMesh(meshPath("degenerate.obj"), false);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.mesh->triangleCount(), 2u);
    EXPECT_EQ(r.mesh->droppedDegenerate, 2u);
    // The vertex only a dropped triangle used (2, 0, 0) is gone from the bounds.
    EXPECT_EQ(r.mesh->bounds().max, Vec3(1, 1, 0));
}

TEST(MeshIo, NanVertex_IsAnErrorNamingThePath) {
    MeshLoadResult r = loadMesh(meshPath("nan_vertex.obj"), true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find(meshPath("nan_vertex.obj")), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("not a finite number"), std::string::npos) << r.error;
}

TEST(MeshIo, NoTriangles_IsAnError) {
    MeshLoadResult r = loadMesh(meshPath("lines_only.obj"), true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("no triangles"), std::string::npos) << r.error;
}

TEST(MeshIo, MissingFile_ErrorNamesThePath) {
    MeshLoadResult r = loadMesh(meshPath("missing.obj"), true);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.mesh, nullptr);
    EXPECT_NE(r.error.find(meshPath("missing.obj")), std::string::npos) << r.error;
}

TEST(MeshIo, FileAssimpCannotRead_IncludesAssimpsReason) {
    // A scene file is JSON, which no assimp importer accepts.
    std::string path = std::string(RAYSTUDIO_TEST_DATA) + "/scenes/example.scene.json";
    MeshLoadResult r = loadMesh(path, true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("assimp"), std::string::npos) << r.error;
}

TEST(MeshIo, Directory_IsAnError) {
    MeshLoadResult r = loadMesh(std::string(RAYSTUDIO_TEST_DATA) + "/meshes", true);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("not a regular file"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace rs
