// libFuzzer target for the scene reader: any text parses to a document or to errors, never a
// crash; a document that parses survives save and reparse unchanged (parse -> save -> reparse).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/scene_io.h"

namespace {
/// Relative mesh paths resolve against scenes/, as in its example scenes (meshes/torus.obj).
const std::string kSceneDir = RAYSTUDIO_FUZZ_SCENE_DIR;

[[noreturn]] void disagree(const std::string& what, const std::string& text) {
    std::fprintf(stderr, "scene_reader_fuzz: %s\n--- saved text ---\n%s\n", what.c_str(),
                 text.c_str());
    std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const rs::SceneLoadResult first = rs::parseScene(text, kSceneDir, "fuzz.scene.json");
    if (!first.ok()) return 0;
    const std::string saved = rs::serializeScene(first.document, kSceneDir);
    const rs::SceneLoadResult second = rs::parseScene(saved, kSceneDir, "saved.scene.json");
    if (!second.ok()) disagree("the saved document does not parse: " + second.errorText(), saved);
    if (!second.document.sameContent(first.document))
        disagree("the reparsed document differs from the parsed one", saved);
    // Saving is a fixed point: the second save writes the same text as the first.
    if (rs::serializeScene(second.document, kSceneDir) != saved)
        disagree("saving the reparsed document writes different text", saved);
    return 0;
}
