// The looks of an asset as text: the materials as a scene file (read back by the scene
// reader, which bounds every field), the rest beside it.
#include "io/asset_content.h"

#include <algorithm>
#include <cmath>

#include "io/scene_io.h"
#include "io/scene_json.h"

namespace rs {

namespace {
/// True when `j` is an array of `n` finite numbers.
bool isNumbers(const Json& j, std::size_t n) {
    return j.is_array() && j.size() == n && std::all_of(j.begin(), j.end(), [](const Json& v) {
               return v.is_number() && std::isfinite(v.get<double>());
           });
}

/// A texture whose image is still inside the asset: nothing the scene writer can name.
Material withoutEmbeddedImage(const AssetLook& look) {
    Material m = look.material;
    if (look.embeddedImage >= 0) m.pattern = std::monostate{};
    return m;
}
}  // namespace

const AssetLook* AssetContent::look(uint32_t index) const {
    for (const AssetLook& l : looks)
        if (l.index == index) return &l;
    return nullptr;
}

std::string encodeAssetLooks(const AssetContent& content, const std::string& assetDir) {
    SceneDocument doc;
    Json looks = Json::array();
    for (const AssetLook& look : content.looks) {
        doc.materials.push_back(withoutEmbeddedImage(look));
        Json j;
        j["index"] = look.index;
        j["embedded_image"] = look.embeddedImage;
        if (const auto* t = std::get_if<ImageTexture>(&look.material.pattern);
            t && look.embeddedImage >= 0)
            j["transform"] = {jsonNumberForFloat(t->scaleU), jsonNumberForFloat(t->scaleV),
                              jsonNumberForFloat(t->offsetU), jsonNumberForFloat(t->offsetV)};
        // A pattern is written in place of the flat colour, which the part falls back to.
        if (look.material.pattern.index() != 0)
            j["flat_color"] = {jsonNumberForFloat(look.material.color.x),
                               jsonNumberForFloat(look.material.color.y),
                               jsonNumberForFloat(look.material.color.z)};
        j["notes"] = look.notes;
        looks.push_back(std::move(j));
    }
    Json images = Json::array();
    for (const AssetImage& image : content.images)
        images.push_back({{"name", image.name}, {"format", image.formatHint}});
    doc.lights = content.lights;
    Json views = Json::array();
    for (const AssetView& view : content.views) {
        SceneDocument one;
        one.camera = view.camera;
        views.push_back({{"name", view.name}, {"scene", serializeScene(one, assetDir)}});
    }
    Json out;
    out["scene"] = serializeScene(doc, assetDir);
    out["views"] = std::move(views);
    out["light_notes"] = content.lightNotes;
    out["looks"] = std::move(looks);
    out["images"] = std::move(images);
    return dumpJson(out);
}

namespace {
/// The asset's cameras, each a scene of its own (names may repeat or be empty, which a scene's
/// `views` would refuse).
bool decodeViews(const Json& in, const std::string& assetDir, std::vector<AssetView>& views,
                 std::string& why) {
    views.clear();
    for (const Json& view : in.value("views", Json::array())) {
        if (!view.is_object() || !view.contains("name") || !view["name"].is_string() ||
            !view.contains("scene") || !view["scene"].is_string()) {
            why = "an asset camera that is not the expected text";
            return false;
        }
        SceneLoadResult camera = parseScene(view["scene"].get<std::string>(), assetDir, "asset");
        if (!camera.ok()) {
            why = "an asset camera that does not read back: " + camera.errorText();
            return false;
        }
        views.push_back({view["name"].get<std::string>(), camera.document.camera});
    }
    return true;
}

/// Look `i` of the wire (`j`) around its material, read back by the scene reader; `images`
/// embedded images came along.
bool decodeLook(const Json& j, std::size_t i, std::size_t images, AssetLook& look,
                std::string& why) {
    const bool ok = j.is_object() && j.contains("index") && j["index"].is_number_unsigned() &&
                    j["index"].get<std::uint64_t>() <= UINT32_MAX && j.contains("embedded_image") &&
                    j["embedded_image"].is_number_integer() && j.contains("notes") &&
                    j["notes"].is_array();
    if (!ok) {
        why = "asset look " + std::to_string(i) + " is not the expected text";
        return false;
    }
    look.index = j["index"].get<uint32_t>();
    const auto image = j["embedded_image"].get<std::int64_t>();
    if (image < -1 || image >= std::int64_t(images)) {
        why = "asset look " + std::to_string(i) + " names an image that is not there";
        return false;
    }
    look.embeddedImage = int(image);
    for (const Json& note : j["notes"])
        if (note.is_string()) look.notes.push_back(note.get<std::string>());
    if (const Json& c = j.value("flat_color", Json()); isNumbers(c, 3)) {
        const Color flat(floatFromJson(c[0].get<double>()), floatFromJson(c[1].get<double>()),
                         floatFromJson(c[2].get<double>()));
        if (glm::all(glm::greaterThanEqual(flat, Color(0.0f)))) look.material.color = flat;
    }
    if (look.embeddedImage >= 0) {
        ImageTexture t;
        if (const Json& f = j.value("transform", Json()); isNumbers(f, 4)) {
            t.scaleU = floatFromJson(f[0].get<double>());
            t.scaleV = floatFromJson(f[1].get<double>());
            t.offsetU = floatFromJson(f[2].get<double>());
            t.offsetV = floatFromJson(f[3].get<double>());
        }
        look.material.pattern = t;
    }
    return true;
}

/// A texture file that cannot be read leaves its part untextured, said in its notes.
void untextureUnreadable(const std::vector<SceneError>& warnings, std::vector<AssetLook>& looks) {
    for (const SceneError& w : warnings)
        for (std::size_t i = 0; i < looks.size(); ++i)
            if (w.pointer.rfind("/materials/" + std::to_string(i) + "/", 0) == 0) {
                std::string why = w.message;
                why = why.substr(0, why.find("; the texture shows as"));
                looks[i].notes.push_back(why + "; left untextured");
                looks[i].material.pattern = std::monostate{};
            }
}

/// The embedded images' names and format hints (their bytes came apart from the text).
void decodeImageNames(const Json& in, std::vector<AssetImage>& images) {
    for (std::size_t i = 0; i < images.size(); ++i) {
        const Json& j = in["images"][i];
        if (!j.is_object()) continue;
        if (j.contains("name") && j["name"].is_string())
            images[i].name = j["name"].get<std::string>();
        if (j.contains("format") && j["format"].is_string())
            images[i].formatHint = j["format"].get<std::string>();
    }
}
}  // namespace

bool decodeAssetLooks(const std::string& text, const std::string& assetDir, AssetContent& content,
                      std::string& why) {
    const Json in = Json::parse(text, nullptr, false);
    if (in.is_discarded() || !in.is_object() || !in.contains("scene") || !in["scene"].is_string() ||
        !in.contains("looks") || !in["looks"].is_array() || !in.contains("images") ||
        !in["images"].is_array() || in["images"].size() != content.images.size()) {
        why = "asset looks that are not the expected text";
        return false;
    }
    SceneLoadResult scene = parseScene(in["scene"].get<std::string>(), assetDir, "asset");
    if (!scene.ok()) {
        why = "asset materials that do not read back: " + scene.errorText();
        return false;
    }
    const Json& looks = in["looks"];
    if (looks.size() != scene.document.materials.size()) {
        why = "asset looks that do not match their materials";
        return false;
    }
    content.looks.clear();
    content.lights = std::move(scene.document.lights);
    if (!decodeViews(in, assetDir, content.views, why)) return false;
    content.lightNotes.clear();
    for (const Json& note : in.value("light_notes", Json::array()))
        if (note.is_string()) content.lightNotes.push_back(note.get<std::string>());
    for (std::size_t i = 0; i < looks.size(); ++i) {
        AssetLook look;
        look.material = std::move(scene.document.materials[i]);
        if (!decodeLook(looks[i], i, content.images.size(), look, why)) return false;
        if (!content.looks.empty() && content.looks.back().index >= look.index) {
            why = "asset looks out of order";
            return false;
        }
        content.looks.push_back(std::move(look));
    }
    untextureUnreadable(scene.warnings, content.looks);
    decodeImageNames(in, content.images);
    return true;
}

}  // namespace rs
