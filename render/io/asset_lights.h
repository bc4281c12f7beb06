// The lights and cameras an imported asset brings along (scenes/FORMAT.md, "Lights and cameras
// of imported assets"): assimp's aiLight and aiCamera, placed by their nodes, as ours.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "scene/document.h"

struct aiScene;

namespace rs {

/// One camera of an asset: its name in the asset (the node's) and our camera.
struct AssetCamera {
    std::string name;
    Camera camera;
};

/// What assetLightsAndCameras found: lights with the asset's names (ids not yet given), the
/// cameras, and one sentence per thing skipped or approximated, naming it.
struct AssetLightsAndCameras {
    std::vector<Light> lights;
    std::vector<AssetCamera> cameras;
    std::vector<std::string> notes;
};

/// The lights and cameras of `scene`, each placed by the world transform of the node that
/// bears its name (composed from the root down), then by `assetToScene` (the placement the
/// import gives the asset's geometry). Point, spot and directional lights become ours; area,
/// ambient and unknown ones are skipped with a note. Works around assimp 5.2.5's glTF quirks
/// (spot angles stored as half-angles, a camera's node translation copied into its position,
/// the field of view stored as yfov * aspect).
///
/// `scene` must be read without aiProcess_PreTransformVertices: that step moves a glTF camera,
/// whose position assimp already set to its node's translation, by the node's transform again,
/// and drops the nodes this needs to undo it. The import can read without it, call this, then
/// Assimp::Importer::ApplyPostProcessing(aiProcess_PreTransformVertices) for the geometry.
AssetLightsAndCameras assetLightsAndCameras(const aiScene& scene, const Mat4& assetToScene);

}  // namespace rs
