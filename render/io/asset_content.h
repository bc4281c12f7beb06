// What an imported asset brings besides its triangles: its materials mapped to ours
// (io/asset_material.h) and the images embedded in it. The import child collects it
// (io/mesh_import.cpp) and sends it with the mesh (io/mesh_wire.h) as text the scene reader
// checks like any scene file, so a material's fields are read and bounded in one place.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "scene/document.h"

namespace rs {

/// An image stored inside the asset file (a GLB's or FBX's embedded texture): the file's
/// bytes as they are (PNG, JPEG, ...).
struct AssetImage {
    std::string name;        ///< The name the asset gives it, or "".
    std::string formatHint;  ///< assimp's hint: "png", "jpg", ... (letters and digits only).
    std::string bytes;
};

/// One material of the asset that some of its triangles use.
struct AssetLook {
    uint32_t index = 0;  ///< The file's material index (MeshPart::material).
    /// The mapped material, its name unique within the asset. With an embedded texture its
    /// pattern is an ImageTexture whose scale and offset are set and whose image is empty
    /// until the importer writes the image out (extractAssetImages).
    Material material;
    int embeddedImage = -1;          ///< Index into AssetContent::images, or -1.
    std::vector<std::string> notes;  ///< What the asset says that the material cannot.
};

/// A camera of the asset, in the asset's own coordinates.
struct AssetView {
    std::string name;
    Camera camera;
};

struct AssetContent {
    std::vector<AssetLook> looks;  ///< In increasing file material index.
    std::vector<AssetImage> images;
    /// The asset's lights (io/asset_lights.h) in its own coordinates, named uniquely and
    /// never "" within the asset; their ids are not given yet.
    std::vector<Light> lights;
    std::vector<AssetView> views;  ///< Its cameras, in its own coordinates.
    /// What its lights and cameras could not keep (each names the light or camera).
    std::vector<std::string> lightNotes;
    /// The look for file material `index`, or null when no triangle uses it.
    const AssetLook* look(uint32_t index) const;
};

/// Longest embedded image accepted from an asset, like an image file's limit.
inline constexpr std::size_t kMaxAssetImageBytes = std::size_t(256) << 20;

/// The looks, lights and cameras as text (the images' bytes travel beside it); `assetDir` is the
/// asset's folder, against which texture paths are written and read.
std::string encodeAssetLooks(const AssetContent& content, const std::string& assetDir);
/// Reads what encodeAssetLooks wrote into `content.looks` and the names of `images` (which
/// must already have their count); false with `why` set when the text is not that.
bool decodeAssetLooks(const std::string& text, const std::string& assetDir, AssetContent& content,
                      std::string& why);

/// `base`, or "base.001", "base.002", ... : the first that `taken` says is free (Blender's
/// rule for a repeated name).
template <class Taken>
std::string numberedName(const std::string& base, Taken taken) {
    if (!taken(base)) return base;
    for (int n = 1;; ++n) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", n);
        if (!taken(base + suffix)) return base + suffix;
    }
}

}  // namespace rs
