// Giving an imported mesh object what its asset brought: the asset's materials become the
// document's, its parts name them, its embedded images become files; its lights and cameras
// are placed as the object is.
#pragma once

#include <string>
#include <vector>

#include "io/asset_content.h"
#include "scene/document.h"

namespace rs {

/// What adopting an asset's looks did.
struct AdoptedLooks {
    std::vector<std::string> materials;  ///< Names of the materials added, in asset order.
    std::vector<std::string> images;     ///< Image files written.
    /// What the looks could not keep, each naming the asset, the part and the file.
    std::vector<std::string> notes;
};

/// Gives mesh object `id` of `doc` the looks of `asset` (what the mesh's import brought):
/// each look becomes a material of `doc`, renamed "name.001", ... when the name is taken, and
/// the object's MeshGeometry::partMaterials name them by file material index. Embedded images
/// are written to `imageDir` (created when missing) as "<assetName>-<n>.<format>"; one that
/// cannot be written leaves its part untextured, with a note. `assetName` names the asset in
/// notes and files (its file name without folder).
AdoptedLooks adoptAssetLooks(SceneDocument& doc, ObjectId id, const AssetContent& asset,
                             const std::string& assetName, const std::string& imageDir);

/// Adds the lights of `asset` to `doc`, placed by mesh object `id`'s transform as its
/// geometry is (positions, targets and directions; a sphere light's radius scaled), each
/// named as in the asset unless an object or light of `doc` has that name ("name.001", ...).
/// Returns the ids given.
std::vector<ObjectId> adoptAssetLights(SceneDocument& doc, ObjectId id, const AssetContent& asset);

/// Camera `view` of the asset placed by `placed`'s transform (mesh object of the asset).
Camera placedAssetCamera(const AssetView& view, const Object& placed);

/// Adds the cameras of `asset` to `doc.views` (view bookmarks), placed by mesh object `id`'s
/// transform (placedAssetCamera), each named as in the asset ("Camera" when it has no name)
/// unless a view of `doc` has that name ("name.001", ...). Returns the names given.
std::vector<std::string> adoptAssetViews(SceneDocument& doc, ObjectId id,
                                         const AssetContent& asset);

}  // namespace rs
