// Scene reader errors: every rule of scenes/FORMAT.md fails the load with pointer, line, column.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>

#include "core/input_file.h"
#include "io/scene_io.h"

namespace rs {
namespace {

// A scene text with "@@" where the error must be reported; the position is counted here,
// independently of the reader's locator, and the marker removed.
struct MarkedText {
    std::string text;
    int line = 0;
    int column = 0;
};

MarkedText mark(const std::string& withMarker) {
    MarkedText m;
    std::size_t at = withMarker.find("@@");
    m.text = withMarker;
    if (at == std::string::npos) return m;
    m.text.erase(at, 2);
    m.line = 1;
    m.column = 1;
    for (std::size_t i = 0; i < at; ++i) {
        if (withMarker[i] == '\n') {
            ++m.line;
            m.column = 1;
        } else {
            ++m.column;
        }
    }
    return m;
}

// The header every case shares, then the case's own sections.
std::string scene(const std::string& body) {
    return "{\n  \"format\": \"raystudio-scene\",\n  \"version\": 1,\n" + body + "\n}\n";
}

// The same for a version 2 file.
std::string scene2(const std::string& body) {
    return "{\n  \"format\": \"raystudio-scene\",\n  \"version\": 2,\n" + body + "\n}\n";
}

struct ErrorCase {
    const char* name;
    std::string text;     ///< With "@@" where the error is.
    const char* pointer;  ///< Expected JSON pointer.
    const char* message;  ///< A part of the expected message.
};

// Test names, not bytes, in gtest's output.
void PrintTo(const ErrorCase& c, std::ostream* os) {
    *os << c.name;
}

class SceneReaderError : public testing::TestWithParam<ErrorCase> {};

TEST_P(SceneReaderError, FailsLoadWithPointerLineAndColumn) {
    const ErrorCase& c = GetParam();
    MarkedText m = mark(c.text);
    ASSERT_GT(m.line, 0) << "case has no @@ marker";
    SceneLoadResult r = parseScene(m.text, RAYSTUDIO_TEST_DATA, "bad.scene.json");
    ASSERT_EQ(r.errors.size(), 1u) << r.errorText();
    const SceneError& e = r.errors[0];
    EXPECT_EQ(e.pointer, c.pointer);
    EXPECT_EQ(e.line, m.line) << e.toString();
    EXPECT_EQ(e.column, m.column) << e.toString();
    EXPECT_NE(e.message.find(c.message), std::string::npos) << e.message;
    EXPECT_EQ(e.file, "bad.scene.json");
    EXPECT_TRUE(r.document.objects.empty() && r.document.materials.empty());
}

const std::string kSphere = R"("type": "sphere", "center": [0, 0, 0])";
// A whole valid scene, for what may or may not follow it.
const std::string kValid = scene(R"(  "render": {})");

const ErrorCase kCases[] = {
    {"SyntaxError", scene(R"(  "render": { "width": @@# })"), "", "syntax error"},
    {"RootNotObject", "@@[1, 2]", "", "must be an object"},
    {"MissingFormat", "@@{ \"version\": 1 }", "/format", "missing required key"},
    {"WrongFormat", "{ \"format\": @@\"other\", \"version\": 1 }", "/format", "raystudio-scene"},
    {"MissingVersion", "@@{ \"format\": \"raystudio-scene\" }", "/version", "missing"},
    {"UnsupportedVersion", "{ \"format\": \"raystudio-scene\", \"version\": @@3 }", "/version",
     "unsupported version 3 (this program reads versions 1 and 2)"},
    {"VersionZero", "{ \"format\": \"raystudio-scene\", \"version\": @@0 }", "/version",
     "unsupported version 0"},
    {"UnknownTopLevelKey", scene(R"(  @@"objekts": [])"), "/objekts", "unknown key"},
    {"UnknownCameraKey", scene(R"(  "camera": { "fov_y": 40, @@"fovy": 40 })"), "/camera/fovy",
     "unknown key"},
    {"UnknownRenderKey", scene(R"(  "render": { @@"depth": 2 })"), "/render/depth", "unknown key"},
    {"UnknownMaterialKey", scene(R"(  "materials": [ { "name": "m", @@"colour": [1, 1, 1] } ])"),
     "/materials/0/colour", "unknown key"},
    {"UnknownLightKey",
     scene(R"(  "lights": [ { "name": "l", "type": "point", "position": [0, 1, 0],
      @@"power": 2 } ])"),
     "/lights/0/power", "unknown key"},
    {"DuplicateKey", scene(R"(  "render": { "width": 10, @@"width": 20 })"), "/render/width",
     "duplicate key"},
    {"NumberGotString", scene(R"(  "camera": { "fov_y": @@"wide" })"), "/camera/fov_y",
     "must be a number"},
    {"IntegerGotFraction", scene(R"(  "render": { "width": @@12.5 })"), "/render/width",
     "must be an integer"},
    {"BoolGotNumber", scene(R"(  "render": { "adaptive_supersampling": @@1 })"),
     "/render/adaptive_supersampling", "true or false"},
    {"NameNotString", scene(R"(  "materials": [ { "name": @@7 } ])"), "/materials/0/name",
     "must be a string"},
    {"VectorOfTwo", scene(R"(  "camera": { "position": @@[0, 1] })"), "/camera/position",
     "array of 3 numbers"},
    {"VectorElementNotNumber", scene(R"(  "camera": { "position": [0, @@null, 1] })"),
     "/camera/position/1", "must be a number"},
    {"NumberTooLargeForFloat", scene(R"(  "render": { "exposure": @@1e39 })"), "/render/exposure",
     "finite"},
    {"UnknownTonemap", scene(R"(  "render": { "tonemap": @@"gamma" })"), "/render/tonemap",
     "must be one of"},
    {"UnknownProjection", scene(R"(  "camera": { "projection": @@"fisheye" })"),
     "/camera/projection", "must be one of"},
    {"ZeroWidth", scene(R"(  "render": { "width": @@0 })"), "/render/width", ">= 1"},
    {"HugeHeight", scene(R"(  "render": { "height": @@20000 })"), "/render/height", "too large"},
    {"HugeWidthBeyondInt", scene(R"(  "render": { "width": @@9999999999 })"), "/render/width",
     "too large"},
    {"NegativeMaxDepth", scene(R"(  "render": { "max_depth": @@-1 })"), "/render/max_depth",
     "in [0, 1000]"},
    {"MaxDepthBeyondStackSafeLimit", scene(R"(  "render": { "max_depth": @@200000 })"),
     "/render/max_depth", "in [0, 1000], got 200000"},
    {"MinWeightOfOne", scene(R"(  "render": { "min_weight": @@1 })"), "/render/min_weight",
     "in [0, 1), got 1"},
    {"NegativeMinWeight", scene(R"(  "render": { "min_weight": @@-0.01 })"), "/render/min_weight",
     "in [0, 1)"},
    {"MinWeightNotNumber", scene(R"(  "render": { "min_weight": @@"1/255" })"),
     "/render/min_weight", "must be a number"},
    {"NegativeShadowSamples", scene(R"(  "render": { "shadow_samples": @@-2 })"),
     "/render/shadow_samples", "in [0, 4096]"},
    {"ShadowSamplesBeyondLimit", scene(R"(  "render": { "shadow_samples": @@5000 })"),
     "/render/shadow_samples", "in [0, 4096]"},
    {"ZeroSupersampling", scene(R"(  "render": { "supersampling": @@0 })"), "/render/supersampling",
     "in [1, 4096]"},
    {"SupersamplingBeyondLimit", scene(R"(  "render": { "supersampling": @@70000 })"),
     "/render/supersampling", "in [1, 4096]"},
    {"NegativeBackground", scene(R"(  "render": { "background": [0, @@-0.5, 0] })"),
     "/render/background/1", ">= 0"},
    {"NegativeAmbient", scene(R"(  "render": { "ambient": [@@-1, 0, 0] })"), "/render/ambient/0",
     ">= 0"},
    {"FovOf180", scene(R"(  "camera": { "fov_y": @@180 })"), "/camera/fov_y", "in (0, 180)"},
    {"FovOfZero", scene(R"(  "camera": { "fov_y": @@0 })"), "/camera/fov_y", "in (0, 180)"},
    {"ZeroOrthoHeight", scene(R"(  "camera": { "ortho_height": @@0 })"), "/camera/ortho_height",
     "> 0"},
    {"CameraTargetIsPosition",
     scene(R"(  "camera": { "position": [1, 2, 3], "target": @@[1, 2, 3] })"), "/camera/target",
     "differ"},
    {"CameraUpAlongView", scene(R"(  "camera": { "target": [0, 5, 0], "up": @@[0, 2, 0] })"),
     "/camera/up", "parallel"},
    {"CameraDefaultUpAlongView", scene(R"(  "camera": @@{ "target": [0, -5, 0] })"), "/camera/up",
     "parallel"},
    {"ZeroUp", scene(R"(  "camera": { "up": @@[0, 0, 0] })"), "/camera/up", "non-zero"},
    {"NegativeMaterialColor",
     scene(R"(  "materials": [ { "name": "m", "color": [1, 1, @@-0.1] } ])"),
     "/materials/0/color/2", ">= 0"},
    {"DiffuseAboveOne", scene(R"(  "materials": [ { "name": "m", "diffuse": @@1.5 } ])"),
     "/materials/0/diffuse", "in [0, 1]"},
    {"NegativeSpecular", scene(R"(  "materials": [ { "name": "m", "specular": @@-0.1 } ])"),
     "/materials/0/specular", "in [0, 1]"},
    {"NegativeShininess", scene(R"(  "materials": [ { "name": "m", "shininess": @@-1 } ])"),
     "/materials/0/shininess", ">= 0"},
    {"ReflectivityAboveOne", scene(R"(  "materials": [ { "name": "m", "reflectivity": @@2 } ])"),
     "/materials/0/reflectivity", "in [0, 1]"},
    {"TransparencyBelowZero", scene(R"(  "materials": [ { "name": "m", "transparency": @@-1 } ])"),
     "/materials/0/transparency", "in [0, 1]"},
    {"ReflectivityPlusTransparencyAboveOne",
     scene(R"(  "materials": [ { "name": "m", "reflectivity": 0.6, "transparency": @@0.5 } ])"),
     "/materials/0/transparency", "reflectivity + transparency must be <= 1"},
    {"ZeroIor", scene(R"(  "materials": [ { "name": "m", "ior": @@0 } ])"), "/materials/0/ior",
     "> 0"},
    {"MissingMaterialName", scene(R"(  "materials": [ @@{ "color": [1, 1, 1] } ])"),
     "/materials/0/name", "missing required key \"name\""},
    {"EmptyMaterialName", scene(R"(  "materials": [ { "name": @@"" } ])"), "/materials/0/name",
     "must not be empty"},
    {"DuplicateMaterialName", scene(R"(  "materials": [ { "name": "m" },
    { "name": @@"m" } ])"),
     "/materials/1/name", "duplicate material name \"m\""},
    {"DuplicateLightName",
     scene(R"(  "lights": [ { "name": "l", "type": "point", "position": [0, 0, 0] },
    { "name": @@"l", "type": "point", "position": [1, 0, 0] } ])"),
     "/lights/1/name", "duplicate light name"},
    {"DuplicateObjectName",
     scene(R"(  "objects": [ { "name": "o", )" + kSphere + R"(, "radius": 1 },
    { "name": @@"o", )" +
           kSphere + R"(, "radius": 2 } ])"),
     "/objects/1/name", "duplicate object name"},
    {"UnknownLightType",
     scene(R"(  "lights": [ { "name": "l", "type": @@"laser", "position": [0, 0, 0] } ])"),
     "/lights/0/type", "must be one of \"point\", \"sphere\", \"directional\", \"spot\""},
    // Version 2's keys in a file that says version 1: an older build would refuse it.
    {"SpotLightInVersion1",
     scene(R"(  "lights": [ { "name": "l", "type": @@"spot", "position": [0, 1, 0],
                 "target": [0, 0, 0] } ])"),
     "/lights/0/type", "needs format version 2 (the file says \"version\": 1)"},
    {"CheckerInVersion1",
     scene(
         R"(  "materials": [ { "name": "m", "color": @@{ "checker": [[1, 1, 1], [0, 0, 0]] } } ])"),
     "/materials/0/color", "needs format version 2"},
    {"EnvironmentInVersion1", scene(R"(  "environment": @@{ "file": "missing-sky.hdr" })"),
     "/environment", "needs format version 2"},
    {"OpaqueShadowsInVersion1", scene(R"(  "render": { "opaque_shadows": @@true })"),
     "/render/opaque_shadows", "needs format version 2"},
    // Version 2's own rules.
    {"CheckerOneColour",
     scene2(R"(  "materials": [ { "name": "m", "color": { "checker": @@[[1, 1, 1]] } } ])"),
     "/materials/0/color/checker", "checker must be an array of 2 colours"},
    {"CheckerNegativeColour", scene2(R"(  "materials": [ { "name": "m",
                    "color": { "checker": [[1, 1, 1], [0, @@-1, 0]] } } ])"),
     "/materials/0/color/checker/1/1", "checker/1 components must be >= 0"},
    {"CheckerZeroScale", scene2(R"(  "materials": [ { "name": "m",
                    "color": { "checker": [[1, 1, 1], [0, 0, 0]], "scale": @@0 } } ])"),
     "/materials/0/color/scale", "scale must be > 0"},
    {"ColorObjectOfNeitherForm",
     scene2(R"(  "materials": [ { "name": "m", "color": @@{ "scale": 2 } } ])"),
     "/materials/0/color", "color must be [r, g, b]"},
    {"CheckerAndTexture", scene2(R"(  "materials": [ { "name": "m",
                    "color": @@{ "checker": [[1, 1, 1], [0, 0, 0]], "texture": "a.png" } } ])"),
     "/materials/0/color", "both"},
    {"UnknownKeyInColour", scene2(R"(  "materials": [ { "name": "m",
                    "color": { "checker": [[1, 1, 1], [0, 0, 0]], @@"scael": 2 } } ])"),
     "/materials/0/color/scael", "unknown key"},
    {"EmptyTexture", scene2(R"(  "materials": [ { "name": "m", "color": { "texture": @@"" } } ])"),
     "/materials/0/color/texture", "texture must not be empty"},
    {"TextureZeroScale", scene2(R"(  "materials": [ { "name": "m",
                    "color": { "texture": "t.png", "scale": [2, @@0] } } ])"),
     "/materials/0/color/scale/1", "texture scale must be non-zero"},
    {"TextureScaleNotPair",
     scene2(R"(  "materials": [ { "name": "m", "color": { "texture": "t.png", "scale": @@3 } } ])"),
     "/materials/0/color/scale", "scale must be an array of 2 numbers [u, v]"},
    {"EnvironmentWithoutFile", scene2(R"(  "environment": @@{ "intensity": 2 })"),
     "/environment/file", "missing required key \"file\""},
    {"EnvironmentNegativeIntensity",
     scene2(R"(  "environment": { "file": "sky.hdr", "intensity": @@-1 })"),
     "/environment/intensity", "intensity must be >= 0"},
    {"SpotAimedAtItself",
     scene2(R"(  "lights": [ { "name": "l", "type": "spot", "position": [0, 1, 0],
                 "target": @@[0, 1, 0] } ])"),
     "/lights/0/target", "spot light target must differ from its position"},
    {"SpotWithoutTarget",
     scene2(R"(  "lights": [ @@{ "name": "l", "type": "spot", "position": [0, 1, 0] } ])"),
     "/lights/0/target", "missing required key \"target\""},
    {"SpotRadiusOver90",
     scene2(R"(  "lights": [ { "name": "l", "type": "spot", "position": [0, 1, 0],
                 "target": [0, 0, 0], "radius": @@120 } ])"),
     "/lights/0/radius", "radius must be in [0, 90]"},
    {"SunWithPosition",
     scene2(R"(  "lights": [ { "name": "l", "type": "directional", "direction": [0, -1, 0],
                 @@"position": [0, 9, 0] } ])"),
     "/lights/0/position", "a directional light has no position"},
    {"SunWithoutDirection", scene2(R"(  "lights": [ @@{ "name": "l", "type": "directional" } ])"),
     "/lights/0/direction", "missing required key"},
    {"SunZeroDirection",
     scene2(R"(  "lights": [ { "name": "l", "type": "directional", "direction": @@[0, 0, 0] } ])"),
     "/lights/0/direction", "direction must be a non-zero vector"},
    {"MissingLightPosition", scene(R"(  "lights": [ @@{ "name": "l", "type": "point" } ])"),
     "/lights/0/position", "missing required key"},
    {"ZeroIntensity",
     scene(
         R"(  "lights": [ { "name": "l", "type": "point", "position": [0, 0, 0], "intensity": @@0 } ])"),
     "/lights/0/intensity", "> 0"},
    {"PointLightWithRadius",
     scene(
         R"(  "lights": [ { "name": "l", "type": "point", "position": [0, 0, 0], @@"radius": 1 } ])"),
     "/lights/0/radius", "point light has no radius"},
    {"SphereLightWithoutRadius",
     scene(R"(  "lights": [ @@{ "name": "l", "type": "sphere", "position": [0, 0, 0] } ])"),
     "/lights/0/radius", "missing required key"},
    {"SphereLightZeroRadius",
     scene(
         R"(  "lights": [ { "name": "l", "type": "sphere", "position": [0, 0, 0], "radius": @@0 } ])"),
     "/lights/0/radius", "> 0"},
    {"NegativeLightColor",
     scene(
         R"(  "lights": [ { "name": "l", "type": "point", "position": [0, 0, 0], "color": [@@-1, 0, 0] } ])"),
     "/lights/0/color/0", ">= 0"},
    {"ZeroRadiusSphere",
     scene(R"(  "objects": [ { "name": "s", )" + kSphere + R"(, "radius": @@0 } ])"),
     "/objects/0/radius", "radius must be > 0, got 0"},
    {"SphereWithoutRadius", scene(R"(  "objects": [ @@{ "name": "s", )" + kSphere + R"( } ])"),
     "/objects/0/radius", "missing required key \"radius\""},
    {"SphereWithPlaneKey",
     scene(R"(  "objects": [ { "name": "s", )" + kSphere +
           R"(, "radius": 1, @@"normal": [0, 1, 0] } ])"),
     "/objects/0/normal", "unknown key"},
    {"MissingObjectType", scene(R"(  "objects": [ @@{ "name": "s" } ])"), "/objects/0/type",
     "missing required key \"type\""},
    {"UnknownObjectType", scene(R"(  "objects": [ { "name": "s", "type": @@"torus" } ])"),
     "/objects/0/type", "must be one of"},
    {"MissingObjectName", scene(R"(  "objects": [ @@{ )" + kSphere + R"(, "radius": 1 } ])"),
     "/objects/0/name", "missing required key \"name\""},
    {"UndefinedMaterial",
     scene(R"(  "objects": [ { "name": "s", )" + kSphere +
           R"(, "radius": 1, "material": @@"gold" } ])"),
     "/objects/0/material", "\"gold\" is not defined"},
    {"EmptyMaterialReference",
     scene(R"(  "objects": [ { "name": "s", )" + kSphere +
           R"(, "radius": 1, "material": @@"" } ])"),
     "/objects/0/material", "must not be empty"},
    {"VisibleNotBool",
     scene(R"(  "objects": [ { "name": "s", )" + kSphere +
           R"(, "radius": 1, "visible": @@"yes" } ])"),
     "/objects/0/visible", "true or false"},
    {"PlaneWithTranslate",
     scene(
         R"(  "objects": [ { "name": "p", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
      @@"translate": [0, 1, 0] } ])"),
     "/objects/0/translate", "plane takes no transform"},
    {"PlaneZeroNormal",
     scene(
         R"(  "objects": [ { "name": "p", "type": "plane", "point": [0, 0, 0], "normal": @@[0, 0, 0] } ])"),
     "/objects/0/normal", "non-zero"},
    {"RectangleZeroU",
     scene(
         R"(  "objects": [ { "name": "r", "type": "rectangle", "center": [0, 0, 0], "u": @@[0, 0, 0], "v": [0, 1, 0] } ])"),
     "/objects/0/u", "non-zero"},
    {"RectangleEdgesNotOrthogonal",
     scene(
         R"(  "objects": [ { "name": "r", "type": "rectangle", "center": [0, 0, 0], "u": [1, 0, 0], "v": @@[1, 1, 0] } ])"),
     "/objects/0/v", "orthogonal"},
    {"BoxWithoutExtent",
     scene(
         R"(  "objects": [ { "name": "b", "type": "box", "min": [0, 0, 0], "max": [1, @@0, 1] } ])"),
     "/objects/0/max/1", "greater than min"},
    {"ZeroScaleNumber",
     scene(R"(  "objects": [ { "name": "s", )" + kSphere + R"(, "radius": 1, "scale": @@0 } ])"),
     "/objects/0/scale", "non-zero"},
    {"ZeroScaleComponent",
     scene(R"(  "objects": [ { "name": "s", )" + kSphere +
           R"(, "radius": 1, "scale": [1, 1, @@0] } ])"),
     "/objects/0/scale/2", "non-zero"},
    {"MissingMeshFile",
     scene(R"(  "objects": [ { "name": "m", "type": "mesh", "file": @@"meshes/nope.obj" } ])"),
     "/objects/0/file", "meshes/nope.obj\": file not found"},
    {"BrokenMesh",
     scene(
         R"(  "objects": [ { "name": "m", "type": "mesh", "file": @@"meshes/nan_vertex.obj" } ])"),
     "/objects/0/file", "nan_vertex.obj\": vertex 0"},
    {"MaterialsNotArray", scene(R"(  "materials": @@{})"), "/materials", "must be an array"},
    {"ObjectEntryNotObject", scene(R"(  "objects": [ @@3 ])"), "/objects/0", "must be an object"},
    {"NulByteAfterTopLevelObject", kValid + "@@" + std::string(1, '\0') + "garbage", "",
     "NUL byte"},
    {"NulByteInsideTopLevelObject",
     "{ \"format\": \"raystudio-scene\",@@" + std::string(1, '\0') + " \"version\": 1 }", "",
     "NUL byte"},
    {"TextAfterTopLevelObject", kValid + "  @@garbage\n", "", "expected end of input"},
    {"SecondTopLevelObject", kValid + "@@{}", "", "expected end of input"},
    {"NestingTooDeep",
     "@@" + scene("  \"x-deep\": " + std::string(300, '[') + std::string(300, ']')), "", "nesting"},
};

INSTANTIATE_TEST_SUITE_P(Rules, SceneReaderError, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<ErrorCase>& info) {
                             return std::string(info.param.name);
                         });

TEST(SceneReader, ManyBadEntries_ReportsEveryErrorInFileOrder) {
    std::string text = scene(R"(  "materials": [ { "name": "m", "ior": -1 } ],
  "objects": [
    { "name": "a", "type": "sphere", "center": [0, 0, 0], "radius": -1 },
    { "name": "b", "type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "rotate": [0, "x", 0] }
  ])");
    SceneLoadResult r = parseScene(text, RAYSTUDIO_TEST_DATA);
    ASSERT_EQ(r.errors.size(), 3u) << r.errorText();
    EXPECT_EQ(r.errors[0].pointer, "/materials/0/ior");
    EXPECT_EQ(r.errors[1].pointer, "/objects/0/radius");
    EXPECT_EQ(r.errors[2].pointer, "/objects/1/rotate/1");
    EXPECT_EQ(r.errors[1].line, 6);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.document.objects.empty());
}

TEST(SceneReader, ErrorText_NamesFileLineColumnPointerAndMessage) {
    SceneLoadResult r = parseScene(scene(R"(  "render": { "width": 0 })"), "", "a.scene.json");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errorText(), "a.scene.json:4:24: /render/width: width must be >= 1, got 0\n");
}

TEST(SceneReader, ColumnsCountCharactersNotBytes) {
    MarkedText m = mark(scene(R"(  "materials": [ { "name": "grün", "ior": @@0 } ])"));
    SceneLoadResult r = parseScene(m.text, "");
    ASSERT_EQ(r.errors.size(), 1u);
    // The marker counted bytes; "ü" is two bytes but one column.
    EXPECT_EQ(r.errors[0].column, m.column - 1);
}

TEST(SceneReader, EscapedKeys_AreLocatedByTheirDecodedPointer) {
    MarkedText m = mark(scene(R"(  "camera": { "a\/b~": 1, @@"\u0066ov": 2 })"));
    SceneLoadResult r = parseScene(m.text, "");
    ASSERT_EQ(r.errors.size(), 2u) << r.errorText();
    EXPECT_EQ(r.errors[0].pointer, "/camera/a~1b~0");
    EXPECT_EQ(r.errors[1].pointer, "/camera/fov");
    EXPECT_EQ(r.errors[1].line, m.line);
    EXPECT_EQ(r.errors[1].column, m.column);
}

TEST(SceneReader, LoadMissingFile_ErrorNamesThePath) {
    std::string path = testing::TempDir() + "/no-such.scene.json";
    SceneLoadResult r = loadScene(path);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].file, path);
    EXPECT_NE(r.errors[0].toString().find(path), std::string::npos);
}

TEST(SceneReader, LoadDirectory_IsAnErrorNotAnEmptyScene) {
    SceneLoadResult r = loadScene(RAYSTUDIO_TEST_DATA);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_NE(r.errors[0].message.find("directory"), std::string::npos);
}

TEST(SceneReader, TrailingWhitespace_IsFine) {
    SceneLoadResult r = parseScene(kValid + " \t\r\n\n", "");
    EXPECT_TRUE(r.ok()) << r.errorText();
}

// Refusals that must come at once, before any read: each names the path and says why (the
// reason is the check made before reading, which a read of the device could not give; a
// bound in seconds would race a loaded CI machine).
void expectRefusedAtOnce(const std::string& path, const char* why) {
    SceneLoadResult r = loadScene(path);
    ASSERT_EQ(r.errors.size(), 1u) << r.errorText();
    EXPECT_EQ(r.errors[0].file, path);
    EXPECT_EQ(r.errors[0].line, 0) << r.errorText();
    EXPECT_NE(r.errors[0].message.find("cannot read scene file"), std::string::npos)
        << r.errorText();
    EXPECT_NE(r.errors[0].message.find(why), std::string::npos) << r.errorText();
}

TEST(SceneReader, LoadDevice_IsRefusedWithoutReadingIt) {
    expectRefusedAtOnce("/dev/zero", "device");
}

TEST(SceneReader, LoadFifo_IsRefusedWithoutBlocking) {
    const std::string fifo = testing::TempDir() + "/scene_errors_fifo.scene.json";
    std::filesystem::remove(fifo);
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
    expectRefusedAtOnce(fifo, "FIFO");
    std::filesystem::remove(fifo);
}

TEST(SceneReader, LoadFileAboveTheSizeLimit_IsRefusedBeforeReading) {
    // A sparse file: its size is over the limit, its blocks are not on disk.
    const std::string big = testing::TempDir() + "/scene_errors_big.scene.json";
    std::ofstream(big) << "{}";
    std::filesystem::resize_file(big, kMaxSceneFileBytes + 1);
    expectRefusedAtOnce(big, "limit");
    std::filesystem::remove(big);
}

TEST(SceneReader, ReadError_IsReportedAsOneNotAsASyntaxError) {
    // procfs says a regular file of size 0; reading offset 0 of a process's memory fails.
    const std::string mem = "/proc/self/mem";
    if (!std::filesystem::exists(mem)) GTEST_SKIP() << "no procfs";
    SceneLoadResult r = loadScene(mem);
    ASSERT_EQ(r.errors.size(), 1u) << r.errorText();
    EXPECT_EQ(r.errors[0].line, 0) << r.errorText();
    EXPECT_NE(r.errors[0].message.find("read error"), std::string::npos) << r.errorText();
    EXPECT_EQ(r.errors[0].message.find("syntax"), std::string::npos) << r.errorText();
}

}  // namespace
}  // namespace rs
