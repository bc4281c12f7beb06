// Mesh geometry edits through the interactive session: the viewport must show the new mesh,
// not a refit of the old one.
#include <gtest/gtest.h>

#include "integrator/renderer.h"
#include "io/mesh_io.h"
#include "session/render_session.h"
#include "test_scenes.h"

namespace rs {
namespace {

using namespace std::chrono_literals;

const std::string kTorus = RAYSTUDIO_SCENES_DIR "/meshes/torus.obj";

/// Largest per-channel difference between the session's frame and a full render of `doc`.
float maxDiffToFullRender(RenderSession& session, const SceneDocument& doc) {
    const RenderResult full = renderImage(CompiledScene(doc));
    float worst = 0.0f;
    session.withFrame([&](const DeepFrame& frame, const auto&) {
        if (frame.pixelCount() != full.image.pixels.size()) {
            worst = kInfinity;
            return;
        }
        for (std::size_t i = 0; i < frame.pixelCount(); ++i) {
            const Color d = glm::abs(frame.color()[i] - full.image.pixels[i]);
            worst = std::max(worst, std::max(d.x, std::max(d.y, d.z)));
        }
    });
    return worst;
}

/// The small room with the torus mesh in front of the camera, loaded as the designer does.
SceneDocument roomWithTorus(bool smooth, ObjectId& torus) {
    SceneDocument doc = test::smallRoom(96, 72);
    Object o;
    o.name = "torus";
    o.material = "white";
    MeshGeometry g;
    g.file = g.resolvedPath = kTorus;
    g.smoothNormals = smooth;
    g.data = loadMesh(kTorus, smooth).mesh;
    o.geometry = std::move(g);
    o.transform.translate = Vec3(0.0f, -0.9f, -3.2f);
    o.transform.rotate = Vec3(60.0f, 25.0f, 0.0f);
    o.transform.scale = Vec3(0.6f);
    torus = doc.addObject(std::move(o));
    return doc;
}

/// What the property panel does for the smooth_normals checkbox: flip it and reload the mesh.
void setSmoothNormals(SceneDocument& doc, ObjectId id, bool smooth) {
    auto& mesh = std::get<MeshGeometry>(doc.findObject(id)->geometry);
    mesh.smoothNormals = smooth;
    mesh.data = loadMesh(mesh.resolvedPath, smooth).mesh;
}

TEST(RenderSession, TogglingSmoothNormals_FrameEqualsFullRenderOfTheNewMesh) {
    for (const bool smoothFirst : {true, false}) {
        ObjectId torus = kNoObject;
        SceneDocument doc = roomWithTorus(smoothFirst, torus);
        ASSERT_NE(std::get<MeshGeometry>(doc.findObject(torus)->geometry).data, nullptr);
        RenderSession session(2);
        session.update(doc);
        ASSERT_TRUE(session.waitUntilComplete(60s));
        ASSERT_LE(maxDiffToFullRender(session, doc), 1e-5f);

        const SceneDocument before = doc;
        setSmoothNormals(doc, torus, !smoothFirst);
        // The shading differs visibly, so a frame that kept the old normals cannot pass.
        ASSERT_GT(maxDiffToFullRender(session, doc), 1e-2f);
        session.update(doc);
        ASSERT_TRUE(session.waitUntilComplete(60s));
        EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f) << "smooth first: " << smoothFirst;

        // And back: the session must not keep either mesh BVH past its edit.
        setSmoothNormals(doc, torus, smoothFirst);
        session.update(doc);
        ASSERT_TRUE(session.waitUntilComplete(60s));
        EXPECT_LE(maxDiffToFullRender(session, before), 1e-5f);
    }
}

TEST(RenderSession, SmoothNormalsFlagAlone_FrameEqualsFullRender) {
    // A document edited outside the property panel may flip the flag on the same data.
    ObjectId torus = kNoObject;
    SceneDocument doc = roomWithTorus(true, torus);
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    std::get<MeshGeometry>(doc.findObject(torus)->geometry).smoothNormals = false;
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    EXPECT_LE(maxDiffToFullRender(session, doc), 1e-5f);
}

}  // namespace
}  // namespace rs
