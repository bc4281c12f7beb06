// Reading what a scene looks like beyond flat colours (format version 2): a material colour's
// checker and texture forms, the environment, and the image files they name.
#include <filesystem>

#include "io/scene_reader_sections.h"
#include "scene/field_rules.h"
#include "texture/texture_store.h"

namespace rs {

namespace {
/// Reads element `index` of the array `key` as the descriptor `field` of `kind` says.
template <class T>
void readElement(EntryReader& r, ParamKind kind, const char* field, const char* key,
                 std::size_t index, std::size_t count, const char* shape, T& target) {
    ParamValue value;
    if (r.element(*findParameter(kind, field), key, index, count, shape, value) ==
        EntryReader::Read::Ok)
        setField(target, field, value);
}

/// x- keys are kept at the levels the format lists, not inside a colour: refused here so
/// that nothing the file holds is silently dropped on save.
void refuseExtras(EntryReader& r) {
    for (const auto& extra : r.finish())
        r.sink().atKey(
            r.pointerTo(extra.first),
            "\"" + extra.first + "\" cannot be kept inside a colour; put it on the material");
}

CheckerPattern readChecker(EntryReader& r) {
    CheckerPattern c;
    const char* shape = "2 colours [[r, g, b], [r, g, b]]";
    readElement(r, ParamKind::Checker, "even", "checker", 0, 2, shape, c);
    readElement(r, ParamKind::Checker, "odd", "checker", 1, 2, shape, c);
    ParamValue scale;
    if (r.parameter(*findParameter(ParamKind::Checker, "scale"), scale) == EntryReader::Read::Ok)
        setField(c, "scale", scale);
    return c;
}

ImageTexture readTexture(EntryReader& r) {
    ImageTexture t;
    ParamValue file;
    if (r.parameter(*findParameter(ParamKind::ImageTexture, "texture"), file) ==
        EntryReader::Read::Ok) {
        if (std::get<std::string>(file).empty())
            r.sink().atValue(r.pointerTo("texture"), "texture must not be empty");
        else
            setField(t, "texture", file);
    }
    const char* shape = "2 numbers [u, v]";
    const ParamKind k = ParamKind::ImageTexture;
    readElement(r, k, "scale_u", "scale", 0, 2, shape, t);
    readElement(r, k, "scale_v", "scale", 1, 2, shape, t);
    readElement(r, k, "offset_u", "offset", 0, 2, shape, t);
    readElement(r, k, "offset_v", "offset", 1, 2, shape, t);
    if (auto e = textureScaleError(t))
        r.sink().atValue(appendPointer(r.pointerTo("scale"), e.key == "scale_u" ? 0u : 1u),
                         e.message);
    return t;
}

/// `file` resolved against the scene's folder, as mesh paths are.
std::string resolve(const std::string& file, const std::string& baseDir) {
    namespace fs = std::filesystem;
    fs::path path(file);
    if (path.is_relative() && !baseDir.empty()) path = fs::path(baseDir) / path;
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    return (ec ? path : absolute).lexically_normal().string();
}

void checkImage(SceneErrorSink& warnings, ImageFile& image, const std::string& baseDir,
                const std::string& pointer, const char* what) {
    if (image.file.empty()) return;
    image.resolvedPath = resolve(image.file, baseDir);
    // The header only: pixels are read tile by tile when rendering needs them.
    std::string why;
    if (!TextureStore::shared().open(image.resolvedPath, why))
        warnings.atValue(pointer, why + "; the " + what + " shows as the missing-image pattern");
}

}  // namespace

void readColorPattern(SceneErrorSink& sink, const Json& json, const std::string& pointer,
                      ColorPattern& out) {
    EntryReader r(sink, json, pointer);
    const bool checker = json.contains("checker"), texture = json.contains("texture");
    if (checker && texture) {
        sink.atValue(pointer, "color has both \"checker\" and \"texture\"; give one");
        r.get("checker"), r.get("texture"), r.get("scale"), r.get("offset");
        return;
    }
    if (checker)
        out = readChecker(r);
    else if (texture)
        out = readTexture(r);
    else
        sink.atValue(pointer,
                     "color must be [r, g, b], {\"checker\": [...], ...} or {\"texture\": ...}");
    if (checker || texture) refuseExtras(r);
}

void readEnvironment(SceneErrorSink& sink, const Json& json, Environment& environment) {
    if (!expectObject(sink, json, "/environment")) return;
    EntryReader r(sink, json, "/environment");
    Environment e;
    readFields(r, ParamKind::Environment, e);
    if (r.ok() && e.image.file.empty()) sink.atValue(r.pointerTo("file"), "file must not be empty");
    e.extras = r.finish();
    environment = std::move(e);
}

void checkImageFiles(SceneErrorSink& warnings, const std::string& baseDir, SceneDocument& doc) {
    for (std::size_t i = 0; i < doc.materials.size(); ++i)
        if (auto* t = std::get_if<ImageTexture>(&doc.materials[i].pattern))
            checkImage(
                warnings, t->image, baseDir,
                appendPointer(appendPointer(appendPointer("/materials", i), "color"), "texture"),
                "texture");
    checkImage(warnings, doc.environment.image, baseDir, "/environment/file", "environment");
}

std::vector<std::string> version2Uses(const SceneDocument& doc) {
    // In the order the reader reads the sections, so errors come in file order.
    std::vector<std::string> uses;
    if (doc.render.opaqueShadows) uses.push_back("/render/opaque_shadows");
    if (!doc.views.empty()) uses.push_back("/views");
    if (doc.environment.present()) uses.push_back("/environment");
    for (std::size_t i = 0; i < doc.materials.size(); ++i)
        if (doc.materials[i].pattern.index() != 0)
            uses.push_back(appendPointer(appendPointer("/materials", i), "color"));
    for (std::size_t i = 0; i < doc.lights.size(); ++i) {
        const LightType t = doc.lights[i].type;
        if (t == LightType::Directional || t == LightType::Spot)
            uses.push_back(appendPointer(appendPointer("/lights", i), "type"));
    }
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
        const auto* mesh = std::get_if<MeshGeometry>(&doc.objects[i].geometry);
        if (mesh && !mesh->partMaterials.empty())
            uses.push_back(appendPointer(appendPointer("/objects", i), "part_materials"));
    }
    return uses;
}

}  // namespace rs
