// The schema is written once (scene/parameters.cpp): this walks every descriptor of every
// kind and proves that the setters (the property panel's path), the writer and the reader
// agree on each field: what one accepts the others accept and keep bit for bit, what is
// outside the format's range all of them refuse, and a default is what an absent key reads as.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "io/scene_io.h"
#include "scene/parameters.h"

namespace rs {
namespace {

using Json = nlohmann::ordered_json;
const std::string kDir = RAYSTUDIO_SCENES_DIR;

/// A document holding one entry of `kind`, and the JSON pointer of that entry.
struct Host {
    SceneDocument doc;
    std::string pointer;
};

/// Where a field of `kind` stands in its entry, as a JSON pointer suffix: the key itself, or
/// an element of the array the format writes two fields as (scenes/FORMAT.md, "color").
std::string fileKey(ParamKind kind, const std::string& key) {
    static const std::map<std::string, std::string> pairs{
        {"even", "checker/0"},  {"odd", "checker/1"},     {"scale_u", "scale/0"},
        {"scale_v", "scale/1"}, {"offset_u", "offset/0"}, {"offset_v", "offset/1"}};
    const bool patterned = kind == ParamKind::Checker || kind == ParamKind::ImageTexture;
    const auto it = pairs.find(key);
    return patterned && it != pairs.end() ? it->second : key;
}

Host hostFor(ParamKind kind) {
    Host h;
    Object o;
    o.name = "o";
    switch (kind) {
        case ParamKind::Plane:
            o.geometry = PlaneGeometry{};
            break;
        case ParamKind::Rectangle:
            o.geometry = RectangleGeometry{};
            break;
        case ParamKind::Box:
            o.geometry = BoxGeometry{};
            break;
        case ParamKind::Mesh: {
            MeshGeometry m;
            m.file = "meshes/torus.obj";
            m.resolvedPath = kDir + "/meshes/torus.obj";
            o.geometry = m;
            break;
        }
        default:
            o.geometry = SphereGeometry{};
    }
    switch (kind) {
        case ParamKind::Material: {
            Material m;
            m.name = "m";
            h.doc.materials.push_back(m);
            h.pointer = "/materials/0";
            break;
        }
        case ParamKind::Checker:
        case ParamKind::ImageTexture: {
            Material m;
            m.name = "m";
            if (kind == ParamKind::Checker) {
                m.pattern = CheckerPattern{};
            } else {
                ImageTexture t;
                t.image = {"textures/tiles.png", kDir + "/textures/tiles.png"};
                m.pattern = t;
            }
            h.doc.materials.push_back(m);
            h.pointer = "/materials/0/color";
            break;
        }
        case ParamKind::Environment:
            h.doc.environment.image = {"textures/sky.hdr", kDir + "/textures/sky.hdr"};
            h.pointer = "/environment";
            break;
        case ParamKind::PointLight:
        case ParamKind::SphereLight:
        case ParamKind::DirectionalLight:
        case ParamKind::SpotLight: {
            Light l;
            l.name = "l";
            l.type = kind == ParamKind::SphereLight        ? LightType::Sphere
                     : kind == ParamKind::DirectionalLight ? LightType::Directional
                     : kind == ParamKind::SpotLight        ? LightType::Spot
                                                           : LightType::Point;
            l.position = Vec3(0.0f, 4.0f, 0.0f);  // a spot light must aim somewhere
            h.doc.addLight(l);
            h.pointer = "/lights/0";
            break;
        }
        case ParamKind::Camera:
            h.pointer = "/camera";
            break;
        case ParamKind::Render:
            h.pointer = "/render";
            break;
        default:
            h.doc.addObject(o);
            h.pointer = "/objects/0";
    }
    return h;
}

/// Calls `f` on the member of `doc` that `kind` describes (each has get/setParameter).
template <class F>
auto onTarget(SceneDocument& doc, ParamKind kind, F f) {
    switch (kind) {
        case ParamKind::Transform:
            return f(doc.objects.at(0).transform);
        case ParamKind::Material:
            return f(doc.materials.at(0));
        case ParamKind::PointLight:
        case ParamKind::SphereLight:
        case ParamKind::DirectionalLight:
        case ParamKind::SpotLight:
            return f(doc.lights.at(0));
        case ParamKind::Checker:
            return f(std::get<CheckerPattern>(doc.materials.at(0).pattern));
        case ParamKind::ImageTexture:
            return f(std::get<ImageTexture>(doc.materials.at(0).pattern));
        case ParamKind::Environment:
            return f(doc.environment);
        case ParamKind::Camera:
            return f(doc.camera);
        case ParamKind::Render:
            return f(doc.render);
        default:
            return f(doc.objects.at(0).geometry);
    }
}

std::optional<ParamValue> get(SceneDocument& doc, ParamKind kind, const std::string& key) {
    return onTarget(doc, kind, [&](auto& t) { return getParameter(t, key); });
}
std::string set(SceneDocument& doc, ParamKind kind, const std::string& key, const ParamValue& v) {
    return onTarget(doc, kind, [&](auto& t) { return setParameter(t, key, v); });
}

bool finite(double v) {
    return std::isfinite(v);
}

/// Legal values a file may hold, beyond what an editor offers wherever the format allows it.
std::vector<ParamValue> legalSamples(const ParamDescriptor& d) {
    const NumberRange& r = d.range;
    std::vector<ParamValue> out;
    switch (d.type) {
        case ParamType::Float: {
            // The top: beyond the soft range when the format allows it, else its closed end.
            if (!finite(r.max))
                out.push_back(float(d.softMax * 3.0));
            else if (r.maxOpen)
                out.push_back(std::nextafter(float(r.max), 0.0f));
            else
                out.push_back(float(r.max));
            // The bottom, likewise.
            if (!finite(r.min))
                out.push_back(float(-3.0 * std::max(1.0, std::abs(d.softMin))));
            else if (r.minOpen)
                out.push_back(std::nextafter(float(r.min), 1e30f));
            else
                out.push_back(float(r.min));
            break;
        }
        case ParamType::Int:
            out.push_back(int(r.min));
            out.push_back(int(r.max));
            break;
        case ParamType::Bool:
            out.push_back(true);
            out.push_back(false);
            break;
        case ParamType::Enum:
            for (int i = 0; i < int(d.enumNames.size()); ++i) out.push_back(i);
            break;
        case ParamType::Vec3:
        case ParamType::Color: {
            if (d.vectorRule == VectorRule::NonNegative) {
                out.push_back(Vec3(0.0f, float(d.softMax * 1.5), 0.25f));
                break;
            }
            if (d.vectorRule == VectorRule::NonZeroComponents) {
                out.push_back(Vec3(-2.0f, float(d.softMax * 3.0), 0.5f));
                break;
            }
            // Beyond the soft range, scaling the default keeps the relations between fields
            // (orthogonal edges, box corners, a camera that can look).
            const Vec3 def = std::get<Vec3>(d.defaultValue);
            const float k = float(std::max(std::abs(d.softMin), d.softMax) * 3.0);
            out.push_back(def == Vec3(0.0f) ? Vec3(k, -k, 1.5f) : def * k);
            break;
        }
        case ParamType::Text:
        case ParamType::File:
            break;  // mesh files: covered by the mesh-path tests
    }
    return out;
}

/// Values outside the format: every setter and the reader must refuse them.
std::vector<Json> illegalSamples(const ParamDescriptor& d, std::vector<ParamValue>& values) {
    const NumberRange& r = d.range;
    std::vector<Json> out;
    auto add = [&](const ParamValue& v, Json j) {
        values.push_back(v);
        out.push_back(std::move(j));
    };
    switch (d.type) {
        case ParamType::Float: {
            if (finite(r.max)) {
                const float v = r.maxOpen ? float(r.max) : std::nextafter(float(r.max), 1e30f);
                add(v, Json(double(v)));
            }
            if (finite(r.min)) {
                const float v = r.minOpen ? float(r.min) : std::nextafter(float(r.min), -1e30f);
                add(v, Json(double(v)));
            }
            break;
        }
        case ParamType::Int:
            add(int(r.min) - 1, Json(int(r.min) - 1));
            add(int(r.max) + 1, Json(int(r.max) + 1));
            break;
        case ParamType::Enum:
            add(int(d.enumNames.size()), Json("no-such-" + d.key));
            break;
        case ParamType::Vec3:
        case ParamType::Color: {
            Vec3 bad(0.0f);
            if (d.vectorRule == VectorRule::NonNegative)
                bad = Vec3(0.5f, -0.25f, 0.5f);
            else if (d.vectorRule == VectorRule::NonZeroComponents)
                bad = Vec3(1.0f, 0.0f, 1.0f);
            else if (d.vectorRule != VectorRule::NonZero)
                break;  // Any: every finite vector
            add(bad, Json::array({bad.x, bad.y, bad.z}));
            break;
        }
        default:
            break;
    }
    return out;
}

SceneLoadResult reread(const SceneDocument& doc) {
    return parseScene(serializeScene(doc, kDir), kDir, "schema.scene.json");
}

Json entryJson(const Json& file, const std::string& pointer) {
    return file.at(Json::json_pointer(pointer));
}

std::string what(ParamKind kind, const ParamDescriptor& d) {
    return std::string(kindLabel(kind)) + "." + d.key;
}

TEST(Schema, EveryKindHasFieldsWithDistinctKeysAndSaneRanges) {
    for (ParamKind kind : kAllParamKinds) {
        std::set<std::string> keys;
        ASSERT_FALSE(parameters(kind).empty()) << kindLabel(kind);
        for (const ParamDescriptor& d : parameters(kind)) {
            EXPECT_TRUE(keys.insert(d.key).second) << what(kind, d) << " twice";
            EXPECT_FALSE(d.label.empty()) << what(kind, d);
            EXPECT_LE(d.softMin, d.softMax) << what(kind, d);
            // What an editor offers lies inside what the format accepts.
            if (d.type == ParamType::Float || d.type == ParamType::Int) {
                EXPECT_TRUE(d.range.contains(d.softMin)) << what(kind, d);
                EXPECT_TRUE(d.range.contains(d.softMax)) << what(kind, d);
            }
            EXPECT_EQ(validateParameter(d, d.defaultValue), "") << what(kind, d);
            if (d.type == ParamType::Enum) {
                EXPECT_GE(d.enumNames.size(), 2u) << what(kind, d);
                EXPECT_TRUE(d.enumLabels.empty() || d.enumLabels.size() == d.enumNames.size());
            }
        }
    }
}

TEST(Schema, EveryLegalValue_IsAcceptedWrittenAndReadBackBitForBit) {
    int checked = 0;
    for (ParamKind kind : kAllParamKinds) {
        for (const ParamDescriptor& d : parameters(kind)) {
            for (const ParamValue& v : legalSamples(d)) {
                Host h = hostFor(kind);
                ASSERT_EQ(set(h.doc, kind, d.key, v), "")
                    << what(kind, d) << " refused by its setter";
                const std::optional<ParamValue> stored = get(h.doc, kind, d.key);
                ASSERT_TRUE(stored) << what(kind, d);
                if (!(kind == ParamKind::Plane && d.key == "normal")) {  // normalised on set
                    EXPECT_EQ(*stored, v) << what(kind, d);
                }
                const SceneLoadResult back = reread(h.doc);
                ASSERT_TRUE(back.ok()) << what(kind, d) << ": " << back.errorText();
                SceneDocument read = back.document;
                EXPECT_EQ(get(read, kind, d.key), stored) << what(kind, d) << " changed on the way";
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 60);
}

TEST(Schema, EveryValueOutsideTheFormat_IsRefusedBySetterAndReader) {
    int checked = 0;
    for (ParamKind kind : kAllParamKinds) {
        for (const ParamDescriptor& d : parameters(kind)) {
            std::vector<ParamValue> values;
            const std::vector<Json> texts = illegalSamples(d, values);
            for (std::size_t i = 0; i < texts.size(); ++i) {
                Host h = hostFor(kind);
                EXPECT_NE(set(h.doc, kind, d.key, values[i]), "")
                    << what(kind, d) << " accepted by its setter: " << texts[i].dump();
                Json file = Json::parse(serializeScene(h.doc, kDir));
                const std::string at = h.pointer + "/" + fileKey(kind, d.key);
                file[Json::json_pointer(at)] = texts[i];
                const SceneLoadResult r = parseScene(file.dump(2), kDir, "bad.scene.json");
                bool placed = false;
                for (const SceneError& e : r.errors) placed |= e.pointer.rfind(at, 0) == 0;
                EXPECT_TRUE(placed) << what(kind, d) << " = " << texts[i].dump()
                                    << " not refused at " << at << ": " << r.errorText();
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 30);
}

TEST(Schema, AnAbsentKey_ReadsAsTheDescriptorsDefault_AndDefaultsAreNotWritten) {
    for (ParamKind kind : kAllParamKinds) {
        for (const ParamDescriptor& d : parameters(kind)) {
            Host h = hostFor(kind);
            Json file = Json::parse(serializeScene(h.doc, kDir));
            Json& entry = file[Json::json_pointer(h.pointer)];
            const std::string key = fileKey(kind, d.key);
            // The checker's two colours are the form itself: without them there is no checker.
            if (kind == ParamKind::Checker && key != d.key) continue;
            // A pair (a texture's scale) is written when either half is not its default.
            const std::string whole = key.substr(0, key.find('/'));
            const bool written = entry.contains(whole);
            // The writer's one rule beyond the descriptors: the lens of the projection in use
            // (fov_y of a perspective camera) is always stated.
            const bool lens = kind == ParamKind::Camera && d.key == "fov_y";
            if (d.required || d.alwaysWritten || lens) {
                EXPECT_TRUE(written) << what(kind, d) << " must always be written";
            } else {
                // A fresh entry holds the struct's defaults: the writer leaves them out.
                EXPECT_FALSE(written) << what(kind, d) << " written at its default";
            }
            entry.erase(whole);
            const SceneLoadResult r = parseScene(file.dump(2), kDir, "absent.scene.json");
            if (d.required) {
                EXPECT_FALSE(r.ok()) << what(kind, d) << " is required but was not missed";
                continue;
            }
            ASSERT_TRUE(r.ok()) << what(kind, d) << ": " << r.errorText();
            SceneDocument read = r.document;
            EXPECT_EQ(get(read, kind, d.key), d.defaultValue) << what(kind, d);
        }
    }
}

TEST(Schema, TheWriterWritesNoFieldTheSchemaDoesNotName) {
    // Structural keys of an entry, not parameters: identity, type, references, visibility.
    const std::set<std::string> structural{"name", "type", "material", "visible"};
    for (ParamKind kind : kAllParamKinds) {
        Host h = hostFor(kind);
        for (const ParamDescriptor& d : parameters(kind))
            for (const ParamValue& v : legalSamples(d)) set(h.doc, kind, d.key, v);
        const Json entry = entryJson(Json::parse(serializeScene(h.doc, kDir)), h.pointer);
        // Setting a light's type makes it the other kind of light, with that kind's fields.
        const ParamKind now = h.doc.lights.empty() ? kind : lightKind(h.doc.lights[0]);
        for (const auto& item : entry.items()) {
            const std::string& key = item.key();
            bool pair = false;
            if (const ParamDescriptor* first = findParameter(now, key + "_u"))
                pair = fileKey(now, first->key) == key + "/0";
            if (now == ParamKind::Checker && key == "checker") pair = true;
            const bool described =
                pair || findParameter(now, key) != nullptr ||
                (h.pointer == "/objects/0" &&
                 findParameter(ParamKind::Transform, key) != nullptr) ||
                (kind == ParamKind::Transform && findParameter(ParamKind::Sphere, key) != nullptr);
            EXPECT_TRUE(described || structural.count(key))
                << kindLabel(kind) << " writes \"" << key << "\", which no descriptor names";
        }
    }
}

TEST(Schema, ToneMapNames_AreTheDescriptorsSpellings) {
    const ParamDescriptor* d = findParameter(ParamKind::Render, "tonemap");
    ASSERT_TRUE(d);
    ASSERT_EQ(d->enumNames.size(), 4u);
    EXPECT_EQ(toneMapName(ToneMap::Clamp), "clamp");
    EXPECT_EQ(toneMapName(ToneMap::Linear), "linear");
    EXPECT_EQ(toneMapName(ToneMap::Reinhard), "reinhard");
    EXPECT_EQ(toneMapName(ToneMap::Aces), "aces");
}

TEST(Schema, FormatLimitsBeyondTheEditorsRange_Load) {
    // The motivating case: a legal file with max_depth 100 must load and stay 100.
    Host h = hostFor(ParamKind::Render);
    Json file = Json::parse(serializeScene(h.doc, kDir));
    file["render"]["max_depth"] = 1000;
    file["render"]["shadow_samples"] = 4096;
    const SceneLoadResult r = parseScene(file.dump(), kDir);
    ASSERT_TRUE(r.ok()) << r.errorText();
    EXPECT_EQ(r.document.render.maxDepth, 1000);
    EXPECT_EQ(r.document.render.shadowSamples, 4096);
    const ParamDescriptor* depth = findParameter(ParamKind::Render, "max_depth");
    EXPECT_LT(depth->softMax, 1000.0);    // what an editor offers by default...
    EXPECT_EQ(depth->range.max, 1000.0);  // ...inside what the format accepts
}

}  // namespace
}  // namespace rs
