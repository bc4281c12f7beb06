// Reading the materials and lights of a scene file, and the uniqueness of names in a list.
#include "io/scene_reader_sections.h"
#include "scene/field_rules.h"

namespace rs {

namespace {
void readMaterial(EntryReader& r, Material& m) {
    r.name(m.name);
    // `color` is [r, g, b] or, from version 2, an object: a checker or an image texture.
    const Json* color = r.get("color");
    const bool patterned = color && color->is_object();
    if (patterned) readColorPattern(r.sink(), *color, r.pointerTo("color"), m.pattern);
    const auto invalid = patterned ? readFields(r, ParamKind::Material, m, {"color"})
                                   : readFields(r, ParamKind::Material, m);
    if (noneInvalid(invalid, {"reflectivity", "transparency"})) {
        if (auto e = materialWeightsError(m)) {
            // Placed where the file raises the sum: transparency when it gives one.
            const char* key = r.has("transparency") ? "transparency" : "reflectivity";
            r.sink().atValue(r.pointerTo(key), e.message);
        }
    }
}

void readLight(EntryReader& r, Light& light) {
    r.name(light.name);
    // The type decides which fields the light has; read it first.
    ParamValue type;
    const auto read = r.parameter(*findParameter(ParamKind::PointLight, "type"), type);
    if (read == EntryReader::Read::Ok) setField(light, "type", type);
    const auto invalid = readFields(r, lightKind(light), light, {"type"});
    if (read != EntryReader::Read::Ok) {
        // The type error says it all; no "unknown key" noise as well.
        for (const char* key : {"radius", "direction", "target", "falloff", "position"}) r.get(key);
        return;
    }
    switch (light.type) {
        case LightType::Point:
            r.forbid("radius", "a point light has no radius (a sphere light has)");
            break;
        case LightType::Directional:
            r.forbid("position",
                     "a directional light has no position (it shines from infinitely "
                     "far along \"direction\")");
            break;
        case LightType::Spot:
            if (noneInvalid(invalid, {"position", "target"}))
                if (auto e = spotConeError(light)) r.sink().atValue(r.pointerTo(e.key), e.message);
            break;
        case LightType::Sphere:
            break;
    }
}
}  // namespace

void UniqueNames::add(SceneErrorSink& sink, const std::string& name,
                      const std::string& entryPointer) {
    const auto [it, inserted] = seen_.try_emplace(name, entryPointer);
    if (!inserted)
        sink.atValue(appendPointer(entryPointer, "name"), std::string("duplicate ") + kind_ +
                                                              " name \"" + name + "\" (also at " +
                                                              it->second + ")");
}

void readMaterials(SceneErrorSink& sink, const Json& json, SceneDocument& doc) {
    if (!expectArray(sink, json, "/materials")) return;
    UniqueNames names("material");
    for (std::size_t i = 0; i < json.size(); ++i) {
        const std::string at = appendPointer("/materials", i);
        if (!expectObject(sink, json[i], at)) continue;
        EntryReader r(sink, json[i], at);
        Material m;
        readMaterial(r, m);
        m.extras = r.finish();
        if (!m.name.empty()) names.add(sink, m.name, at);
        // Kept even when broken: objects that name it must not get a second, false error.
        doc.materials.push_back(std::move(m));
    }
}

void readLights(SceneErrorSink& sink, const Json& json, SceneDocument& doc) {
    if (!expectArray(sink, json, "/lights")) return;
    UniqueNames names("light");
    for (std::size_t i = 0; i < json.size(); ++i) {
        const std::string at = appendPointer("/lights", i);
        if (!expectObject(sink, json[i], at)) continue;
        EntryReader r(sink, json[i], at);
        Light light;
        readLight(r, light);
        light.extras = r.finish();
        if (!light.name.empty()) names.add(sink, light.name, at);
        doc.addLight(std::move(light));
    }
}

}  // namespace rs
