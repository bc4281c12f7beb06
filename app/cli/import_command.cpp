// `raystudio-cli import ASSET -o SCENE`: a scene file holding one asset (glTF, OBJ, FBX, ...
// through assimp) with its materials and textures, its lights (or a key light) and a camera
// that frames it (or its own), ready for `render`.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "arguments.h"
#include "commands.h"
#include "io/asset_looks.h"
#include "io/mesh_io.h"
#include "io/scene_io.h"

namespace rs::cli {

namespace {
namespace fs = std::filesystem;

/// Of each half of the picture, what the framed box may fill (the rest is margin).
constexpr float kFramedFill = 0.9f;

/// A camera looking at `box` from the front right and a little above, as near as keeps all
/// eight corners of the box inside the picture (at the render's aspect) with a margin: a flat
/// or long asset fills the frame, not only the sphere around it.
Camera framing(const Aabb& box, const RenderSettings& render) {
    Camera c;
    const Vec3 centre = 0.5f * (box.min + box.max);
    const float radius = std::max(0.5f * glm::length(box.max - box.min), 1e-3f);
    const float aspect = float(render.width) / float(render.height);
    const float tanY = std::tan(0.5f * c.fovY * float(M_PI) / 180.0f) * kFramedFill;
    const float tanX = tanY * aspect;
    const Vec3 back = glm::normalize(Vec3(0.6f, 0.45f, 1.0f));
    const Vec3 forward = -back;
    const Vec3 right = glm::normalize(glm::cross(forward, c.up));
    const Vec3 up = glm::cross(right, forward);
    // A corner at `depth` beyond the centre and (x, y) off the axis is in the picture when
    // |x| <= tanX * (distance + depth), and likewise y; every corner stays in front.
    float distance = 0.0f;
    for (int k = 0; k < 8; ++k) {
        const Vec3 corner((k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
                          (k & 4) ? box.max.z : box.min.z);
        const Vec3 rel = corner - centre;
        const float depth = glm::dot(rel, forward);
        distance = std::max({distance, std::abs(glm::dot(rel, right)) / tanX - depth,
                             std::abs(glm::dot(rel, up)) / tanY - depth, 0.05f * radius - depth});
    }
    c.target = centre;
    c.position = centre + distance * back;
    return c;
}

/// One point light above, to the left of and in front of the asset (a photographer's key).
Light keyLight(const Aabb& box) {
    Light l;
    l.name = "key light";
    const float radius = std::max(0.5f * glm::length(box.max - box.min), 1e-3f);
    l.position = 0.5f * (box.min + box.max) + 3.0f * radius * Vec3(-0.6f, 1.0f, 0.8f);
    return l;
}
}  // namespace

int runImport(int argc, char** argv) {
    OptionSpec spec;
    spec.valued = {"--output", "--width", "--height", "--camera"};
    spec.flags = {"--flat-normals"};
    spec.aliases = {{"-o", "--output"}};
    Arguments args(argc, argv, 2, spec);
    if (args.positional().size() != 1) throw UsageError{"expects exactly one asset file"};
    const auto output = args.value("--output");
    if (!output) throw UsageError{"needs -o SCENE.scene.json"};
    const std::string camera = args.value("--camera").value_or("frame");
    if (camera != "frame" && camera != "asset")
        throw UsageError{"--camera must be frame or asset, got \"" + camera + "\""};
    SceneDocument doc;
    doc.render.width = args.intValue("--width", 1, 16384).value_or(doc.render.width);
    doc.render.height = args.intValue("--height", 1, 16384).value_or(doc.render.height);

    const std::string asset = args.positional()[0];
    const MeshLoadResult loaded = loadMesh(asset, !args.has("--flat-normals"));
    if (!loaded.ok()) {
        std::fprintf(stderr, "raystudio-cli: %s\n", loaded.error.c_str());
        return 2;
    }
    std::error_code ec;
    const fs::path scene = fs::absolute(*output, ec).lexically_normal();
    const fs::path sceneDir = scene.parent_path();
    if (!fs::is_directory(sceneDir, ec)) {
        std::fprintf(stderr, "raystudio-cli: %s: the folder does not exist\n",
                     sceneDir.string().c_str());
        return 2;
    }

    // The asset as it is, resting on y = 0 and centred over the origin.
    Object o;
    o.name = fs::path(asset).stem().string();
    if (o.name.empty()) o.name = "asset";
    MeshGeometry g;
    g.smoothNormals = !args.has("--flat-normals");
    g.resolvedPath = loaded.mesh->sourcePath;
    g.file = g.resolvedPath;
    g.data = loaded.mesh;
    o.geometry = std::move(g);
    const Aabb bounds = loaded.mesh->bounds();
    const Vec3 centre = 0.5f * (bounds.min + bounds.max);
    // (+ 0: no "-0" in the file for an asset already in place.)
    o.transform.translate = Vec3(-centre.x + 0.0f, -bounds.min.y + 0.0f, -centre.z + 0.0f);
    const ObjectId id = doc.addObject(std::move(o));
    const Aabb placed{bounds.min + doc.findObject(id)->transform.translate,
                      bounds.max + doc.findObject(id)->transform.translate};

    const AdoptedLooks looks =
        adoptAssetLooks(doc, id, loaded.asset ? *loaded.asset : AssetContent{},
                        fs::path(asset).filename().string(), sceneDir.string());
    for (const std::string& note : looks.notes)
        std::fprintf(stderr, "raystudio-cli: %s\n", note.c_str());
    const AssetContent none;
    const AssetContent& content = loaded.asset ? *loaded.asset : none;
    for (const std::string& note : content.lightNotes)
        std::fprintf(stderr, "raystudio-cli: asset \"%s\": %s\n",
                     fs::path(asset).filename().string().c_str(), note.c_str());
    doc.lights.clear();
    const std::size_t assetLights = adoptAssetLights(doc, id, content).size();
    if (assetLights == 0) doc.addLight(keyLight(placed));
    // Every camera of the asset is kept as a view (render --view NAME looks through it).
    const std::vector<std::string> views = adoptAssetViews(doc, id, content);
    if (camera == "asset") {
        if (content.views.empty()) {
            std::fprintf(stderr, "raystudio-cli: %s has no camera (--camera asset)\n",
                         asset.c_str());
            return 2;
        }
        doc.camera = doc.findView(views.front())->camera;
    } else {
        doc.camera = framing(placed, doc.render);
    }

    std::string error;
    if (!saveScene(scene.string(), doc, error)) {
        std::fprintf(stderr, "raystudio-cli: %s\n", error.c_str());
        return 1;
    }
    std::printf("wrote %s: %zu triangles, %zu materials, %zu embedded images, %s, %s\n",
                scene.string().c_str(), loaded.mesh->triangleCount(), looks.materials.size(),
                looks.images.size(),
                assetLights ? (std::to_string(assetLights) +
                               (assetLights == 1 ? " light" : " lights") + " of the asset")
                                  .c_str()
                            : "a key light (the asset has none)",
                camera == "asset" ? ("its camera \"" + views[0] + "\"").c_str()
                                  : "a camera that frames it");
    if (!views.empty()) {
        std::string list;
        for (const std::string& v : views)
            list.append(list.empty() ? "\"" : ", \"").append(v) += '"';
        std::printf("its cameras are views %s (render --view NAME)\n", list.c_str());
    }
    std::printf("moved by (%g, %g, %g) to rest on y = 0, centred over the origin\n",
                double(-centre.x + 0.0f), double(-bounds.min.y + 0.0f), double(-centre.z + 0.0f));
    return 0;
}

}  // namespace rs::cli
