// Format version 2 (scenes/FORMAT.md): which version the writer states, the colour forms, the
// environment and the new lights round-trip, and an image that cannot be read is a warning
// that leaves the scene loadable and its path as written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/scene_io.h"

namespace rs {
namespace {

using Json = nlohmann::ordered_json;
const std::string kDir = RAYSTUDIO_SCENES_DIR;

SceneDocument base() {
    SceneDocument doc;
    Material m;
    m.name = "m";
    doc.materials.push_back(m);
    Light l;
    l.name = "l";
    l.position = Vec3(0.0f, 5.0f, 0.0f);
    doc.addLight(l);
    Object o;
    o.name = "ball";
    o.material = "m";
    o.geometry = SphereGeometry{};
    doc.addObject(o);
    return doc;
}

int writtenVersion(const SceneDocument& doc) {
    return Json::parse(serializeScene(doc, kDir)).at("version").get<int>();
}

SceneDocument reread(const SceneDocument& doc) {
    const SceneLoadResult r = parseScene(serializeScene(doc, kDir), kDir, "v2.scene.json");
    EXPECT_TRUE(r.ok()) << r.errorText();
    EXPECT_TRUE(r.warnings.empty()) << r.warningText();
    return r.document;
}

TEST(SceneVersion2, TheWriterStatesVersion1UntilAVersion2KeyIsUsed) {
    SceneDocument doc = base();
    EXPECT_EQ(writtenVersion(doc), 1);
    {
        SceneDocument d = doc;
        d.materials[0].pattern = CheckerPattern{};
        EXPECT_EQ(writtenVersion(d), 2);
    }
    {
        SceneDocument d = doc;
        d.lights[0].type = LightType::Directional;
        EXPECT_EQ(writtenVersion(d), 2);
    }
    {
        SceneDocument d = doc;
        d.lights[0].type = LightType::Spot;
        EXPECT_EQ(writtenVersion(d), 2);
    }
    {
        SceneDocument d = doc;
        d.environment.image.file = "textures/sky.hdr";
        EXPECT_EQ(writtenVersion(d), 2);
    }
    {
        SceneDocument d = doc;
        d.render.opaqueShadows = true;
        EXPECT_EQ(writtenVersion(d), 2);
    }
    // A sphere light is version 1's: still version 1.
    doc.lights[0].type = LightType::Sphere;
    EXPECT_EQ(writtenVersion(doc), 1);
}

TEST(SceneVersion2, ColourFormsEnvironmentAndLights_RoundTrip) {
    SceneDocument doc = base();
    doc.materials[0].pattern =
        CheckerPattern{Color(0.9f, 0.1f, 0.2f), Color(0.0f, 0.3f, 1.0f), 0.25f};
    Material textured;
    textured.name = "t";
    ImageTexture t;
    t.image = {"textures/tiles.png", kDir + "/textures/tiles.png"};
    t.scaleU = 4.0f;
    t.scaleV = -2.0f;
    t.offsetU = 0.5f;
    textured.pattern = t;
    doc.materials.push_back(textured);
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.direction = Vec3(1.0f, -2.0f, 0.5f);
    sun.intensity = 0.7f;
    doc.addLight(sun);
    Light spot;
    spot.name = "spot";
    spot.type = LightType::Spot;
    spot.position = Vec3(0.0f, 4.0f, 1.0f);
    spot.target = Vec3(0.5f, 0.0f, 0.0f);
    spot.coneRadius = 12.5f;
    spot.coneFalloff = 20.0f;
    doc.addLight(spot);
    doc.environment.image = {"textures/sky.hdr", kDir + "/textures/sky.hdr"};
    doc.environment.intensity = 1.5f;
    doc.environment.rotation = -90.0f;
    doc.render.opaqueShadows = true;

    const SceneDocument back = reread(doc);
    EXPECT_TRUE(back.sameContent(doc));
    const auto& c = std::get<CheckerPattern>(back.materials[0].pattern);
    EXPECT_EQ(c.odd, Color(0.0f, 0.3f, 1.0f));
    EXPECT_EQ(c.scale, 0.25f);
    const auto& bt = std::get<ImageTexture>(back.materials[1].pattern);
    EXPECT_EQ(bt.image.resolvedPath, kDir + "/textures/tiles.png");
    EXPECT_EQ(bt.scaleV, -2.0f);
    EXPECT_EQ(back.lights[2].coneFalloff, 20.0f);
    EXPECT_EQ(back.environment.rotation, -90.0f);

    // The file spells it as the format says, with paths relative to the scene's folder.
    const Json j = Json::parse(serializeScene(doc, kDir));
    EXPECT_EQ(j["materials"][0]["color"].dump(),
              R"({"checker":[[0.9,0.1,0.2],[0.0,0.3,1.0]],"scale":0.25})");
    EXPECT_EQ(j["materials"][1]["color"].dump(),
              R"({"texture":"textures/tiles.png","scale":[4.0,-2.0],"offset":[0.5,0.0]})");
    EXPECT_EQ(j["environment"].dump(),
              R"({"file":"textures/sky.hdr","intensity":1.5,"rotation":-90.0})");
    EXPECT_EQ(j["lights"][1].dump(),
              R"({"name":"sun","type":"directional","direction":[1.0,-2.0,0.5],"intensity":0.7})");
}

TEST(SceneVersion2, AMissingTexture_IsAWarningNamingItsKey_AndIsSavedBackAsWritten) {
    const std::string text = R"({
  "format": "raystudio-scene",
  "version": 2,
  "environment": { "file": "no-such-sky.hdr" },
  "materials": [
    { "name": "a", "color": [1, 0, 0] },
    { "name": "b", "color": { "texture": "textures/no-such.png", "scale": [2, 2] } }
  ],
  "objects": [ { "name": "ball", "type": "sphere", "center": [0, 0, 0], "radius": 1,
                 "material": "b" } ]
}
)";
    const SceneLoadResult r = parseScene(text, kDir, "missing.scene.json");
    ASSERT_TRUE(r.ok()) << r.errorText();
    ASSERT_EQ(r.warnings.size(), 2u) << r.warningText();
    EXPECT_EQ(r.warnings[0].pointer, "/materials/1/color/texture");
    EXPECT_EQ(r.warnings[0].line, 7);
    EXPECT_NE(r.warnings[0].message.find("textures/no-such.png"), std::string::npos);
    EXPECT_NE(r.warnings[0].message.find("missing-image pattern"), std::string::npos);
    EXPECT_EQ(r.warnings[1].pointer, "/environment/file");
    EXPECT_EQ(r.document.objects.size(), 1u);

    const Json saved = Json::parse(serializeScene(r.document, kDir));
    EXPECT_EQ(saved["materials"][1]["color"]["texture"], "textures/no-such.png");
    EXPECT_EQ(saved["environment"]["file"], "no-such-sky.hdr");
}

TEST(SceneVersion2, ATextureThatIsADirectory_IsAWarning) {
    const std::string text = R"({ "format": "raystudio-scene", "version": 2,
  "materials": [ { "name": "b", "color": { "texture": "textures" } } ] })";
    const SceneLoadResult r = parseScene(text, kDir, "dir.scene.json");
    ASSERT_TRUE(r.ok()) << r.errorText();
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].message.find("directory"), std::string::npos) << r.warnings[0].message;
}

}  // namespace
}  // namespace rs
