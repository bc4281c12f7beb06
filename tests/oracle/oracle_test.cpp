// The POV-Ray oracle: every bundled scene and one small scene per illumination term, rendered
// by POV-Ray 3.7 from the twin tests/oracle/scene_to_pov.py writes, and by us, compared pixel
// by pixel. Unlike tests/image (our own references, bit-level regressions) the reference here
// comes from an independent renderer, so a term that is wrong in both the code and our own
// references fails here.
//
// The comparison, per scene, on linear colour (POV-Ray writes half-float EXR, ~5e-4 relative):
// - mean |ours - POV-Ray| over pixels and channels <= mean bound;
// - every pixel (no free pixels) within `pixel` of the range POV-Ray's 3x3 neighbourhood of it
//   spans, per channel: a shadow terminator or a refracted edge may fall on the neighbouring
//   pixel, because our ray origins are offset from the surface along the normal and POV-Ray's
//   are not (and it intersects in double precision), but no value may appear that POV-Ray
//   shows nowhere near;
// - at most `edgePixels` pixels differ from POV-Ray's own pixel by more than `pixel`: the
//   pixels that need the neighbourhood, counted and bounded per scene.
// OracleTolerance below shows that these bounds fail for a wrong term.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "image/image_io.h"
#include "integrator/renderer.h"
#include "io/scene_io.h"

namespace rs {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 160;
constexpr int kHeight = 90;

struct OracleCase {
    std::string name;   ///< test name
    std::string scene;  ///< path of the scene file
    double mean;        ///< bound on the mean absolute difference
    float pixel;        ///< bound on every pixel's distance from POV-Ray's 3x3 range
    int edgePixels;     ///< pixels allowed to need that neighbourhood
    int shadowSamples;  ///< override of render.shadow_samples for both renderers; -1: none
    std::string why;    ///< what the bounds allow for
    /// Camera samples a pixel for both (a perfect square). Above 1, POV-Ray renders at
    /// sqrt(samples) times the size, one ray through each centre, and its pixels are averaged
    /// in blocks: the centres of our regular sub-grid exactly.
    int samples = 1;
};

std::string feature(const char* name) {
    return std::string(RAYSTUDIO_ORACLE_DIR "/scenes/") + name + ".scene.json";
}
std::string bundled(const char* name) {
    return std::string(RAYSTUDIO_SCENES_DIR "/") + name + ".scene.json";
}

constexpr double kV2Mean = 3.0 / 255.0;
constexpr float kV2Pixel = 0.35f;
constexpr int kV2Edges = 400;

// Half-float rounding of POV-Ray's output is below 1e-3 for values up to 2; 0.01 is 2.5 steps
// of an 8-bit display value. The edge counts are the measured ones plus a small margin.
const std::vector<OracleCase>& cases() {
    static const std::vector<OracleCase> all = {
        {"ambient", feature("ambient"), 2e-4, 0.01f, 0, -1, "ambient only: exact"},
        {"lambert", feature("lambert"), 2e-4, 0.01f, 0, -1, "Lambert, no shadows: exact"},
        {"phong", feature("phong"), 2e-4, 0.01f, 0, -1, "Phong n = 10, 60, 300: exact"},
        {"mirror", feature("mirror"), 3e-4, 0.01f, 10, -1,
         "reflected shadow edges move with the surface offset"},
        {"glass", feature("glass"), 4e-4, 0.07f, 12, -1,
         "Schlick split, refraction through ball and slab, total internal reflection: rays "
         "refracted up to 6 times magnify the offset, so an edge seen through glass may move "
         "by more than a pixel (measured: 6 pixels beyond 0.07, worst 0.059 off POV-Ray's 3x3 "
         "range)"},
        {"hard_shadow", feature("hard-shadow"), 3e-4, 0.01f, 10, -1,
         "shadow terminators move by the surface offset (about 2 % of edge pixels)"},
        {"soft_shadow", feature("soft-shadow"), 5e-3, 0.04f, 10, 256,
         "256 jittered samples against POV-Ray's 16 x 16 grid: visibility noise ~ 1/16 of the "
         "light in the penumbra; POV-Ray takes N.L at the light's centre, ours per sample"},
        {"ortho", feature("ortho"), 2e-4, 0.01f, 2, -1, "orthographic camera"},
        {"boxes", feature("boxes"), 2e-4, 0.01f, 4, -1, "rotated, scaled boxes, an ellipsoid"},
        {"rectangles", feature("rectangles"), 2e-4, 0.01f, 4, -1, "rectangles, one a mirror"},
        {"mesh", feature("mesh"), 3e-4, 0.01f, 12, -1,
         "smooth and flat torus: shadow terminators on a faceted surface"},
        {"reference_room", bundled("reference-room"), 5e-4, 0.08f, 20, -1,
         "edges seen through the glass ball move by more than a pixel, shadow edges by one "
         "(measured: 10 pixels beyond 0.08, worst 0.066)"},
        {"glass_and_mirrors", bundled("glass-and-mirrors"), 1.2e-3, 0.17f, 24, -1,
         "three glass balls (ior 1.33, 1.5, 2.42) at depth 5: edges seen through two of them "
         "and a mirror, and shadows filtered through the glass (measured: mean 1.1e-3, 21 "
         "pixels beyond 0.17, worst 0.153)"},
        {"mesh_scene", bundled("mesh"), 4e-4, 0.07f, 30, -1,
         "smooth-normal torus: POV-Ray and we pick different sides of a shadow terminator on "
         "single pixels where shading and geometric normals disagree (measured: 20 pixels beyond "
         "0.07, worst 0.059)"},
        {"soft_shadows", bundled("soft-shadows"), 5e-3, 0.04f, 20, 256,
         "as soft_shadow; the bundled scene's 16 samples raised to 256 for both"},
        // Format version 2, at 16 samples a pixel: a mean of 3/255 on linear values. Our checker
        // and textures are filtered by the ray's footprint, POV-Ray's point-sampled: they
        // differ where cells are smaller than a sample (the far floor).
        {"classic", bundled("classic"), kV2Mean, kV2Pixel, kV2Edges, -1,
         "sky, checker floor, glass and mirror balls, sun light, filtered shadows", 16},
        {"classic_spot", feature("classic-spot"), kV2Mean, kV2Pixel, kV2Edges, -1,
         "spot light (tightness 0), tinted glass's filtered shadow, turned sky", 16},
        {"classic_sun", feature("classic-sun"), kV2Mean, kV2Pixel, kV2Edges, -1,
         "low sun, brighter turned sky, checker of 0.75 on a floor, moved mirror ball", 16},
        {"classic_opaque", feature("classic-opaque"), kV2Mean, kV2Pixel, kV2Edges, -1,
         "render.opaque_shadows: the glass casts version 1's black shadow", 16},
        {"textures", feature("textures"), kV2Mean, kV2Pixel, kV2Edges, -1,
         "an sRGB PNG through sphere, rectangle and plane UVs, scaled and offset", 16},
    };
    return all;
}

struct Comparison {
    double mean = 0.0;
    float worstEnvelope = 0.0f;  ///< largest distance from POV-Ray's 3x3 range
    float worstDirect = 0.0f;
    int beyondDirect = 0;  ///< pixels farther than the bound from POV-Ray's own pixel
    int worstX = -1, worstY = -1;
};

Comparison compare(const ImageRgb& ours, const ImageRgb& pov, float bound) {
    Comparison c;
    double sum = 0.0;
    for (int y = 0; y < ours.height; ++y)
        for (int x = 0; x < ours.width; ++x) {
            const Color o = ours.at(x, y);
            const Color p = pov.at(x, y);
            Color lo = p, hi = p;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = std::clamp(x + dx, 0, ours.width - 1);
                    const int ny = std::clamp(y + dy, 0, ours.height - 1);
                    lo = glm::min(lo, pov.at(nx, ny));
                    hi = glm::max(hi, pov.at(nx, ny));
                }
            const Color d = glm::abs(o - p);
            sum += double(d.x + d.y + d.z) / 3.0;
            const float direct = std::max({d.x, d.y, d.z});
            const Color out = glm::max(lo - o, o - hi);
            const float envelope = std::max({out.x, out.y, out.z, 0.0f});
            if (direct > bound) ++c.beyondDirect;
            c.worstDirect = std::max(c.worstDirect, direct);
            if (envelope > c.worstEnvelope) {
                c.worstEnvelope = envelope;
                c.worstX = x;
                c.worstY = y;
            }
        }
    c.mean = sum / (double(ours.width) * double(ours.height));
    return c;
}

std::string shellQuoted(const fs::path& p) {
    return "'" + p.string() + "'";
}

/// POV-Ray's render of `scenePath`'s twin, or an error message.
bool renderPovray(const OracleCase& c, ImageRgb& image, std::string& error) {
    int n = 1;
    while ((n + 1) * (n + 1) <= c.samples) ++n;
    const int width = kWidth * n, height = kHeight * n;
    const fs::path work = fs::path(RAYSTUDIO_ORACLE_WORK) / c.name;
    fs::create_directories(work);
    const fs::path pov = work / "twin.pov", exr = work / "povray.exr", log = work / "povray.log";
    std::string convert = "'" RAYSTUDIO_PYTHON "' '" RAYSTUDIO_ORACLE_DIR "/scene_to_pov.py' " +
                          shellQuoted(c.scene) + " " + shellQuoted(pov) + " --width " +
                          std::to_string(kWidth) + " --height " + std::to_string(kHeight);
    if (c.shadowSamples >= 0) convert += " --shadow-samples " + std::to_string(c.shadowSamples);
    if (std::system((convert + " 2>" + shellQuoted(log)).c_str()) != 0) {
        error = "scene_to_pov.py failed: " + convert;
    } else {
        fs::remove(exr);
        const std::string render = "'" RAYSTUDIO_POVRAY "' +W" + std::to_string(width) + " +H" +
                                   std::to_string(height) + " -D -A +WT1 +FE +O" +
                                   shellQuoted(exr) + " " + shellQuoted(pov) + " >" +
                                   shellQuoted(log) + " 2>&1";
        if (std::system(render.c_str()) != 0) error = "povray failed: " + render;
    }
    if (!error.empty()) {
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        error += "\n" + text.str();
        return false;
    }
    ImageRgb full;
    if (!readImage(exr.string(), full, error)) return false;
    if (n == 1) {
        image = full;
        return true;
    }
    if (full.width != width || full.height != height) {
        error = "POV-Ray's image is " + std::to_string(full.width) + "x" +
                std::to_string(full.height) + ", not " + std::to_string(width) + "x" +
                std::to_string(height);
        return false;
    }
    image = ImageRgb(kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            Color sum(0.0f);
            for (int dy = 0; dy < n; ++dy)
                for (int dx = 0; dx < n; ++dx) sum += full.at(x * n + dx, y * n + dy);
            image.at(x, y) = sum / float(n * n);
        }
    return true;
}

/// Mean and standard deviation of a picture's luminance (Rec. 709 weights).
std::pair<double, double> lumaStats(const ImageRgb& image) {
    double sum = 0.0, squares = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Color c = image.at(x, y);
            const double l = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
            sum += l;
            squares += l * l;
        }
    const double count = double(image.width) * double(image.height);
    const double mean = sum / count;
    return {mean, std::sqrt(std::max(0.0, squares / count - mean * mean))};
}

/// Mean |a - b| over the rows [y0, y1) and all channels.
double meanDifference(const ImageRgb& a, const ImageRgb& b, int y0, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < a.width; ++x) {
            const Color d = glm::abs(a.at(x, y) - b.at(x, y));
            sum += double(d.x + d.y + d.z) / 3.0;
        }
    return sum / (double(a.width) * double(y1 - y0));
}

SceneDocument oracleDocument(const OracleCase& c) {
    SceneLoadResult loaded = loadScene(c.scene);
    EXPECT_TRUE(loaded.ok()) << loaded.errorText();
    SceneDocument doc = loaded.document;
    doc.render.width = kWidth;
    doc.render.height = kHeight;
    doc.render.supersampling = c.samples;  // POV-Ray: -A, one ray through each (sub)centre
    doc.render.adaptiveSupersampling = false;
    if (c.shadowSamples >= 0) doc.render.shadowSamples = c.shadowSamples;
    return doc;
}

const OracleCase& findCase(const std::string& name) {
    for (const OracleCase& c : cases())
        if (c.name == name) return c;
    throw std::runtime_error("no oracle case " + name);
}

void PrintTo(const OracleCase& c, std::ostream* os) {
    *os << c.name;
}

class Oracle : public ::testing::TestWithParam<OracleCase> {};

TEST_P(Oracle, MatchesPovray) {
    const OracleCase& c = GetParam();
    ImageRgb pov;
    std::string error;
    ASSERT_TRUE(renderPovray(c, pov, error)) << error;
    ASSERT_EQ(pov.width, kWidth);
    ASSERT_EQ(pov.height, kHeight);
    if (c.samples > 1) {
        // Not trivially black, blown out or uniform: a twin that lost its objects, its lights
        // or its sky must not pass by agreeing on nothing.
        const auto [mean, spread] = lumaStats(pov);
        EXPECT_GE(mean, 0.05) << c.name << ": POV-Ray's picture is nearly black";
        EXPECT_LE(mean, 2.0) << c.name << ": POV-Ray's picture is blown out";
        EXPECT_GE(spread, 0.05) << c.name << ": POV-Ray's picture is nearly uniform";
    }
    const SceneDocument doc = oracleDocument(c);
    for (const EngineKind engine : {EngineKind::Embree, EngineKind::Builtin}) {
        RenderOptions options;
        const ImageRgb ours = renderImage(CompiledScene(doc, nullptr, engine), options).image;
        if (c.samples > 1) {
            const auto [mean, spread] = lumaStats(ours);
            EXPECT_GE(mean, 0.05) << c.name << ": our picture is nearly black";
            EXPECT_LE(mean, 2.0) << c.name << ": our picture is blown out";
            EXPECT_GE(spread, 0.05) << c.name << ": our picture is nearly uniform";
        }
        const Comparison d = compare(ours, pov, c.pixel);
        // Kept next to POV-Ray's render for a look at a failure (oiiotool --diff).
        const fs::path mine = fs::path(RAYSTUDIO_ORACLE_WORK) / c.name /
                              (std::string("ours-") + engineName(engine) + ".exr");
        std::string ignored;
        writeImage(mine.string(), ours, ToneMap::Clamp, 0.0f, ignored);
        const std::string where = c.name + " (" + engineName(engine) + "): " + c.why;
        RecordProperty(c.name + "_" + engineName(engine) + "_mean", std::to_string(d.mean));
        EXPECT_LE(d.mean, c.mean) << where;
        EXPECT_LE(d.worstEnvelope, c.pixel)
            << where << "; worst pixel (" << d.worstX << ", " << d.worstY << ")";
        EXPECT_LE(d.beyondDirect, c.edgePixels) << where;
        std::cout << "[oracle] " << c.name << " " << engineName(engine) << ": mean " << d.mean
                  << ", worst envelope " << d.worstEnvelope << ", worst direct " << d.worstDirect
                  << ", pixels beyond " << c.pixel << ": " << d.beyondDirect << "\n";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, Oracle, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

/// True when `doc` rendered by us passes case `c`'s bounds against POV-Ray's unchanged twin.
bool passes(const OracleCase& c, const SceneDocument& doc) {
    // POV-Ray's files go to a folder of this test's own: ctest -j runs the Scenes case of the
    // same name at the same time, and reading its half-written EXR crashed the reader.
    OracleCase own = c;
    own.name += "-tolerance";
    ImageRgb pov;
    std::string error;
    EXPECT_TRUE(renderPovray(own, pov, error)) << error;
    const Comparison d = compare(renderImage(CompiledScene(doc)).image, pov, c.pixel);
    return d.mean <= c.mean && d.worstEnvelope <= c.pixel && d.beyondDirect <= c.edgePixels;
}

Material& material(SceneDocument& doc, const std::string& name) {
    for (Material& m : doc.materials)
        if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
}

// The bounds are tight enough to catch each term gone slightly wrong.
TEST(OracleTolerance, SlightlyWrongTerms_Fail) {
    {
        const OracleCase& c = findCase("lambert");
        SceneDocument doc = oracleDocument(c);
        EXPECT_TRUE(passes(c, doc));
        doc.lights[0].intensity *= 1.03f;  // 3 % too bright
        EXPECT_FALSE(passes(c, doc)) << "a 3 % brighter light passes";
    }
    {
        const OracleCase& c = findCase("ambient");
        SceneDocument doc = oracleDocument(c);
        doc.render.ambient *= 1.05f;
        EXPECT_FALSE(passes(c, doc)) << "5 % more ambient passes";
    }
    {
        const OracleCase& c = findCase("phong");
        SceneDocument doc = oracleDocument(c);
        material(doc, "p60").shininess = 50.0f;
        EXPECT_FALSE(passes(c, doc)) << "Phong exponent 50 for 60 passes";
    }
    {
        const OracleCase& c = findCase("mirror");
        SceneDocument doc = oracleDocument(c);
        material(doc, "mirror").reflectivity = 0.87f;
        EXPECT_FALSE(passes(c, doc)) << "reflectivity 0.87 for 0.9 passes";
    }
    {
        const OracleCase& c = findCase("glass");
        SceneDocument doc = oracleDocument(c);
        material(doc, "glass").ior = 1.45f;
        EXPECT_FALSE(passes(c, doc)) << "ior 1.45 for 1.5 passes";
    }
    {
        const OracleCase& c = findCase("hard_shadow");
        SceneDocument doc = oracleDocument(c);
        doc.objects.eraseIf([](const Object& o) { return o.name == "low ball"; });
        EXPECT_FALSE(passes(c, doc)) << "a missing small ball and its shadow pass";
    }
    {
        const OracleCase& c = findCase("reference_room");
        SceneDocument doc = oracleDocument(c);
        for (Object& o : doc.objects.editable())
            if (o.name == "chrome ball") o.material = "chalk";
        EXPECT_FALSE(passes(c, doc)) << "the chrome ball made matte passes";
    }
}

// The version-2 terms gone slightly wrong fail too.
TEST(OracleTolerance, SlightlyWrongVersion2Terms_Fail) {
    {
        const OracleCase& c = findCase("classic");
        SceneDocument doc = oracleDocument(c);
        EXPECT_TRUE(passes(c, doc));
        doc.environment.intensity = 1.15f;
        EXPECT_FALSE(passes(c, doc)) << "a 15 % brighter sky passes";
    }
    {
        const OracleCase& c = findCase("classic");
        SceneDocument doc = oracleDocument(c);
        std::get<CheckerPattern>(material(doc, "checker floor").pattern).scale = 0.9f;
        EXPECT_FALSE(passes(c, doc)) << "checker cells of 0.9 for 1 pass";
    }
    {
        const OracleCase& c = findCase("classic_opaque");
        SceneDocument doc = oracleDocument(c);
        doc.render.opaqueShadows = false;
        EXPECT_FALSE(passes(c, doc)) << "a filtered shadow for an opaque one passes";
    }
    {
        const OracleCase& c = findCase("classic_spot");
        SceneDocument doc = oracleDocument(c);
        doc.lights[0].coneFalloff = 34.0f;
        EXPECT_FALSE(passes(c, doc)) << "a spot falloff of 34 degrees for 30 passes";
    }
    {
        const OracleCase& c = findCase("textures");
        SceneDocument doc = oracleDocument(c);
        std::get<ImageTexture>(material(doc, "ball tiles").pattern).offsetU = 0.1f;
        EXPECT_FALSE(passes(c, doc)) << "a ball texture turned by a tenth passes";
    }
}

// The sky is seen: the classic scene's upper rows (above the horizon at 160 x 90) differ from
// the same scene without its environment, in our render and in POV-Ray's, by far more than the
// oracle's mean bound, so a renderer that ignores the environment fails here and in the
// classic case above.
TEST(OracleSky, ClassicSkyIsSeen) {
    const OracleCase& c = findCase("classic");
    OracleCase bare = c;
    bare.name = "classic-nosky";
    bare.scene = feature("classic-nosky");
    const SceneDocument with = oracleDocument(c);
    const SceneDocument without = oracleDocument(bare);
    ASSERT_TRUE(with.environment.present());
    ASSERT_FALSE(without.environment.present());
    const int rows = 15;  // the horizon is below row 20 of 90 at the classic camera
    const ImageRgb oursWith = renderImage(CompiledScene(with)).image;
    const ImageRgb oursWithout = renderImage(CompiledScene(without)).image;
    ImageRgb povWith, povWithout;
    std::string error;
    OracleCase own = c;
    own.name += "-sky";
    ASSERT_TRUE(renderPovray(own, povWith, error)) << error;
    ASSERT_TRUE(renderPovray(bare, povWithout, error)) << error;
    EXPECT_GE(meanDifference(povWith, povWithout, 0, rows), 0.1) << "POV-Ray's twin lost the sky";
    EXPECT_GE(meanDifference(oursWith, oursWithout, 0, rows), 0.1) << "our render lost the sky";
    EXPECT_LE(meanDifference(oursWith, povWith, 0, rows), kV2Mean) << "our sky is not POV-Ray's";
}

}  // namespace
}  // namespace rs
