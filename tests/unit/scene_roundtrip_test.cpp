// Save/load round trips: the format's example and a few hundred random valid documents.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "io/scene_io.h"

namespace rs {
namespace {

const std::string kData = RAYSTUDIO_TEST_DATA;

// Random valid documents. Values span many magnitudes so float -> text -> float is tested
// on awkward numbers, not just on short decimals.
class RandomScene {
public:
    explicit RandomScene(uint32_t seed) : rng_(seed) {}

    SceneDocument make() {
        SceneDocument doc;
        doc.camera = camera();
        doc.render = render();
        doc.extras = extras();
        int materials = pick(0, 4);
        for (int i = 0; i < materials; ++i) doc.materials.push_back(material(i));
        for (int i = pick(0, 3); i > 0; --i) doc.addLight(light(i));
        for (int i = pick(0, 8); i > 0; --i) doc.addObject(object(i, doc));
        return doc;
    }

private:
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    bool coin() { return pick(0, 1) == 1; }
    float unit() { return std::uniform_real_distribution<float>(0.0f, 1.0f)(rng_); }
    float any() {
        switch (pick(0, 3)) {
            case 0:
                return static_cast<float>(pick(-10, 10));
            case 1:
                return std::uniform_real_distribution<float>(-100.0f, 100.0f)(rng_);
            case 2:
                return std::ldexp(unit() - 0.5f, pick(-100, 100));
            default:
                return std::round(unit() * 1000.0f) / 100.0f;  // 0.01 steps, as typed
        }
    }
    float positive() {
        float v = std::abs(any());
        return v > 0.0f ? v : 0.5f;
    }
    Vec3 vec() { return Vec3(any(), any(), any()); }
    Vec3 nonZeroVec() {
        Vec3 v = vec();
        return v == Vec3(0.0f) ? Vec3(1, 0, 0) : v;
    }
    // Unit vector computed in double: float squares of 1e30 components overflow.
    static Vec3 direction(const Vec3& v) {
        glm::dvec3 d(v.x, v.y, v.z);
        d /= glm::length(d);
        return Vec3(static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z));
    }
    Color color() { return Color(unit() * 2, unit(), coin() ? 0.0f : unit()); }

    Extras extras() {
        Extras e;
        static const char* const samples[] = {
            R"({"zoom":2.5,"tags":["a","ü"]})", "null", "[1,-2,3.25]",
            "\"text with \\\" quote\"",         "true", "1e-07"};
        for (int i = pick(0, 2); i > 0; --i) {
            nlohmann::ordered_json v = nlohmann::ordered_json::parse(samples[pick(0, 5)]);
            e.emplace_back("x-key" + std::to_string(i), v.dump());
        }
        return e;
    }

    Camera camera() {
        Camera c;
        c.projection = coin() ? Projection::Perspective : Projection::Orthographic;
        c.position = vec();
        c.target = c.position + Vec3(1.0f + unit(), unit(), -1.0f - unit());
        c.up = Vec3(unit() * 0.1f, 1.0f, unit() * 0.1f);
        c.fovY = 1.0f + unit() * 178.0f;
        c.orthoHeight = positive();
        c.extras = extras();
        return c;
    }

    RenderSettings render() {
        RenderSettings r;
        r.width = pick(1, 16384);
        r.height = pick(1, 4096);
        r.maxDepth = pick(0, 12);
        if (coin()) r.minWeight = coin() ? 0.0f : unit();
        r.shadowSamples = pick(0, 64);
        r.supersampling = pick(1, 16);
        r.adaptiveSupersampling = coin();
        r.tonemap = static_cast<ToneMap>(pick(0, 3));
        r.exposure = any();
        r.background = color();
        r.ambient = color();
        r.extras = extras();
        return r;
    }

    Material material(int i) {
        Material m;
        m.name = i == 1 ? "a/b~c \"quoted\" ü" : "material " + std::to_string(i);
        m.color = color();
        m.diffuse = unit();
        m.specular = unit();
        m.shininess = positive();
        m.reflectivity = unit();
        m.transparency = unit() * (1.0f - m.reflectivity);
        m.ior = positive();
        m.extras = extras();
        return m;
    }

    Light light(int i) {
        Light l;
        l.name = "light " + std::to_string(i);
        l.type = coin() ? LightType::Point : LightType::Sphere;
        l.position = vec();
        // A point light has no radius in the file; the model's default stands in for it.
        if (l.type == LightType::Sphere) l.radius = positive();
        l.color = color();
        l.intensity = positive();
        l.extras = extras();
        return l;
    }

    Object object(int i, const SceneDocument& doc) {
        static const char* const meshes[] = {"meshes/cube.obj", "meshes/tetra.ply",
                                             "meshes/quad_translated.gltf"};
        Object o;
        o.name = "object " + std::to_string(i);
        int m = pick(-1, static_cast<int>(doc.materials.size()) - 1);
        if (m >= 0) o.material = doc.materials[static_cast<std::size_t>(m)].name;
        o.visible = coin();
        switch (pick(0, 4)) {
            case 0:
                o.geometry = SphereGeometry{vec(), positive()};
                break;
            case 1:
                o.geometry = PlaneGeometry{vec(), direction(nonZeroVec())};
                break;
            case 2: {
                Vec3 u = nonZeroVec();
                Vec3 v =
                    direction(glm::cross(direction(u), direction(Vec3(u.y, u.z + 1.0f, -u.x))));
                if (!std::isfinite(v.x) || v == Vec3(0.0f)) v = direction(Vec3(u.y, -u.x, 0.0f));
                o.geometry = RectangleGeometry{vec(), u, v * positive()};
                break;
            }
            case 3: {
                // The extent must survive float addition even for corners near 1e15.
                Vec3 lo = vec();
                Vec3 extent =
                    glm::max(Vec3(positive(), positive(), positive()), glm::abs(lo) * 1e-3f + 1.0f);
                o.geometry = BoxGeometry{lo, lo + extent};
                break;
            }
            default: {
                MeshGeometry g;
                g.file = meshes[pick(0, 2)];
                g.resolvedPath = kData + "/" + g.file;
                g.smoothNormals = coin();
                o.geometry = g;
            }
        }
        if (!std::holds_alternative<PlaneGeometry>(o.geometry) && coin()) {
            if (coin()) o.transform.translate = vec();
            if (coin()) o.transform.rotate = vec();
            o.transform.scaleWrittenAsNumber = coin();
            o.transform.scale = o.transform.scaleWrittenAsNumber
                                    ? Vec3(positive())
                                    : Vec3(positive(), -positive(), positive());
        }
        o.extras = extras();
        return o;
    }

    std::mt19937 rng_;
};

TEST(SceneRoundTrip, FormatExample_SavesAndLoadsToTheSameDocument) {
    SceneLoadResult first = loadScene(kData + "/scenes/example.scene.json");
    ASSERT_TRUE(first.ok()) << first.errorText();
    ASSERT_EQ(first.document.objects.size(), 3u);
    std::string text = serializeScene(first.document, kData + "/scenes");
    SceneLoadResult second = parseScene(text, kData + "/scenes");
    ASSERT_TRUE(second.ok()) << second.errorText() << text;
    EXPECT_TRUE(second.document.sameContent(first.document)) << text;
    EXPECT_EQ(serializeScene(second.document, kData + "/scenes"), text);
}

TEST(SceneRoundTrip, RandomDocuments_SaveAndLoadToTheSameDocument) {
    RandomScene random(20240611);
    for (int n = 0; n < 300; ++n) {
        SceneDocument doc = random.make();
        std::string text = serializeScene(doc, kData);
        SceneLoadResult back = parseScene(text, kData);
        ASSERT_TRUE(back.ok()) << "document " << n << ":\n" << back.errorText() << text;
        ASSERT_TRUE(back.document.sameContent(doc)) << "document " << n << ":\n" << text;
        // Same text again: writing is deterministic and loses nothing on a second pass.
        ASSERT_EQ(serializeScene(back.document, kData), text) << "document " << n;
    }
}

TEST(SceneRoundTrip, MeshPathSpellings_SaveAndLoadToTheSameDocument) {
    // Found by the scene reader's fuzzer: "meshes//cube.obj" saved as "meshes/cube.obj" and
    // the reloaded document compared unequal, though it is the same mesh file.
    const std::string spellings[] = {"meshes/cube.obj",           "meshes//cube.obj",
                                     "./meshes/cube.obj",         "meshes/./cube.obj",
                                     "meshes/../meshes/cube.obj", kData + "/meshes/cube.obj"};
    for (const std::string& file : spellings) {
        const std::string text = R"({ "format": "raystudio-scene", "version": 1,
            "objects": [ { "name": "m", "type": "mesh", "file": ")" +
                                 file + R"(" } ] })";
        SceneLoadResult first = parseScene(text, kData);
        ASSERT_TRUE(first.ok()) << file << ": " << first.errorText();
        const std::string saved = serializeScene(first.document, kData);
        EXPECT_EQ(nlohmann::json::parse(saved)["objects"][0]["file"], "meshes/cube.obj") << file;
        SceneLoadResult second = parseScene(saved, kData);
        ASSERT_TRUE(second.ok()) << file << ": " << second.errorText();
        EXPECT_TRUE(second.document.sameContent(first.document)) << file;
        EXPECT_EQ(serializeScene(second.document, kData), saved) << file;
    }
    // A different file, or the same file with other normals, is a different mesh.
    SceneLoadResult cube = parseScene(R"({ "format": "raystudio-scene", "version": 1,
        "objects": [ { "name": "m", "type": "mesh", "file": "meshes/cube.obj" } ] })",
                                      kData);
    SceneLoadResult tetra = parseScene(R"({ "format": "raystudio-scene", "version": 1,
        "objects": [ { "name": "m", "type": "mesh", "file": "meshes/tetra.ply" } ] })",
                                       kData);
    ASSERT_TRUE(cube.ok() && tetra.ok()) << cube.errorText() << tetra.errorText();
    EXPECT_FALSE(cube.document.sameContent(tetra.document));
    SceneDocument flat = cube.document;
    std::get<MeshGeometry>(flat.objects[0].geometry).smoothNormals = false;
    EXPECT_FALSE(flat.sameContent(cube.document));
}

TEST(SceneRoundTrip, SameContent_NoticesAChangedFloat) {
    // Guards the round-trip test against a comparison that could never fail.
    SceneLoadResult a = loadScene(kData + "/scenes/example.scene.json");
    ASSERT_TRUE(a.ok());
    SceneDocument b = a.document;
    std::get<SphereGeometry>(b.objects[1].geometry).radius = std::nextafter(1.0f, 2.0f);
    EXPECT_FALSE(b.sameContent(a.document));
    SceneLoadResult back = parseScene(serializeScene(b, ""), "");
    ASSERT_TRUE(back.ok()) << back.errorText();
    EXPECT_EQ(std::get<SphereGeometry>(back.document.objects[1].geometry).radius,
              std::nextafter(1.0f, 2.0f));
}

}  // namespace
}  // namespace rs
