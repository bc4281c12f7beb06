// Document edits of a material's colour form (flat colour, checker or image texture), as pure
// functions on a SceneDocument: the property panel's mode selector and an image dropped on an
// object in the viewport use them, and tests call them alike.
#pragma once

#include <string>

#include "scene/document.h"

namespace rs::ui {

/// What a material's colour is, as the mode selector offers it.
enum class ColorMode { Colour = 0, Checker = 1, Image = 2 };

/// The mode `m` is in (Colour when it has no pattern).
ColorMode colorModeOf(const Material& m);

/// A checker with the schema's defaults (render/scene/parameters.cpp), except that its first
/// colour is `m`'s flat colour, so the material keeps its hue.
CheckerPattern newChecker(const Material& m);
/// An image texture of `absolutePath` (kept as the user picked it and as the resolved path;
/// the scene writer makes it relative to the scene's folder) with the schema's default repeat
/// and offset.
ImageTexture newImageTexture(const std::string& absolutePath);

/// Puts `m` in `mode`: Colour drops the pattern (the flat colour, kept all along, shows
/// again); Checker makes newChecker(m) unless it already is one; Image needs `imagePath`
/// (absolute) and keeps the repeat and offset of a texture it already has. False when
/// nothing changed or Image has no path.
bool setColorMode(Material& m, ColorMode mode, const std::string& imagePath = {});

/// True when `path`'s extension is one of the image files a texture may be (case ignored):
/// .png .jpg .jpeg .tif .tiff .exr .hdr .tga .bmp.
bool isTextureFileName(const std::string& path);

/// What giving an object a dropped image did.
struct TextureDrop {
    std::string material;  ///< The material that now has the texture.
    bool created = false;  ///< A new material was made for the object (it had none or shared).
    bool changed = false;  ///< False when its material had that texture already.
    std::string error;     ///< Why nothing changed; empty on success.
};

/// Gives object `id`'s material the image texture `absolutePath`. When the object has no
/// material, or shares it with other objects, a new material named after the image (with the
/// old one's coefficients) is made and assigned, so no other object changes.
TextureDrop giveObjectTexture(SceneDocument& doc, ObjectId id, const std::string& absolutePath);

}  // namespace rs::ui
