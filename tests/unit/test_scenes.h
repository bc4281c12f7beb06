// Small scenes built in code for the integrator and renderer tests.
#pragma once

#include <memory>
#include <string>

#include "scene/document.h"
#include "scene/mesh_data.h"

namespace rs::test {

/// A document with one material per call, returning the material's name.
inline std::string addMaterial(SceneDocument& doc, const std::string& name, Color color,
                               float diffuse, float specular = 0.0f, float reflectivity = 0.0f,
                               float transparency = 0.0f, float ior = 1.5f) {
    Material m;
    m.name = name;
    m.color = color;
    m.diffuse = diffuse;
    m.specular = specular;
    m.reflectivity = reflectivity;
    m.transparency = transparency;
    m.ior = ior;
    doc.materials.push_back(m);
    return name;
}

inline ObjectId addSphere(SceneDocument& doc, const std::string& name, Vec3 center, float radius,
                          const std::string& material) {
    Object o;
    o.name = name;
    o.material = material;
    o.geometry = SphereGeometry{center, radius};
    return doc.addObject(o);
}

inline ObjectId addPlane(SceneDocument& doc, const std::string& name, Vec3 point, Vec3 normal,
                         const std::string& material) {
    Object o;
    o.name = name;
    o.material = material;
    o.geometry = PlaneGeometry{point, normal};
    return doc.addObject(o);
}

inline ObjectId addPointLight(SceneDocument& doc, const std::string& name, Vec3 position,
                              float intensity = 1.0f) {
    Light l;
    l.name = name;
    l.position = position;
    l.intensity = intensity;
    return doc.addLight(l);
}

inline ObjectId addSphereLight(SceneDocument& doc, const std::string& name, Vec3 position,
                               float radius) {
    Light l;
    l.name = name;
    l.type = LightType::Sphere;
    l.position = position;
    l.radius = radius;
    return doc.addLight(l);
}

/// A small room: floor, back wall, a diffuse, a mirror and a glass ball, one light.
inline SceneDocument smallRoom(int width = 64, int height = 48) {
    SceneDocument doc;
    doc.render.width = width;
    doc.render.height = height;
    doc.camera.position = Vec3(0, 0, 0);
    doc.camera.target = Vec3(0, -0.5f, -4);
    addMaterial(doc, "white", Color(0.75f), 0.9f, 0.3f);
    addMaterial(doc, "red", Color(0.8f, 0.2f, 0.2f), 1.0f);
    addMaterial(doc, "mirror", Color(0.9f), 0.0f, 0.0f, 0.9f);
    addMaterial(doc, "glass", Color(1.0f), 0.0f, 0.5f, 0.0f, 1.0f, 1.5f);
    addPlane(doc, "floor", Vec3(0, -2, 0), Vec3(0, 1, 0), "white");
    addPlane(doc, "back", Vec3(0, 0, -8), Vec3(0, 0, 1), "red");
    addSphere(doc, "diffuse ball", Vec3(-1.5f, -1.2f, -5), 0.8f, "white");
    addSphere(doc, "mirror ball", Vec3(0.3f, -1.0f, -6), 1.0f, "mirror");
    addSphere(doc, "glass ball", Vec3(1.2f, -1.4f, -4), 0.6f, "glass");
    addPointLight(doc, "key", Vec3(0, 3, -3));
    return doc;
}

/// A small tetrahedron mesh built in code (no file), shared by the documents that use it.
inline std::shared_ptr<const MeshData> tetrahedron() {
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {Vec3(0, 0.5f, 0), Vec3(-0.4f, -0.3f, 0.3f), Vec3(0.4f, -0.3f, 0.3f),
                       Vec3(0, -0.3f, -0.4f)};
    mesh->indices = {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2};
    return mesh;
}

/// `n` spheres in a row, "sphere 0" to "sphere n-1", one material ("red", used by none) and a
/// light ("key"): the scene of the tests of edits, lookups and panels at scale.
inline SceneDocument manySpheres(int n) {
    SceneDocument doc;
    Material red;
    red.name = "red";
    doc.materials.push_back(red);
    for (int i = 0; i < n; ++i) {
        Object o;
        o.name = "sphere " + std::to_string(i);
        o.geometry = SphereGeometry{Vec3(float(i), 0.0f, 0.0f), 0.4f};
        doc.addObject(o);
    }
    Light key;
    key.name = "key";
    doc.addLight(key);
    return doc;
}

}  // namespace rs::test
