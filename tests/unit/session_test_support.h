// The session tests' shared pieces: the invariant's comparison with a full render, and the
// rooms the session tests edit.
#pragma once

#include <gtest/gtest.h>

#include <chrono>

#include "integrator/renderer.h"
#include "session/render_session.h"
#include "test_scenes.h"

namespace rs::test {

using namespace std::chrono_literals;

/// Largest per-channel difference between the session's frame and a fresh full render with
/// the session's engine; the object ids seen through the pixel centres must agree too.
inline float maxDiffToFullRender(RenderSession& session, const SceneDocument& doc) {
    const RenderResult full = renderImage(CompiledScene(doc, nullptr, session.engine()));
    float worst = 0.0f;
    session.withFrame([&](const DeepFrame& frame, const auto& snapshot) {
        EXPECT_EQ(frame.pixelCount(), full.image.pixels.size());
        if (frame.pixelCount() != full.image.pixels.size()) {
            worst = kInfinity;
            return;
        }
        EXPECT_EQ(snapshot->engineKind(), session.engine());
        std::size_t idMismatches = 0;
        for (std::size_t i = 0; i < frame.pixelCount(); ++i) {
            const Color d = glm::abs(frame.color()[i] - full.image.pixels[i]);
            worst = std::max(worst, std::max(d.x, std::max(d.y, d.z)));
            idMismatches += frame.id()[i] != full.ids[i];
        }
        EXPECT_EQ(idMismatches, 0u);
    });
    return worst;
}

/// testRoom plus one object of every other kind: a rotated box, a rectangle, a mesh.
inline SceneDocument mixedRoom(bool orthographic) {
    SceneDocument doc = test::smallRoom(64, 48);
    doc.render.shadowSamples = 2;
    Object box;
    box.name = "box";
    box.material = "red";
    box.geometry = BoxGeometry{Vec3(-0.3f), Vec3(0.3f)};
    box.transform.translate = Vec3(-0.4f, -1.6f, -3.5f);
    box.transform.rotate = Vec3(10, 35, 0);
    doc.addObject(box);
    Object panel;
    panel.name = "panel";
    panel.material = "mirror";
    panel.geometry =
        RectangleGeometry{Vec3(2.0f, -1.0f, -6.0f), Vec3(0.6f, 0, 0.3f), Vec3(0, 0.6f, 0)};
    doc.addObject(panel);
    Object mesh;
    mesh.name = "mesh";
    mesh.material = "white";
    MeshGeometry g;
    g.file = "tetrahedron.obj";
    g.data = test::tetrahedron();
    g.smoothNormals = false;
    mesh.geometry = g;
    mesh.transform.translate = Vec3(0.8f, -1.5f, -3.2f);
    mesh.transform.scale = Vec3(1.0f, 1.5f, 1.0f);
    doc.addObject(mesh);
    if (orthographic) {
        doc.camera.projection = Projection::Orthographic;
        doc.camera.orthoHeight = 5.0f;
    }
    return doc;
}

inline SceneDocument testRoom() {
    SceneDocument doc = test::smallRoom(64, 48);
    Light area;
    area.name = "area";
    area.type = LightType::Sphere;
    area.position = Vec3(-2, 2.5f, -3);
    area.radius = 0.4f;
    area.intensity = 0.5f;
    doc.addLight(area);
    doc.render.shadowSamples = 4;
    return doc;
}

/// Renders `doc` under `policy` with every pixel dirty on every edit and no governor (exactly
/// this policy, whatever the machine's speed), then begins dragging objects[2] and moves it
/// once; true when that step's interactive pass finished (its info in `info`).
inline bool firstDragStep(RenderSession& session, SceneDocument& doc, InteractionPolicy policy,
                          PassInfo& info) {
    policy.dirtyRegions = false;
    policy.governorTargetMs = 0.0;
    session.setPolicy(policy);
    session.update(doc);
    if (!session.waitUntilComplete(60s)) return false;
    session.beginInteraction(doc.objects[2].id);
    doc.objects[2].transform.translate.x += 0.3f;
    const uint64_t gen = session.update(doc);
    return session.waitForPass(gen, 30s, &info) && info.kind == PassKind::Interactive;
}

}  // namespace rs::test
