// A scene with every kind of bounded object for the edit tests (dirty precision, invariant).
#pragma once

#include "test_scenes.h"

namespace rs::test {

/// An octahedron with per-vertex normals (the directions of its vertices), so smooth
/// normals change its shading.
inline std::shared_ptr<const MeshData> octahedron() {
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {Vec3(0.4f, 0, 0),  Vec3(-0.4f, 0, 0), Vec3(0, 0.4f, 0),
                       Vec3(0, -0.4f, 0), Vec3(0, 0, 0.4f),  Vec3(0, 0, -0.4f)};
    for (const Vec3& p : mesh->positions) mesh->normals.push_back(glm::normalize(p));
    mesh->indices = {0, 2, 4, 4, 2, 1, 1, 2, 5, 5, 2, 0, 4, 3, 0, 1, 3, 4, 5, 3, 1, 0, 3, 5};
    return mesh;
}

/// The small room plus a box, a rectangle, a smooth mesh and a sphere light: every kind of
/// bounded object, a mirror and glass (secondary rays) and soft shadows.
inline SceneDocument editRoom(int width = 64, int height = 48) {
    SceneDocument doc = smallRoom(width, height);
    doc.render.shadowSamples = 2;
    addMaterial(doc, "paint", Color(0.3f, 0.6f, 0.9f), 0.9f, 0.2f);
    addMaterial(doc, "card", Color(0.9f, 0.7f, 0.2f), 0.9f);
    Object box;
    box.name = "box";
    box.material = "paint";
    box.geometry = BoxGeometry{Vec3(-0.3f), Vec3(0.3f)};
    box.transform.translate = Vec3(-0.4f, -1.6f, -3.5f);
    box.transform.rotate = Vec3(10, 35, 0);
    doc.addObject(box);
    Object card;
    card.name = "card";
    card.material = "card";
    card.geometry =
        RectangleGeometry{Vec3(2.0f, -1.0f, -6.0f), Vec3(0.5f, 0, 0.3f), Vec3(0, 0.5f, 0)};
    doc.addObject(card);
    Object mesh;
    mesh.name = "gem";
    mesh.material = "white";
    MeshGeometry g;
    g.file = "octahedron.obj";
    g.data = octahedron();
    g.smoothNormals = true;
    mesh.geometry = g;
    mesh.transform.translate = Vec3(0.9f, -1.5f, -3.0f);
    doc.addObject(mesh);
    Light area;
    area.name = "area";
    area.type = LightType::Sphere;
    area.position = Vec3(-2, 2.5f, -3);
    area.radius = 0.4f;
    area.intensity = 0.5f;
    doc.addLight(area);
    return doc;
}

}  // namespace rs::test
