// Reading the materials and lights of a scene file, and the uniqueness of names in a list.
#include "io/scene_reader_sections.h"

namespace rs {

namespace {
// Rounding of two decimal fractions (0.3 + 0.7) must not turn a valid sum into an error.
constexpr float kSumTolerance = 1e-6f;

void readMaterial(EntryReader& r, Material& m) {
    r.name(m.name);
    r.vector("color", m.color, VectorRule::NonNegative);
    r.number("diffuse", m.diffuse, NumberRange::fraction());
    r.number("specular", m.specular, NumberRange::fraction());
    r.number("shininess", m.shininess, NumberRange::nonNegative());
    bool weights = r.number("reflectivity", m.reflectivity, NumberRange::fraction());
    weights = r.number("transparency", m.transparency, NumberRange::fraction()) && weights;
    r.number("ior", m.ior, NumberRange::positive());
    if (weights && m.reflectivity + m.transparency > 1.0f + kSumTolerance) {
        const char* key = r.has("transparency") ? "transparency" : "reflectivity";
        r.sink().atValue(r.pointerTo(key),
                         "reflectivity + transparency must be <= 1, got " +
                             describeJson(Json(jsonNumberForFloat(m.reflectivity))) + " + " +
                             describeJson(Json(jsonNumberForFloat(m.transparency))));
    }
}

void readLight(EntryReader& r, Light& light) {
    r.name(light.name);
    bool typed =
        r.enumeration("type", light.type,
                      {{"point", LightType::Point}, {"sphere", LightType::Sphere}}, Need::Required);
    // Geometry keys without a default in the format are required: position, sphere radius.
    r.vector("position", light.position, VectorRule::Any, Need::Required);
    r.vector("color", light.color, VectorRule::NonNegative);
    r.number("intensity", light.intensity, NumberRange::positive());
    if (!typed) {
        r.get("radius");  // the type error says it all; no "unknown key" noise as well
    } else if (light.type == LightType::Sphere) {
        r.number("radius", light.radius, NumberRange::positive(), Need::Required);
    } else {
        r.forbid("radius", "a point light has no radius (a sphere light has)");
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
