// Checkers, image textures and the environment through the one trace path (scenes/FORMAT.md
// "materials" and "environment"): each expected value is worked out here from the format's
// equations, and every image is written here with OpenImageIO.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "closed_form_support.h"
#include "integrator/whitted.h"
#include "session_test_support.h"
#include "test_scenes.h"

namespace rs {
namespace {

namespace fs = std::filesystem;
using OIIO::TypeDesc;
using test::addMaterial;
using test::addPlane;
using test::addPointLight;
using test::addSphere;
using test::expectColorNear;
using test::traceOne;

constexpr double kPi = 3.14159265358979323846;

/// The sRGB EOTF, written out here in double.
float srgbDecode(int code) {
    const double c = code / 255.0;
    return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

/// A material `name` whose colour is a checker.
void addChecker(SceneDocument& doc, const std::string& name, Color even, Color odd, float scale,
                float reflectivity = 0.0f, float transparency = 0.0f) {
    addMaterial(doc, name, Color(0.8f), 1.0f, 0.0f, reflectivity, transparency);
    doc.materials.back().pattern = CheckerPattern{even, odd, scale};
}

/// A material `name` whose colour is the image `file`.
void addTexture(SceneDocument& doc, const std::string& name, const std::string& file) {
    addMaterial(doc, name, Color(0.8f), 1.0f);
    ImageTexture t;
    t.image.file = file;
    doc.materials.back().pattern = t;
}

/// Straight down onto the floor y = 0 at (x, z), from just above it.
Ray down(float x, float z) {
    return Ray::make(Vec3(x, 0.1f, z), Vec3(0, -1, 0));
}

class PatternsTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "raystudio-patterns-XXXXXX").string();
        ASSERT_NE(mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    /// Writes a w x h image (top row first) of `channels` channels of `format`.
    std::string write(const std::string& name, int w, int h, int channels, TypeDesc format,
                      const void* pixels) {
        const std::string file = (dir_ / name).string();
        auto out = OIIO::ImageOutput::create(file);
        EXPECT_TRUE(out) << OIIO::geterror();
        if (!out) return file;
        const OIIO::ImageSpec spec(w, h, channels, format);
        EXPECT_TRUE(out->open(file, spec)) << out->geterror();
        EXPECT_TRUE(out->write_image(format, pixels)) << out->geterror();
        EXPECT_TRUE(out->close());
        return file;
    }

    /// An 8 x 4 float RGB image: colour `left` where u < 1/2, `right` from u = 1/2 on.
    std::string twoColumns(const std::string& name, Color left, Color right) {
        std::vector<float> pixels;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 8; ++x) {
                const Color c = x < 4 ? left : right;
                pixels.insert(pixels.end(), {c.x, c.y, c.z});
            }
        return write(name, 8, 4, 3, TypeDesc::FLOAT, pixels.data());
    }

    fs::path dir_;
};

// --- Checker ---------------------------------------------------------------------------------

TEST(CheckerSurface, EachCellLitByLambertWithItsOwnColour) {
    const Color even(0.9f, 0.2f, 0.1f), odd(0.1f, 0.3f, 0.8f), ambient(0.05f, 0.1f, 0.05f);
    SceneDocument doc;
    doc.render.ambient = ambient;
    addChecker(doc, "tiles", even, odd, 1.0f);
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "tiles");
    const float intensity = 1.5f;
    // Cell (i, j, k) = floor of each coordinate + 0.001: the floor is in j = 0, so the cell
    // at (x, z) is even when floor(x) + floor(z) is.
    for (const auto& [x, z] : {std::pair{0.5f, 0.5f}, std::pair{1.5f, 0.5f}, std::pair{-0.5f, 0.5f},
                               std::pair{-0.5f, -2.5f}, std::pair{2.5f, 3.5f}}) {
        SceneDocument lit = doc;
        addPointLight(lit, "above", Vec3(x, 4.0f, z), intensity);  // N.L = 1
        const bool isEven = (int(std::floor(x)) + int(std::floor(z))) % 2 == 0;
        const Color c = isEven ? even : odd;
        const Color expected = ambient * c + intensity * c;
        expectColorNear(traceOne(lit, down(x, z)), expected, 1e-5f,
                        "x = " + std::to_string(x) + ", z = " + std::to_string(z));
    }
}

TEST(CheckerSurface, MovesWithItsObject_APlaneKeepsTheScenesSpace) {
    const Color even(1.0f, 0.0f, 0.0f), odd(0.0f, 0.0f, 1.0f);
    SceneDocument doc;
    doc.render.ambient = Color(1.0f);  // No light: the colour is the cell's.
    addChecker(doc, "tiles", even, odd, 1.0f);
    Object board;
    board.name = "board";
    board.material = "tiles";
    board.geometry = RectangleGeometry{Vec3(0), Vec3(10, 0, 0), Vec3(0, 0, -10)};
    const ObjectId id = doc.addObject(board);
    expectColorNear(traceOne(doc, down(0.5f, 0.5f)), even, 1e-5f, "in place");
    doc.findObject(id)->transform.translate = Vec3(1, 0, 0);
    // Object space is world space minus (1, 0, 0): (0.5, 0, 0.5) is in cell (-1, 0, 0).
    expectColorNear(traceOne(doc, down(0.5f, 0.5f)), odd, 1e-5f, "moved by +1 in x");
    expectColorNear(traceOne(doc, down(1.5f, 0.5f)), even, 1e-5f, "the cell moved along");
    doc.findObject(id)->transform.translate = Vec3(0);
    doc.findObject(id)->transform.scale = Vec3(2.0f);  // Cells twice as large.
    expectColorNear(traceOne(doc, down(1.5f, 0.5f)), even, 1e-5f, "scaled by 2");

    // A plane's own space is the scene's: moving its point does not move its cells.
    SceneDocument floor;
    floor.render.ambient = Color(1.0f);
    addChecker(floor, "tiles", even, odd, 1.0f);
    addPlane(floor, "floor", Vec3(1, 0, 0), Vec3(0, 1, 0), "tiles");
    expectColorNear(traceOne(floor, down(0.5f, 0.5f)), even, 1e-5f, "plane");
}

TEST(CheckerSurface, FarFloorAtGrazingAngleIsTheMeanColour_NearFloorIsSharp) {
    const Color even(1.0f, 0.8f, 0.6f), odd(0.0f, 0.2f, 0.1f);
    SceneDocument doc;
    doc.render.ambient = Color(1.0f);
    doc.render.width = 640, doc.render.height = 480;
    addChecker(doc, "tiles", even, odd, 0.01f);
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "tiles");
    // From height 1 at a slope of 1 in 50: the floor 50 units away. A pixel's cone there is
    // 50 * 2 tan(27.5 deg) / 480 = 0.11 units across and 50 times that along the view, over
    // ten cells across and hundreds along: a point sample would give one cell's colour.
    const Color mean = 0.5f * (even + odd);
    for (float x : {0.0f, 0.013f, 0.37f}) {
        const Ray grazing = Ray::make(Vec3(x, 1.0f, 0.0f), glm::normalize(Vec3(0, -0.02f, -1)));
        expectColorNear(traceOne(doc, grazing), mean, 0.02f * (even.x - odd.x),
                        "grazing, x = " + std::to_string(x));
    }
    // Near and head-on the cone is a fiftieth of a cell: the cells themselves.
    expectColorNear(traceOne(doc, down(0.005f, 0.005f)), even, 1e-4f, "near, even cell");
    expectColorNear(traceOne(doc, down(0.015f, 0.005f)), odd, 1e-4f, "near, odd cell");
}

TEST(CheckerSurface, OneColourTwiceIsBitIdenticalToTheFlatColour) {
    const Color c(0.7f, 0.45f, 0.2f);
    SceneDocument flat = test::smallRoom();
    addMaterial(flat, "paint", c, 0.9f, 0.3f);
    addSphere(flat, "ball", Vec3(0.7f, 0.5f, -3.0f), 0.5f, "paint");
    SceneDocument patterned = flat;
    patterned.materials.back().pattern = CheckerPattern{c, c, 0.25f};
    const Camera& cam = flat.camera;
    for (float dx : {-0.3f, -0.1f, 0.0f, 0.12f, 0.25f}) {
        for (float dy : {-0.3f, -0.05f, 0.1f}) {
            const Vec3 dir =
                glm::normalize(glm::normalize(cam.target - cam.position) + Vec3(dx, dy, 0.0f));
            const Ray ray = Ray::make(cam.position, dir);
            const Color a = traceOne(flat, ray), b = traceOne(patterned, ray);
            EXPECT_EQ(a, b) << "dx = " << dx << ", dy = " << dy;
        }
    }
}

TEST(CheckerSurface, GlassShadowTakesTheCheckerColourWhereTheShadowRayCrossesIt) {
    // A glass sheet (transparency 1, no reflection) at y = 1 with a checker over a white
    // floor, a point light straight above: the floor below each cell gets light * the cell.
    const Color even(0.9f, 0.5f, 0.1f), odd(0.2f, 0.6f, 1.0f), white(1.0f);
    SceneDocument doc;
    doc.render.ambient = Color(0.0f);
    addMaterial(doc, "white", white, 1.0f);
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "white");
    addChecker(doc, "glass", even, odd, 1.0f, 0.0f, 1.0f);
    Object sheet;
    sheet.name = "sheet";
    sheet.material = "glass";
    // In object space at y = 0.5 (cell j = 0), moved up to y = 1.
    sheet.geometry = RectangleGeometry{Vec3(0, 0.5f, 0), Vec3(10, 0, 0), Vec3(0, 0, -10)};
    sheet.transform.translate = Vec3(0, 0.5f, 0);
    doc.addObject(sheet);
    for (const auto& [x, expected] : {std::pair{0.5f, even}, std::pair{1.5f, odd}}) {
        SceneDocument lit = doc;
        addPointLight(lit, "above", Vec3(x, 4.0f, 0.5f));
        expectColorNear(traceOne(lit, down(x, 0.5f)), expected, 1e-5f, "x = " + std::to_string(x));
    }
}

TEST(CheckerSurface, MirrorShownAsLambertWhileMovingTakesTheCellsColour) {
    // The interactive policy's mirror-as-Lambert share (reflectivity r shaded as a Lambert
    // surface of the colour there): local (1 - r) * (A c kd + I c kd) + r * (A c + I c).
    const Color even(0.9f, 0.6f, 0.2f), odd(0.1f, 0.4f, 0.7f), ambient(0.1f, 0.05f, 0.1f);
    const float kd = 0.5f, r = 0.6f, intensity = 1.25f;
    SceneDocument doc;
    doc.render.ambient = ambient;
    addChecker(doc, "tiles", even, odd, 1.0f, r);
    doc.materials.back().diffuse = kd;
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "tiles");
    TraceOptions moving = TraceOptions::fromSettings(doc.render);
    moving.reflectionAsDiffuse = true;
    for (const auto& [x, c] : {std::pair{0.5f, even}, std::pair{1.5f, odd}}) {
        SceneDocument lit = doc;
        addPointLight(lit, "above", Vec3(x, 4.0f, 0.5f), intensity);
        const CompiledScene scene(lit);
        const WhittedIntegrator integrator(scene, moving);
        TraceCounters counters;
        const Color got = integrator.traceCamera(down(x, 0.5f), 3u, counters);
        const Color expected = (1.0f - r) * (ambient * c * kd + intensity * c * kd) +
                               r * (ambient * c + intensity * c);
        expectColorNear(got, expected, 1e-5f, "x = " + std::to_string(x));
    }
}

TEST(CheckerSurface, DeferredShadowsResolveToTheFullTraceOnAPattern) {
    // Shown unshadowed first, then each record's shadowed-minus-unshadowed added: the record
    // must carry the cell's colour for the sum to be the full trace's.
    const Color even(0.9f, 0.6f, 0.2f), odd(0.1f, 0.4f, 0.7f);
    SceneDocument doc;
    doc.render.ambient = Color(0.05f);
    addChecker(doc, "tiles", even, odd, 1.0f);
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "tiles");
    addMaterial(doc, "stone", Color(0.5f), 1.0f);
    addSphere(doc, "blocker", Vec3(0.5f, 2.0f, 0.5f), 0.4f, "stone");
    addPointLight(doc, "above", Vec3(0.5f, 4.0f, 0.5f));
    const CompiledScene scene(doc);
    const WhittedIntegrator full(scene);
    TraceOptions deferredOptions = TraceOptions::fromSettings(doc.render);
    deferredOptions.shadows = ShadowQuality::Deferred;
    const WhittedIntegrator deferred(scene, deferredOptions);
    for (const auto& [x, c] : {std::pair{0.5f, even}, std::pair{1.5f, odd}}) {
        TraceCounters counters;
        const Color whole = full.traceCamera(down(x, 0.5f), 5u, counters);
        ShadingRecord records[4];
        RecordSink sink{records, 4};
        Color sum = deferred.traceCamera(down(x, 0.5f), 5u, counters, nullptr, &sink);
        ASSERT_FALSE(sink.overflow);
        EXPECT_EQ(sink.count, 1);  // The floor point: the light's term was left to resolve.
        for (int k = 0; k < sink.count; ++k) sum += deferred.resolveDeferred(records[k], counters);
        expectColorNear(sum, whole, 1e-6f, "x = " + std::to_string(x));
    }
    // Under the blocker only the ambient term is left; beside it the light adds c.
    TraceCounters counters;
    expectColorNear(full.traceCamera(down(0.5f, 0.5f), 5u, counters), 0.05f * even, 1e-6f,
                    "shadowed even cell");
    expectColorNear(full.traceCamera(down(1.5f, 0.5f), 5u, counters),
                    0.05f * odd + odd * (4.0f / std::sqrt(17.0f)),  // N.L = 4 / sqrt(17)
                    1e-5f, "lit odd cell");
}

// --- Image textures -------------------------------------------------------------------------

TEST_F(PatternsTest, SphereShowsTheImageWhereItsLongitudeSays_8BitIsDecodedFromSRGB) {
    // Left half (u < 1/2) sRGB code 188 red, right half 188 green; 188 decodes to ~0.5029.
    std::vector<uint8_t> pixels;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            pixels.insert(pixels.end(), {uint8_t(x < 4 ? 188 : 0), uint8_t(x < 4 ? 0 : 188), 0});
    const std::string file = write("halves.png", 8, 4, 3, TypeDesc::UINT8, pixels.data());
    SceneDocument doc;
    doc.render.ambient = Color(1.0f);  // No light: the texel's colour.
    addTexture(doc, "map", file);
    addSphere(doc, "globe", Vec3(0, 0, 0), 1.0f, "map");
    const float half = srgbDecode(188);
    ASSERT_NEAR(half, 0.5029f, 1e-4f);
    const Color red(half, 0, 0), green(0, half, 0);
    // u = atan2(z, x) / (2 pi) in [0, 1): a ray from outside toward the centre hits the
    // sphere at the direction it came from.
    for (double u : {0.125, 0.25, 0.375, 0.625, 0.75, 0.875}) {
        const double phi = 2.0 * kPi * u;
        const Vec3 at(float(std::cos(phi)), 0.2f, float(std::sin(phi)));
        const Vec3 from = 5.0f * at;
        const Ray ray = Ray::make(from, glm::normalize(-from));
        expectColorNear(traceOne(doc, ray), u < 0.5 ? red : green, 1.5e-3f,
                        "u = " + std::to_string(u));
    }
    const CompiledScene scene(doc);
    EXPECT_TRUE(scene.problems().empty());
}

TEST_F(PatternsTest, TexturedFloorIsLitByLambert) {
    // A 2 x 2 float image on the floor, one unit per image: u = x, v = -z (scenes/FORMAT.md).
    // Texel (column c, row r from the top) covers u in [c/2, (c+1)/2), v in [1-(r+1)/2, 1-r/2).
    const Color tl(0.25f, 0.5f, 0.75f), tr(0.5f, 0.125f, 0.25f), bl(0.75f, 0.75f, 0.125f),
        br(0.125f, 0.25f, 1.0f);
    const float pixels[] = {tl.x, tl.y, tl.z, tr.x, tr.y, tr.z, bl.x, bl.y, bl.z, br.x, br.y, br.z};
    const std::string file = write("four.exr", 2, 2, 3, TypeDesc::FLOAT, pixels);
    SceneDocument doc;
    const Color ambient(0.1f);
    doc.render.ambient = ambient;
    addTexture(doc, "map", file);
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "map");
    // Texel centres: u = 1/4 or 3/4, v = 1/4 or 3/4 (z = -v).
    for (const auto& [x, z, c] : {std::tuple{0.25f, -0.75f, tl}, std::tuple{0.75f, -0.75f, tr},
                                  std::tuple{0.25f, -0.25f, bl}, std::tuple{0.75f, -0.25f, br},
                                  std::tuple{1.25f, -1.25f, bl}}) {
        SceneDocument lit = doc;
        addPointLight(lit, "above", Vec3(x, 3.0f, z), 2.0f);
        expectColorNear(traceOne(lit, down(x, z)), ambient * c + 2.0f * c, 1e-4f,
                        "x = " + std::to_string(x) + ", z = " + std::to_string(z));
    }
}

TEST_F(PatternsTest, MissingTextureIsAProblemNamingItsKey_AndRendersTheMissingPattern) {
    SceneDocument doc;
    doc.render.ambient = Color(1.0f);
    addMaterial(doc, "plain", Color(0.5f), 1.0f);
    const std::string missing = (dir_ / "no-such-image.png").string();
    addTexture(doc, "map", missing);
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "map");
    const CompiledScene scene(doc);
    ASSERT_EQ(scene.problems().size(), 1u);
    const std::string& problem = scene.problems()[0];
    EXPECT_EQ(problem.rfind("/materials/1/color/texture: ", 0), 0u) << problem;
    EXPECT_NE(problem.find("no-such-image.png"), std::string::npos) << problem;
    // Magenta where floor(8 s) + floor(8 t) is even, s = u = x, t = 1 - v = 1 + z.
    for (const auto& [x, z] : {std::pair{0.0625f, 0.0625f}, std::pair{0.1875f, 0.0625f},
                               std::pair{0.1875f, -0.0625f}, std::pair{0.3125f, 0.4375f}}) {
        const int cells = int(std::floor(8.0f * x)) + int(std::floor(8.0f * (1.0f + z)));
        const Color expected = cells % 2 == 0 ? Color(1, 0, 1) : Color(0);
        expectColorNear(traceOne(doc, down(x, z)), expected, 1e-5f,
                        "x = " + std::to_string(x) + ", z = " + std::to_string(z));
    }
}

// --- Environment ----------------------------------------------------------------------------

TEST_F(PatternsTest, EscapingCameraRayReturnsTheEnvironmentTimesItsIntensity) {
    const Color a(0.25f, 0.5f, 0.75f), b(0.75f, 0.125f, 0.5f);
    SceneDocument doc;
    doc.render.background = Color(0.3f, 0.3f, 0.3f);
    doc.environment.image.file = twoColumns("sky.exr", a, b);
    doc.environment.intensity = 2.0f;
    // u = atan2(z, x) / (2 pi): +Z is u = 1/4 (a), -Z is u = 3/4 (b); up and down alike.
    const Vec3 o(0.0f);
    for (float y : {-0.5f, 0.0f, 0.6f}) {
        expectColorNear(traceOne(doc, Ray::make(o, glm::normalize(Vec3(0.3f, y, 1)))), 2.0f * a,
                        1e-4f, "toward +Z, y = " + std::to_string(y));
        expectColorNear(traceOne(doc, Ray::make(o, glm::normalize(Vec3(-0.3f, y, -1)))), 2.0f * b,
                        1e-4f, "toward -Z, y = " + std::to_string(y));
    }
    // Turned 180 degrees about +Y: what the image shows at +Z is seen toward -Z.
    doc.environment.rotation = 180.0f;
    expectColorNear(traceOne(doc, Ray::make(o, Vec3(0, 0, 1))), 2.0f * b, 1e-4f, "+Z turned");
    expectColorNear(traceOne(doc, Ray::make(o, Vec3(0, 0, -1))), 2.0f * a, 1e-4f, "-Z turned");
    // Without it, the background.
    doc.environment = Environment{};
    expectColorNear(traceOne(doc, Ray::make(o, Vec3(0, 0, 1))), Color(0.3f), 0.0f, "none");
}

TEST_F(PatternsTest, MirrorReflectsTheEnvironment) {
    const Color a(0.25f, 0.5f, 0.75f), b(0.75f, 0.125f, 0.5f);
    SceneDocument doc;
    doc.render.ambient = Color(0.5f);  // The mirror has no local part: ambient shows nowhere.
    doc.environment.image.file = twoColumns("sky.exr", a, b);
    doc.environment.intensity = 0.5f;
    addMaterial(doc, "mirror", Color(1.0f), 1.0f, 0.0f, 1.0f);
    addPlane(doc, "floor", Vec3(0), Vec3(0, 1, 0), "mirror");
    // Down at 45 degrees toward -Z: reflected up toward -Z (u = 3/4, b); toward +Z: a.
    const Ray towardMinusZ = Ray::make(Vec3(0, 1, 0), glm::normalize(Vec3(0, -1, -1)));
    const Ray towardPlusZ = Ray::make(Vec3(0, 1, 0), glm::normalize(Vec3(0, -1, 1)));
    expectColorNear(traceOne(doc, towardMinusZ), 0.5f * b, 1e-4f, "toward -Z");
    expectColorNear(traceOne(doc, towardPlusZ), 0.5f * a, 1e-4f, "toward +Z");
}

TEST_F(PatternsTest, MissingEnvironmentIsAProblem_AndRendersTheMissingPattern) {
    SceneDocument doc;
    doc.render.background = Color(0.3f);
    doc.environment.image.file = (dir_ / "no-sky.hdr").string();
    const CompiledScene scene(doc);
    ASSERT_EQ(scene.problems().size(), 1u);
    EXPECT_EQ(scene.problems()[0].rfind("/environment/file: ", 0), 0u) << scene.problems()[0];
    EXPECT_NE(scene.problems()[0].find("no-sky.hdr"), std::string::npos);
    int magenta = 0, black = 0;
    for (int i = 0; i <= 40; ++i) {
        const float x = -1.0f + 0.05f * float(i);
        const Color c = traceOne(doc, Ray::make(Vec3(0), glm::normalize(Vec3(x, 0.1f, 1))));
        magenta += c == Color(1, 0, 1);
        black += c == Color(0);
    }
    EXPECT_EQ(magenta + black, 41);  // Never the background, never a crash.
    EXPECT_GT(magenta, 0);
    EXPECT_GT(black, 0);
}

// --- Through the interactive session -------------------------------------------------------

TEST_F(PatternsTest, DraggedCheckeredBallUnderTheSkyEndsAsAFullRender) {
    // The session refits the snapshot as the ball moves: its checker must move with it, and
    // what escapes must stay the sky, as a render from scratch of the final document says.
    SceneDocument doc = test::smallRoom(64, 48);
    doc.environment.image.file =
        twoColumns("sky.exr", Color(0.25f, 0.5f, 0.75f), Color(0.75f, 0.125f, 0.5f));
    doc.environment.rotation = 30.0f;
    for (Material& m : doc.materials)
        if (m.reflectivity == 0.0f && m.transparency == 0.0f)
            m.pattern = CheckerPattern{m.color, Color(0.1f, 0.2f, 0.9f), 0.3f};
    addChecker(doc, "ball checker", Color(0.9f, 0.8f, 0.1f), Color(0.8f, 0.1f, 0.1f), 0.2f);
    const ObjectId ball = addSphere(doc, "ball", Vec3(-0.8f, -1.2f, -3.5f), 0.5f, "ball checker");
    SceneDocument noSky = doc;
    noSky.environment = Environment{};
    ASSERT_NE(renderImage(CompiledScene(doc)).image.pixels,
              renderImage(CompiledScene(noSky)).image.pixels)
        << "the camera sees the sky";
    RenderSession session(2);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(std::chrono::seconds(60)));
    EXPECT_LE(test::maxDiffToFullRender(session, doc), 1e-5f) << "before the drag";
    session.beginInteraction(ball);
    for (int step = 1; step <= 4; ++step) {
        doc.findObject(ball)->transform.translate = Vec3(0.13f * float(step), 0.05f, 0.0f);
        session.update(doc);
    }
    session.endInteraction();
    ASSERT_TRUE(session.waitUntilComplete(std::chrono::seconds(60)));
    EXPECT_LE(test::maxDiffToFullRender(session, doc), 1e-5f) << "after the drag";
}

}  // namespace
}  // namespace rs
