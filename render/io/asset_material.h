// One material of an imported asset (glTF, OBJ/MTL, FBX, ... through assimp) as a RayStudio
// Material: a pure mapping, with what the Whitted model cannot express written down as notes.
//
// The mapping, rule by rule ($... and ?...: the assimp keys read; each number is clamped to
// its field's range, and a value that is not finite is ignored with a note):
//   name          ?mat.name; empty: "asset material N" (N the material's index in the asset).
//   color         $clr.base (glTF baseColorFactor) rgb, else $clr.diffuse (MTL Kd) rgb.
//   texture       the first BaseColor texture, else the first Diffuse one (MTL map_Kd): a file
//                 (relative to the asset's folder, '\' read as '/') or an embedded image ("*N",
//                 or a name an embedded image carries). Its uv channel ($tex.uvwsrc) and
//                 $tex.uvtrafo (KHR_texture_transform) come along unchanged; without rotation
//                 the transform becomes the ImageTexture's scale and offset as they stand
//                 (assimp 5.2.5 already flips glTF's V for them: offset_v = 1 - scale_v - o_v,
//                 which is right when read as uv * scale + translation; assimp's own
//                 TransformUVCoords translates first, and PR 6804 proposes storing a
//                 pre-scale translation, which a newer assimp would need undone here). MTL's
//                 map_Kd -s/-o options never arrive: assimp 5.2.5 drops them unread.
//                 The texture replaces the colour: a base colour factor that is not white,
//                 which the asset multiplies in, is noted.
//   PBR (when $mat.metallicFactor m is present; $mat.roughnessFactor r defaults to 1 as in
//   glTF; a roughness alone is FBX's, derived by assimp from the Phong exponent: Phong below):
//     reflectivity  m * (1 - r): only smooth metal is a mirror (our mirror is not tinted).
//     specular      1 - r: the highlight's weight.
//     shininess     0.5 / r^4 - 0.5 in [1, 10000]: the Phong exponent whose lobe matches GGX
//                   (alpha = r^2) through Blinn-Phong 2 / alpha^2 - 2, a quarter of it for
//                   Phong's R.V.
//   Phong (otherwise, e.g. OBJ/MTL, FBX; m counts as 0):
//     specular      Rec. 709 luminance of $clr.specular (Ks) times $mat.shinpercent if present.
//     shininess     $mat.shininess (Ns), in [0, 10000].
//     reflectivity  $mat.reflectivity, in [0, 1].
//   glass         transparency = $mat.transmission.factor (KHR_materials_transmission) times
//                 (1 - m); ior = $mat.refracti (KHR_materials_ior, MTL Ni) when > 0, else 1.5.
//   see-through   opacity $mat.opacity (MTL d; assimp turns Tr into d = 1 - Tr), else
//                 1 - $mat.transparencyfactor: transparency = max(glass, 1 - opacity). With
//                 no transmission the ior stays $mat.refracti, else 1 (straight through, as
//                 alpha blending shows it; MTL's default Ni is 1 too). glTF alpha counts only
//                 in alphaMode BLEND; MASK's cut-out is noted.
//   sum           reflectivity + transparency <= 1: transparency gives way.
//   noted only    emissive colour, a texture's clamp/mirror wrap modes, texture rotation,
//                 a UV channel other than 0, a second texture of the same kind.
//   ignored       ambient colour (the scene's ambient applies), two-sidedness, shading model.
#pragma once

#include <string>
#include <vector>

#include "scene/document.h"

struct aiMaterial;

namespace rs {

/// What the mapping needs to know about the asset around one of its materials.
struct AssetTextureContext {
    std::string assetDir;  ///< Folder of the asset file: texture paths are relative to it.
    std::vector<std::string> embeddedNames;  ///< aiScene::mTextures[i]->mFilename, in order.
    unsigned materialIndex = 0;              ///< For a nameless material's name.
};

/// assimp's aiUVTransform as the asset gave it: uv' = uv * scale + translation in assimp's
/// (V up) texture space, rotated by `rotation` radians counter-clockwise about (0.5, 0.5).
struct AssetUvTransform {
    float translationU = 0.0f, translationV = 0.0f;
    float scaleU = 1.0f, scaleV = 1.0f;
    float rotation = 0.0f;
    bool operator==(const AssetUvTransform&) const = default;
};

/// The base-colour texture of an asset material.
struct AssetTexture {
    enum class Source { None, File, Embedded };
    Source source = Source::None;
    std::string path;        ///< As the asset names it: a file path or "*N".
    int embeddedIndex = -1;  ///< Embedded: the index into aiScene::mTextures.
    unsigned uvChannel = 0;  ///< The aiMesh texture-coordinate channel it reads.
    bool hasTransform = false;
    AssetUvTransform transform;  ///< $tex.uvtrafo, when hasTransform.
    /// Scale and offset from the transform; the image is set for a File (file: the path as
    /// given, resolvedPath: against the asset's folder), empty for an Embedded one until the
    /// importer extracts it.
    ImageTexture look;
};

struct AssetMaterial {
    Material material;  ///< Its pattern is the texture's look when that names a file.
    AssetTexture texture;
    std::vector<std::string> notes;  ///< What the asset says that the material cannot.
};

/// Maps one assimp material (see the table at the top of this file). Pure: reads no file.
AssetMaterial mapAssetMaterial(const aiMaterial& in, const AssetTextureContext& context);

}  // namespace rs
