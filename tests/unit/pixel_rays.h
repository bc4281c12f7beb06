// The camera rays through every pixel centre of a scene, with the renderer's per-pixel seeds,
// for tests that trace a whole image through the kernel as one batch.
#pragma once

#include <vector>

#include "integrator/sampling.h"
#include "integrator/trace_kernel.h"
#include "scene/document.h"
#include "snapshot/compiled_scene.h"

namespace rs::test {

struct PixelRays {
    std::vector<Vec3> origin, dir;
    std::vector<uint32_t> seed;

    PixelRays(const CompiledScene& scene, int width, int height) {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const Ray r = scene.camera().generateRay(float(x) + 0.5f, float(y) + 0.5f);
                origin.push_back(r.origin), dir.push_back(r.dir);
                seed.push_back(hash32(uint32_t(y * width + x)));
            }
    }
    std::size_t size() const { return origin.size(); }
    /// All of them as one coherent batch.
    CameraBatch batch() const { return {origin.data(), dir.data(), seed.data(), size(), true}; }
    /// Ray i alone.
    CameraBatch one(std::size_t i) const { return {&origin[i], &dir[i], &seed[i], 1, true}; }
};

/// A sampled sphere light of radius 0.4 at `position`.
inline ObjectId addSphereLight(SceneDocument& doc, const std::string& name, Vec3 position) {
    Light sphere;
    sphere.name = name;
    sphere.type = LightType::Sphere;
    sphere.radius = 0.4f;
    sphere.position = position;
    return doc.addLight(sphere);
}

}  // namespace rs::test
