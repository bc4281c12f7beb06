// Colour-form edits: defaults from the parameter descriptors, the mode switch, dropped images.
#include "document/color_pattern_edits.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "document/scene_edits.h"
#include "scene/parameters.h"

namespace rs::ui {

namespace {

/// `target` with every field of `kind` at its descriptor's default.
template <class T>
T withDefaults(ParamKind kind) {
    T target;
    for (const ParamDescriptor& d : parameters(kind))
        if (d.type != ParamType::File) setParameter(target, d.key, d.defaultValue);
    return target;
}

}  // namespace

ColorMode colorModeOf(const Material& m) {
    if (std::holds_alternative<CheckerPattern>(m.pattern)) return ColorMode::Checker;
    if (std::holds_alternative<ImageTexture>(m.pattern)) return ColorMode::Image;
    return ColorMode::Colour;
}

CheckerPattern newChecker(const Material& m) {
    CheckerPattern c = withDefaults<CheckerPattern>(ParamKind::Checker);
    c.even = m.color;
    return c;
}

ImageTexture newImageTexture(const std::string& absolutePath) {
    ImageTexture t = withDefaults<ImageTexture>(ParamKind::ImageTexture);
    t.image = ImageFile{absolutePath, absolutePath};
    return t;
}

bool setColorMode(Material& m, ColorMode mode, const std::string& imagePath) {
    switch (mode) {
        case ColorMode::Colour:
            if (std::holds_alternative<std::monostate>(m.pattern)) return false;
            m.pattern = std::monostate{};
            return true;
        case ColorMode::Checker:
            if (std::holds_alternative<CheckerPattern>(m.pattern)) return false;
            m.pattern = newChecker(m);
            return true;
        case ColorMode::Image: {
            if (imagePath.empty()) return false;
            ImageTexture t = newImageTexture(imagePath);
            if (const auto* old = std::get_if<ImageTexture>(&m.pattern)) {
                if (old->image.source() == imagePath) return false;
                ImageFile image = t.image;
                t = *old;
                t.image = image;
            }
            m.pattern = std::move(t);
            return true;
        }
    }
    return false;
}

bool isTextureFileName(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    static const char* const kExtensions[] = {".png", ".jpg", ".jpeg", ".tif", ".tiff",
                                              ".exr", ".hdr", ".tga",  ".bmp"};
    return std::any_of(std::begin(kExtensions), std::end(kExtensions),
                       [&](const char* e) { return ext == e; });
}

TextureDrop giveObjectTexture(SceneDocument& doc, ObjectId id, const std::string& absolutePath) {
    TextureDrop result;
    Object* o = doc.findObject(id);
    if (!o) {
        result.error = "only objects have a material (lights and the camera have none)";
        return result;
    }
    Material* m = findMaterial(doc, o->material);
    if (!m || materialUsers(doc, o->material) > 1) {
        // Its own material, so that the objects sharing the old one keep their look.
        Material copy;
        if (m) copy = *m;
        copy.name = uniqueName(doc, std::filesystem::path(absolutePath).stem().string());
        if (copy.name.empty()) copy.name = uniqueName(doc, "texture");
        o->material = copy.name;
        doc.materials.push_back(std::move(copy));
        m = &doc.materials.back();
        result.created = true;
    }
    result.changed = setColorMode(*m, ColorMode::Image, absolutePath) || result.created;
    result.material = m->name;
    return result;
}

}  // namespace rs::ui
