// scenes/FORMAT.md, the scene format's contract, against the scene reader and writer: every
// example in it loads (or, when marked invalid, fails with exactly the errors it shows), the
// examples cover every kind of object, light and material and every key of the format, and
// each survives a save and a load.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "io/scene_io.h"

namespace rs {
namespace {

const std::string kScenesDir = RAYSTUDIO_SCENES_DIR;
const std::string kFormatDoc = kScenesDir + "/FORMAT.md";

/// One fenced block of the document: its language tag, its text and the line it starts on.
struct Block {
    std::string language;
    std::string text;
    int line = 0;
};

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

/// The fenced blocks of a Markdown text, in order. A fence is a line starting with ```,
/// the opening one followed by the block's language.
std::vector<Block> fencedBlocks(const std::string& markdown) {
    std::vector<Block> blocks;
    std::istringstream in(markdown);
    std::string line;
    int number = 0;
    bool inside = false;
    Block current;
    while (std::getline(in, line)) {
        ++number;
        if (line.rfind("```", 0) != 0) {
            if (inside) current.text += line + "\n";
            continue;
        }
        if (inside) {
            blocks.push_back(current);
            inside = false;
        } else {
            current = Block{line.substr(3), "", number};
            inside = true;
        }
    }
    EXPECT_FALSE(inside) << "FORMAT.md: the block opened on line " << current.line
                         << " is never closed";
    return blocks;
}

/// Where an example is, for failure messages.
std::string where(const Block& b) {
    return "FORMAT.md:" + std::to_string(b.line) + " (```" + b.language + ")";
}

/// Loads a valid example as if the reader read FORMAT.md itself: the example's text on its
/// own lines, so an error's line:column points into the document.
SceneLoadResult loadInPlace(const Block& b) {
    return parseScene(std::string(std::size_t(b.line), '\n') + b.text, kScenesDir, "FORMAT.md");
}

class FormatDoc : public ::testing::Test {
protected:
    void SetUp() override {
        const std::string text = readFile(kFormatDoc);
        ASSERT_FALSE(text.empty()) << "cannot read " << kFormatDoc;
        blocks_ = fencedBlocks(text);
        for (std::size_t i = 0; i < blocks_.size(); ++i) {
            if (blocks_[i].language == "json") valid_.push_back(blocks_[i]);
            if (blocks_[i].language == "json-saved")
                saved_.push_back({i > 0 ? blocks_[i - 1] : Block{}, blocks_[i]});
            if (blocks_[i].language != "json-invalid") continue;
            Invalid bad{blocks_[i], {}};
            if (i + 1 < blocks_.size() && blocks_[i + 1].language == "stderr")
                bad.expected = blocks_[i + 1].text;
            invalid_.push_back(bad);
        }
    }

    /// The document an example holds; fails the test (and returns an empty one) if it
    /// does not load.
    SceneDocument load(const Block& b) const {
        SceneLoadResult r = loadInPlace(b);
        EXPECT_TRUE(r.ok()) << where(b) << " does not load:\n" << r.errorText();
        return r.document;
    }

    struct Invalid {
        Block example;
        std::string expected;  ///< The `stderr` block after it; empty when there is none.
    };
    /// A `json-saved` block: what the program writes for the `json` block before it.
    struct Saved {
        Block example;
        Block written;
    };
    std::vector<Block> blocks_, valid_;
    std::vector<Invalid> invalid_;
    std::vector<Saved> saved_;
};

TEST_F(FormatDoc, HasExamplesOfBothKindsAndNoUnknownFences) {
    // A misspelt fence (```jsn) would silently take an example out of this test.
    const std::set<std::string> known = {"json",       "json-invalid", "stderr",
                                         "json-saved", "text",         "sh"};
    for (const Block& b : blocks_)
        EXPECT_TRUE(known.count(b.language)) << where(b) << ": unknown fence language";
    EXPECT_GE(valid_.size(), 8u);
    EXPECT_GE(invalid_.size(), 5u);
    for (const Invalid& bad : invalid_)
        EXPECT_FALSE(bad.expected.empty())
            << where(bad.example) << " is not followed by a ```stderr block of its errors";
    EXPECT_GE(saved_.size(), 1u);
    for (const Saved& s : saved_)
        EXPECT_EQ(s.example.language, "json")
            << where(s.written) << " does not follow the ```json example it was saved from";
}

TEST_F(FormatDoc, EveryExampleLoads) {
    for (const Block& b : valid_) {
        SceneLoadResult r = loadInPlace(b);
        EXPECT_TRUE(r.ok()) << where(b) << " does not load:\n" << r.errorText();
    }
}

TEST_F(FormatDoc, EveryInvalidExampleFailsWithTheErrorsItShows) {
    for (const Invalid& bad : invalid_) {
        // As `raystudio-cli validate bad.scene.json` reports it: the file name is the path given.
        SceneLoadResult r = parseScene(bad.example.text, kScenesDir, "bad.scene.json");
        EXPECT_FALSE(r.ok()) << where(bad.example) << " loads, but is shown as invalid";
        EXPECT_EQ(r.errorText(), bad.expected) << where(bad.example);
    }
}

TEST_F(FormatDoc, ExamplesShowEveryKindOfObjectLightAndMaterial) {
    std::set<std::string> objects, lights, materials, places;
    bool orthographic = false, perspective = false, numberScale = false, vectorScale = false;
    bool hidden = false, sharpMesh = false;
    for (const Block& b : valid_) {
        const SceneDocument doc = load(b);
        (doc.camera.projection == Projection::Orthographic ? orthographic : perspective) = true;
        for (const Material& m : doc.materials) {
            // Kinds by the illumination equation's terms, decided here, not by the product.
            if (m.transparency > 0.0f) materials.insert("glass");
            if (m.reflectivity > 0.0f) materials.insert("mirror");
            if (m.reflectivity == 0.0f && m.transparency == 0.0f && m.diffuse > 0.0f)
                materials.insert(m.specular > 0.0f ? "phong" : "diffuse");
            if (std::holds_alternative<CheckerPattern>(m.pattern)) materials.insert("checker");
            if (std::holds_alternative<ImageTexture>(m.pattern)) materials.insert("image");
            if (!m.extras.empty()) places.insert("material");
        }
        for (const Light& l : doc.lights) {
            static const char* const types[] = {"point", "sphere", "directional", "spot"};
            lights.insert(types[int(l.type)]);
            if (!l.extras.empty()) places.insert("light");
        }
        for (const Object& o : doc.objects) {
            const Geometry& g = o.geometry;
            if (std::holds_alternative<SphereGeometry>(g)) objects.insert("sphere");
            if (std::holds_alternative<PlaneGeometry>(g)) objects.insert("plane");
            if (std::holds_alternative<RectangleGeometry>(g)) objects.insert("rectangle");
            if (std::holds_alternative<BoxGeometry>(g)) objects.insert("box");
            if (const auto* mesh = std::get_if<MeshGeometry>(&g)) {
                objects.insert("mesh");
                EXPECT_TRUE(mesh->data && mesh->data->triangleCount() > 0) << where(b);
                sharpMesh = sharpMesh || !mesh->smoothNormals;
            }
            if (o.transform.scale != Vec3(1.0f))
                (o.transform.scaleWrittenAsNumber ? numberScale : vectorScale) = true;
            hidden = hidden || !o.visible;
            if (!o.extras.empty()) places.insert("object");
        }
        if (!doc.extras.empty()) places.insert("top level");
        if (!doc.camera.extras.empty()) places.insert("camera");
        if (!doc.render.extras.empty()) places.insert("render");
    }
    using Names = std::set<std::string>;
    EXPECT_EQ(objects, (Names{"sphere", "plane", "rectangle", "box", "mesh"}));
    EXPECT_EQ(lights, (Names{"point", "sphere", "directional", "spot"}));
    EXPECT_EQ(materials, (Names{"diffuse", "phong", "mirror", "glass", "checker", "image"}));
    EXPECT_EQ(places, (Names{"top level", "camera", "render", "material", "light", "object"}))
        << "x- keys";
    EXPECT_TRUE(orthographic && perspective);
    EXPECT_TRUE(numberScale) << "no example writes scale as a number";
    EXPECT_TRUE(vectorScale) << "no example writes scale as [x, y, z]";
    EXPECT_TRUE(hidden) << "no example has \"visible\": false";
    EXPECT_TRUE(sharpMesh) << "no example has \"smooth_normals\": false";
}

TEST_F(FormatDoc, ExamplesUseEveryKeyOfTheFormat) {
    // The format's keys, written out here from the document (not taken from the reader).
    using Keys = std::set<std::string>;
    const std::map<std::string, Keys> format = {
        {"top level",
         {"format", "version", "camera", "render", "environment", "materials", "lights",
          "objects"}},
        {"environment", {"file", "intensity", "rotation"}},
        {"checker colour", {"checker", "scale"}},
        {"texture colour", {"texture", "scale", "offset"}},
        {"camera", {"projection", "position", "target", "up", "fov_y", "ortho_height"}},
        {"render",
         {"width", "height", "max_depth", "min_weight", "shadow_samples", "supersampling",
          "adaptive_supersampling", "tonemap", "exposure", "background", "ambient",
          "opaque_shadows"}},
        {"material",
         {"name", "color", "diffuse", "specular", "shininess", "reflectivity", "transparency",
          "ior"}},
        {"light",
         {"name", "type", "position", "radius", "color", "intensity", "direction", "target",
          "falloff"}},
        {"object", {"name", "type", "material", "visible", "translate", "rotate", "scale"}},
        {"sphere", {"center", "radius"}},
        {"plane", {"point", "normal"}},
        {"rectangle", {"center", "u", "v"}},
        {"box", {"min", "max"}},
        {"mesh", {"file", "smooth_normals", "part_materials"}},
    };
    std::map<std::string, Keys> seen;
    Keys tonemaps;
    auto note = [&](const std::string& section, const nlohmann::json& j) {
        for (auto it = j.begin(); it != j.end(); ++it)
            if (it.key().rfind("x-", 0) != 0) seen[section].insert(it.key());
    };
    for (const Block& b : valid_) {
        const nlohmann::json j = nlohmann::json::parse(b.text, nullptr, false);
        ASSERT_TRUE(j.is_object()) << where(b);
        note("top level", j);
        if (j.contains("camera")) note("camera", j["camera"]);
        if (j.contains("render")) {
            note("render", j["render"]);
            if (j["render"].contains("tonemap"))
                tonemaps.insert(j["render"]["tonemap"].get<std::string>());
        }
        if (j.contains("environment")) note("environment", j["environment"]);
        for (const auto& m : j.value("materials", nlohmann::json::array())) {
            note("material", m);
            const nlohmann::json color = m.value("color", nlohmann::json());
            if (color.is_object())
                note(color.contains("checker") ? "checker colour" : "texture colour", color);
        }
        for (const auto& l : j.value("lights", nlohmann::json::array())) note("light", l);
        for (const auto& o : j.value("objects", nlohmann::json::array())) {
            note("object", o);
            note(o.at("type").get<std::string>(), o);
        }
    }
    for (const auto& [section, keys] : format) {
        Keys missing;
        std::set_difference(keys.begin(), keys.end(), seen[section].begin(), seen[section].end(),
                            std::inserter(missing, missing.begin()));
        EXPECT_TRUE(missing.empty())
            << section << ": no example uses " << nlohmann::json(missing).dump();
    }
    EXPECT_EQ(tonemaps, (Keys{"clamp", "linear", "reinhard", "aces"}));
}

TEST_F(FormatDoc, ExamplesComeBackTheSameAfterSaveAndLoad) {
    for (const Block& b : valid_) {
        const SceneDocument doc = load(b);
        const std::string saved = serializeScene(doc, kScenesDir);
        SceneLoadResult again = parseScene(saved, kScenesDir, where(b) + ", saved");
        ASSERT_TRUE(again.ok()) << again.errorText() << saved;
        EXPECT_TRUE(again.document.sameContent(doc)) << where(b) << " saved as\n" << saved;
        // Saving what was loaded from a save writes the same text.
        EXPECT_EQ(serializeScene(again.document, kScenesDir), saved) << where(b);

        // What the document's equality does not see: x- values, a number scale, mesh paths.
        const nlohmann::json source = nlohmann::json::parse(b.text);
        const nlohmann::json written = nlohmann::json::parse(saved);
        for (auto it = source.begin(); it != source.end(); ++it) {
            if (it.key().rfind("x-", 0) == 0) {
                EXPECT_EQ(written.value(it.key(), nlohmann::json()), it.value()) << where(b);
            }
        }
        const auto objects = source.value("objects", nlohmann::json::array());
        ASSERT_EQ(written.at("objects").size(), objects.size()) << where(b);
        for (std::size_t i = 0; i < objects.size(); ++i) {
            const nlohmann::json& in = objects[i];
            const nlohmann::json& out = written["objects"][i];
            for (auto it = in.begin(); it != in.end(); ++it) {
                if (it.key().rfind("x-", 0) == 0) {
                    EXPECT_EQ(out.value(it.key(), nlohmann::json()), it.value()) << where(b);
                }
            }
            if (in.contains("scale") && in["scale"].is_number() && in["scale"] != 1) {
                EXPECT_EQ(out.value("scale", nlohmann::json()), in["scale"]) << where(b);
            }
            if (in.contains("file")) {  // below the scenes' folder: relative, spelt plainly
                const std::filesystem::path file = in["file"].get<std::string>();
                EXPECT_EQ(out.value("file", ""), file.lexically_normal().generic_string())
                    << where(b);
            }
        }
    }
}

TEST_F(FormatDoc, TheWriterWritesWhatTheDocumentShows) {
    // Compared as JSON with key order (ordered_json): which keys are written, in which order,
    // with which values; the spacing of the page is its own.
    using Ordered = nlohmann::ordered_json;
    for (const Saved& s : saved_) {
        const SceneDocument doc = load(s.example);
        const std::string text = serializeScene(doc, kScenesDir);
        const Ordered shown = Ordered::parse(s.written.text, nullptr, false);
        ASSERT_FALSE(shown.is_discarded()) << where(s.written) << " is not JSON";
        EXPECT_EQ(Ordered::parse(text), shown) << where(s.written) << "; the program writes\n"
                                               << text;
        // What is shown as written is itself a scene that loads into the same document.
        SceneLoadResult again = loadInPlace(s.written);
        EXPECT_TRUE(again.ok()) << again.errorText();
        EXPECT_TRUE(again.document.sameContent(doc)) << where(s.written);
    }
}

}  // namespace
}  // namespace rs
