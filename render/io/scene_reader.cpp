// Reading scene files: syntax, the top level, and the SceneError text forms.
#include <climits>
#include <filesystem>

#include "core/input_file.h"
#include "io/scene_io.h"
#include "io/scene_reader_sections.h"

namespace rs {

namespace {
// nlohmann prefixes its messages with "[json.exception.parse_error.101] parse error at line
// 1, column 5: "; we give the position ourselves, so keep only what follows.
std::string withoutNlohmannPrefix(const std::string& what) {
    std::size_t column = what.find("column ");
    std::size_t colon = column == std::string::npos ? what.find("] ") : what.find(": ", column);
    if (colon == std::string::npos) return what;
    return what.substr(colon + 2);
}

bool parseSyntax(const std::string& text, const std::string& fileName, Json& root,
                 std::vector<SceneError>& errors) {
    SceneError e;
    e.file = fileName;
    // nlohmann takes a NUL byte for the end of the input, so a scene followed by "\0junk"
    // would pass. JSON text never holds a raw NUL (in strings it must be escaped).
    if (std::size_t nul = text.find('\0'); nul != std::string::npos) {
        TextPosition pos = positionOfOffset(text, nul);
        e.line = pos.line;
        e.column = pos.column;
        e.message = "syntax error: NUL byte; a scene file is text, one JSON object";
        errors.push_back(std::move(e));
        return false;
    }
    try {
        root = Json::parse(text);
        return true;
    } catch (const Json::parse_error& ex) {
        // `byte` counts from 1 and names the character that could not be read.
        TextPosition pos = positionOfOffset(text, ex.byte > 0 ? ex.byte - 1 : 0);
        e.line = pos.line;
        e.column = pos.column;
        e.message = "syntax error: " + withoutNlohmannPrefix(ex.what());
    } catch (const Json::exception& ex) {  // e.g. a number too large for a double
        e.message = "syntax error: " + withoutNlohmannPrefix(ex.what());
    }
    errors.push_back(std::move(e));
    return false;
}

// Returns false when the text is not a scene of a version this program reads: then nothing
// else is checked, since a flood of "unknown key" errors would hide the one that matters.
bool readHeader(EntryReader& top, int& version) {
    std::string format;
    if (!top.string("format", format, Need::Required)) return false;
    if (format != "raystudio-scene") {
        top.sink().atValue("/format", "format must be \"raystudio-scene\", got \"" + format + "\"");
        return false;
    }
    if (!top.integer("version", version, INT_MIN, INT_MAX, Need::Required)) return false;
    if (version < 1 || version > kSceneFormatVersion) {
        top.sink().atValue("/version", "unsupported version " + std::to_string(version) +
                                           " (this program reads versions 1 and 2)");
        return false;
    }
    return true;
}

// A version 1 file must not use what version 2 added: an old build would refuse it.
void refuseVersion2Keys(SceneErrorSink& sink, const SceneDocument& doc) {
    for (const std::string& pointer : version2Uses(doc))
        sink.atValue(pointer, "needs format version 2 (the file says \"version\": 1)");
}
}  // namespace

std::string SceneError::toString() const {
    std::string out = file;
    if (line > 0) {
        // Appended piecewise: "literal" + std::string trips GCC 12's -Wrestrict false positive.
        if (!out.empty()) out += ':';
        out += std::to_string(line);
        if (column > 0) out.append(":").append(std::to_string(column));
    }
    if (!out.empty()) out += ": ";
    if (!pointer.empty()) out += pointer + ": ";
    return out + message;
}

std::string SceneLoadResult::errorText() const {
    std::string out;
    for (const SceneError& e : errors) out += e.toString() + "\n";
    return out;
}

std::string SceneLoadResult::warningText() const {
    std::string out;
    for (const SceneError& e : warnings) out += e.toString() + "\n";
    return out;
}

SceneLoadResult parseScene(const std::string& text, const std::string& baseDir,
                           const std::string& fileName) {
    SceneLoadResult result;
    Json root;
    if (!parseSyntax(text, fileName, root, result.errors)) return result;

    JsonLocator locator(text);
    SceneErrorSink sink(fileName, locator, result.errors);
    if (locator.tooDeep()) {
        sink.atValue(
            "", "nesting is deeper than " + std::to_string(JsonLocator::kMaxDepth) + " levels");
        return result;
    }
    // nlohmann keeps one of two equal keys silently; the format treats that as a typo.
    for (const JsonLocator::DuplicateKey& d : locator.duplicateKeys())
        sink.at(d.pointer, d.position,
                "duplicate key \"" + d.pointer.substr(d.pointer.rfind('/') + 1) + "\"");
    if (!expectObject(sink, root, "")) return result;

    EntryReader top(sink, root, "");
    SceneDocument& doc = result.document;
    int version = 0;
    if (readHeader(top, version)) {
        if (const Json* j = top.get("camera")) readCamera(sink, *j, "/camera", doc.camera);
        if (const Json* j = top.get("views")) readViews(sink, *j, doc);
        if (const Json* j = top.get("render")) readRenderSettings(sink, *j, doc.render);
        if (const Json* j = top.get("environment")) readEnvironment(sink, *j, doc.environment);
        if (const Json* j = top.get("materials")) readMaterials(sink, *j, doc);
        if (const Json* j = top.get("lights")) readLights(sink, *j, doc);
        if (const Json* j = top.get("objects")) readObjects(sink, *j, baseDir, doc);
        doc.extras = top.finish();
        if (version == 1) refuseVersion2Keys(sink, doc);
    }
    if (!result.ok()) {
        result.document = SceneDocument{};
        return result;
    }
    SceneErrorSink warnings(fileName, locator, result.warnings);
    checkImageFiles(warnings, baseDir, doc);
    return result;
}

SceneLoadResult loadScene(const std::string& path) {
    namespace fs = std::filesystem;
    auto fail = [&](const std::string& why) {
        SceneLoadResult result;
        result.errors.push_back(SceneError{path, "", 0, 0, "cannot read scene file: " + why});
        return result;
    };
    // Directories, devices, FIFOs and oversized files are refused before anything is opened.
    std::string text, error;
    if (!readInputFile(path, kMaxSceneFileBytes, text, error)) return fail(error);
    std::error_code ec;
    fs::path absolute = fs::absolute(fs::path(path), ec);
    std::string baseDir = (ec ? fs::path(path) : absolute).parent_path().string();
    return parseScene(text, baseDir, path);
}

}  // namespace rs
