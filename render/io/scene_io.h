// Reading and writing scene files, format versions 1 and 2 (scenes/FORMAT.md).
#pragma once

#include <string>
#include <vector>

#include "scene/document.h"

namespace rs {

/// One problem found in a scene file, with where it is.
struct SceneError {
    std::string file;     ///< Scene file path (may be empty for in-memory text).
    std::string pointer;  ///< JSON pointer, e.g. "/objects/3/radius"; "" for the document.
    int line = 0;         ///< 1-based line, 0 when unknown.
    int column = 0;       ///< 1-based column, 0 when unknown.
    std::string message;  ///< What is wrong, e.g. "radius must be > 0, got 0".
    /// "file:line:column: /pointer: message", leaving out what is unknown.
    std::string toString() const;
};

/// Outcome of a load: either a document, or every error found (never both).
struct SceneLoadResult {
    SceneDocument document;
    std::vector<SceneError> errors;
    /// Problems that do not stop the load (an image file that cannot be read: it shows as the
    /// missing-image pattern and is saved back as written). Only with a document.
    std::vector<SceneError> warnings;
    bool ok() const { return errors.empty(); }
    /// All errors, one per line.
    std::string errorText() const;
    /// All warnings, one per line.
    std::string warningText() const;
};

/// The newest format version this program reads and writes.
inline constexpr int kSceneFormatVersion = 2;
/// Where `doc` uses what version 1 cannot say, as JSON pointers (a patterned colour, a sun or
/// spot light's type, the environment, opaque_shadows): the writer writes version 1 when
/// there is none, and the reader refuses each in a file that says version 1.
std::vector<std::string> version2Uses(const SceneDocument& doc);

/// Parses scene text. `baseDir` resolves relative mesh and image paths; `fileName` is used in
/// messages. Meshes are loaded (through loadMesh) so a missing or broken mesh fails the load.
SceneLoadResult parseScene(const std::string& text, const std::string& baseDir,
                           const std::string& fileName = "");
/// Reads and parses a scene file.
SceneLoadResult loadScene(const std::string& path);

/// Serialises a document. `baseDir` is the folder the file will live in: mesh paths are
/// written relative to it when the mesh lies below it, absolute otherwise.
std::string serializeScene(const SceneDocument& doc, const std::string& baseDir);
/// Writes atomically (temporary file, then rename): a failed save never truncates `path`.
bool saveScene(const std::string& path, const SceneDocument& doc, std::string& error);

}  // namespace rs
